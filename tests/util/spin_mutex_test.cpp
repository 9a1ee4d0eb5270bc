// SpinMutex: mutual exclusion under contention (more threads than cores, so
// the yielding path runs too) and try_lock's answers.
#include "util/spin_mutex.hpp"

#include <gtest/gtest.h>

#include <mutex>
#include <thread>
#include <vector>

namespace clips::util {
namespace {

TEST(SpinMutex, NoIncrementIsLostUnderContention) {
  SpinMutex m;
  // A plain (non-atomic) counter and a two-step update: without mutual
  // exclusion some increments would be lost.
  long counter = 0;
  long shadow = 0;
  constexpr int kThreads = 8, kRounds = 20000;
  std::vector<std::thread> ts;
  for (int t = 0; t < kThreads; ++t)
    ts.emplace_back([&] {
      for (int i = 0; i < kRounds; ++i) {
        std::lock_guard lock(m);
        const long c = counter;
        shadow = c;
        counter = shadow + 1;
      }
    });
  for (auto& t : ts) t.join();
  EXPECT_EQ(counter, long{kThreads} * kRounds);
}

TEST(SpinMutex, TryLockFailsWhileHeldAndSucceedsAfter) {
  SpinMutex m;
  ASSERT_TRUE(m.try_lock());
  bool other = true;
  std::thread([&] { other = m.try_lock(); }).join();
  EXPECT_FALSE(other);
  m.unlock();
  std::thread([&] {
    other = m.try_lock();
    if (other) m.unlock();
  }).join();
  EXPECT_TRUE(other);
}

}  // namespace
}  // namespace clips::util
