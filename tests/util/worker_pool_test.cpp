// WorkerPool: every index runs once, results land where they belong, errors
// propagate, and a pool is reusable.
#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "util/worker_pool.hpp"

namespace clips::util {
namespace {

TEST(WorkerPool, RunsEveryIndexExactlyOnce) {
  WorkerPool pool(2);
  EXPECT_EQ(pool.threads(), 2);
  for (size_t n : {0u, 1u, 2u, 7u, 100u}) {
    std::vector<std::atomic<int>> hits(n);
    pool.run(n, [&](size_t i) { hits[i].fetch_add(1); });
    for (size_t i = 0; i < n; ++i) EXPECT_EQ(hits[i].load(), 1) << "n=" << n << " i=" << i;
  }
}

TEST(WorkerPool, UsesMoreThanOneThread) {
  WorkerPool pool(2);
  std::mutex m;
  std::set<std::thread::id> ids;
  // Items slow enough that the second thread claims some of them.
  pool.run(8, [&](size_t) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::lock_guard lock(m);
    ids.insert(std::this_thread::get_id());
  });
  EXPECT_EQ(ids.size(), 2u);
}

TEST(WorkerPool, RethrowsTheFirstErrorAfterAllItemsFinish) {
  WorkerPool pool(2);
  std::atomic<int> done{0};
  EXPECT_THROW(pool.run(6,
                        [&](size_t i) {
                          if (i == 3) throw std::runtime_error("item 3");
                          done.fetch_add(1);
                        }),
               std::runtime_error);
  EXPECT_EQ(done.load(), 5);
  // Still usable afterwards.
  std::atomic<int> again{0};
  pool.run(4, [&](size_t) { again.fetch_add(1); });
  EXPECT_EQ(again.load(), 4);
}

TEST(WorkerPool, SingleThreadRunsInOrderOnTheCaller) {
  WorkerPool pool(1);
  std::vector<size_t> order;
  const auto me = std::this_thread::get_id();
  pool.run(5, [&](size_t i) {
    EXPECT_EQ(std::this_thread::get_id(), me);
    order.push_back(i);
  });
  EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace clips::util
