#pragma once
// WorkerPool: a few persistent threads for small, latency-sensitive parallel
// loops (one belief update refines 8 independent policies; spawning threads
// per step would cost more than the work on a fast step).
//
// run(n, f) calls f(0) .. f(n-1), each exactly once, on the pool's threads and
// the calling thread, and returns when all are done. Indices are claimed
// dynamically, so uneven items balance; results must not depend on which
// thread runs an index. The first exception thrown by f is rethrown by run()
// after every claimed index has finished. Concurrent run() calls on one pool
// are serialised.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace clips::util {

class WorkerPool {
 public:
  // `threads` counts the caller: threads = 2 starts one extra thread. 0 means
  // std::thread::hardware_concurrency().
  explicit WorkerPool(int threads = 0);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }
  void run(size_t n, const std::function<void(size_t)>& f);

 private:
  void work_on_current_job();
  void worker_loop();

  std::vector<std::thread> workers_;
  std::mutex run_mutex_;  // one job at a time
  std::mutex m_;
  std::condition_variable wake_, done_;
  const std::function<void(size_t)>* job_ = nullptr;
  size_t n_ = 0, next_ = 0, finished_ = 0;
  unsigned generation_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

}  // namespace clips::util
