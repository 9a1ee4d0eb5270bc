#pragma once
// SpinMutex: a lock for critical sections of a few hundred nanoseconds that
// two or more threads take often (the shared state graph's table). A
// std::mutex puts a waiter to sleep in the kernel, and waking it costs more
// than the section it waited for; this one spins briefly, then yields the
// core so that more threads than cores still make progress. Meets the
// standard Lockable requirements (std::lock_guard, std::unique_lock).
#include <atomic>
#include <thread>

namespace clips::util {

class SpinMutex {
 public:
  void lock() noexcept {
    for (int spins = 0;;) {
      if (!locked_.exchange(true, std::memory_order_acquire)) return;
      while (locked_.load(std::memory_order_relaxed)) {
        if (spins < kSpinsBeforeYield) {
          ++spins;
          pause();
        } else {
          std::this_thread::yield();
        }
      }
    }
  }
  bool try_lock() noexcept {
    return !locked_.load(std::memory_order_relaxed) && !locked_.exchange(true, std::memory_order_acquire);
  }
  void unlock() noexcept { locked_.store(false, std::memory_order_release); }

 private:
  static constexpr int kSpinsBeforeYield = 1 << 10;
  static void pause() noexcept {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  std::atomic<bool> locked_{false};
};

}  // namespace clips::util
