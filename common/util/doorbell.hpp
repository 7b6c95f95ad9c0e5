// A doorbell between threads: ring() from any thread (a middleware listener), wait() on one
// (the frame thread), on a Linux futex with no mutex around it.
//
// Why not a condition variable: after a wait on a std::condition_variable, glibc marks the
// re-acquired mutex as contended, so every frame paid one more futex system call on the frame
// thread, and the waker takes the mutex too. Here a wake-up is one FUTEX_WAKE by the ringer
// (only when someone waits) and the waiter's return from FUTEX_WAIT.
//
// Use: read value() before looking at the shared state; if there is nothing to do, wait(value,
// timeout). A ring between the look and the wait changes the value, so the wait returns at once
// (no lost wake-up).
#pragma once

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <ctime>

namespace fedsim::util {

class Doorbell {
 public:
  std::uint32_t value() const { return rings_.load(std::memory_order_acquire); }

  void ring() {
    rings_.fetch_add(1);  // seq_cst: ordered against the waiter's count (Dekker)
    if (waiters_.load() > 0) {
      syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&rings_), FUTEX_WAKE_PRIVATE, 1,
              nullptr, nullptr, 0);
    }
  }

  /// Returns when the bell rang since `seen` was read, or after `timeout` (or spuriously).
  void wait(std::uint32_t seen, std::chrono::nanoseconds timeout) {
    waiters_.fetch_add(1);
    if (rings_.load() == seen) {
      timespec ts{static_cast<time_t>(timeout.count() / 1000000000),
                  static_cast<long>(timeout.count() % 1000000000)};
      syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&rings_), FUTEX_WAIT_PRIVATE, seen,
              &ts, nullptr, 0);
    }
    waiters_.fetch_sub(1);
  }

 private:
  static_assert(sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t) &&
                std::atomic<std::uint32_t>::is_always_lock_free);
  std::atomic<std::uint32_t> rings_{0};
  std::atomic<int> waiters_{0};
};

}  // namespace fedsim::util
