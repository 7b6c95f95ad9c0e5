#include "common/runtime/shutdown.hpp"

#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace fedsim::runtime {

namespace {
std::mutex g_mutex;
std::condition_variable g_changed;
std::atomic<bool> g_requested{false};
std::atomic<int> g_signal{0};
std::once_flag g_installed;

sigset_t shutdown_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}
}  // namespace

void install_shutdown_handler() {
  std::call_once(g_installed, [] {
    sigset_t set = shutdown_signals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread([set] {
      for (;;) {
        int sig = 0;
        if (sigwait(&set, &sig) == 0) {
          g_signal.store(sig);
          request_shutdown();
        }
      }
    }).detach();
  });
}

bool shutdown_requested() { return g_requested.load(); }

void request_shutdown() {
  {
    std::lock_guard lock(g_mutex);
    g_requested.store(true);
  }
  g_changed.notify_all();
}

bool wait_for_shutdown(std::chrono::milliseconds timeout) {
  std::unique_lock lock(g_mutex);
  return g_changed.wait_for(lock, timeout, [] { return g_requested.load(); });
}

int shutdown_signal() { return g_signal.load(); }

}  // namespace fedsim::runtime
