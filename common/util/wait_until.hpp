// Waiting for an event with a deadline, instead of sleeping a fixed time and then looking: a
// fixed sleep is too short on a loaded machine (the test fails) and too long on an idle one (the
// suite is slow). The tests use it to wait for samples, log lines, files and process states.
#pragma once

#include <chrono>
#include <thread>

namespace fedsim::util {

/// Calls `done()` every `poll` until it returns true or `timeout_s` seconds have passed; true
/// if it held (it is asked once more at the deadline, so a slow poll cannot miss it).
template <class Condition>
bool wait_until(Condition&& done, double timeout_s,
                std::chrono::milliseconds poll = std::chrono::milliseconds(10)) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(poll);
  }
  return done();
}

}  // namespace fedsim::util
