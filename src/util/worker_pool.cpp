#include "util/worker_pool.hpp"

#include <algorithm>
#include <string>
#include <system_error>

namespace clips::util {

WorkerPool::WorkerPool(int threads) {
  int t = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  try {
    for (int i = 1; i < t; ++i) workers_.emplace_back([this] { worker_loop(); });
  } catch (const std::system_error& e) {
    // The threads already started must be stopped and joined here (the
    // destructor does not run for an object whose constructor threw).
    const size_t started = workers_.size() + 1;
    {
      std::lock_guard lock(m_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
    throw std::system_error(e.code(), "cannot start thread " + std::to_string(started) + " of " + std::to_string(t) +
                                          " (ask for fewer threads)");
  }
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(m_);
    stop_ = true;
  }
  wake_.notify_all();
  for (auto& w : workers_) w.join();
}

// Claims indices of the current job until none is left. Called with m_ unlocked.
void WorkerPool::work_on_current_job() {
  std::unique_lock lock(m_);
  while (job_ != nullptr && next_ < n_) {
    const size_t i = next_++;
    const auto* f = job_;
    lock.unlock();
    try {
      (*f)(i);
    } catch (...) {
      std::lock_guard g(m_);
      if (!error_) error_ = std::current_exception();
    }
    lock.lock();
    if (++finished_ == n_) done_.notify_all();
  }
}

void WorkerPool::worker_loop() {
  unsigned seen = 0;
  for (;;) {
    {
      std::unique_lock lock(m_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    work_on_current_job();
  }
}

void WorkerPool::run(size_t n, const std::function<void(size_t)>& f) {
  if (n == 0) return;
  std::lock_guard serial(run_mutex_);
  if (workers_.empty() || n == 1) {
    for (size_t i = 0; i < n; ++i) f(i);
    return;
  }
  {
    std::lock_guard lock(m_);
    job_ = &f;
    n_ = n;
    next_ = finished_ = 0;
    error_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  work_on_current_job();
  std::exception_ptr err;
  {
    std::unique_lock lock(m_);
    done_.wait(lock, [&] { return finished_ == n_; });
    job_ = nullptr;
    err = error_;
  }
  if (err) std::rethrow_exception(err);
}

}  // namespace clips::util
