// WorkerPool: every index runs once, results land where they belong, errors
// propagate, and a pool is reusable.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <string>
#include <system_error>
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

// issue 46: when a thread cannot start (here: the address space is too
// small for its stack), the constructor throws std::system_error naming the
// thread, after joining the ones it started; it neither deadlocks nor ends
// the process. Run in a child process, whose address space is limited.
TEST(WorkerPool, FailingThreadCreationIsAnError) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "sanitizers reserve address space of their own";
#else
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Room for what is mapped now and a few thread stacks, not for 200.
    long pages = 0;
    if (FILE* f = fopen("/proc/self/statm", "r")) {
      if (fscanf(f, "%ld", &pages) != 1) pages = 0;
      fclose(f);
    }
    const rlim_t now = static_cast<rlim_t>(pages) * static_cast<rlim_t>(sysconf(_SC_PAGESIZE));
    const rlimit lim{now + (64u << 20), now + (64u << 20)};
    if (pages == 0 || setrlimit(RLIMIT_AS, &lim) != 0) _exit(3);
    try {
      WorkerPool pool(200);
      _exit(1);  // every thread started: the limit did not bite
    } catch (const std::system_error& e) {
      const std::string what = e.what();
      _exit(what.find("cannot start thread") != std::string::npos ? 0 : 2);
    } catch (...) {
      _exit(4);
    }
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no thread failed; 2: another message; 3: no limit; 4: another exception";
#endif
}

}  // namespace
}  // namespace clips::util
