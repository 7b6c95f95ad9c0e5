// CLOCK_MONOTONIC in nanoseconds: the one clock used for frame timing across processes on a host.
#pragma once

#include <cstdint>
#include <ctime>

namespace fedsim::util {

inline std::uint64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::uint64_t>(ts.tv_sec) * 1'000'000'000ull +
         static_cast<std::uint64_t>(ts.tv_nsec);
}

/// CLOCK_REALTIME (UTC) in nanoseconds, signed: for stamps compared with other processes'
/// (e.g. a command issued before a federate started), never for frame timing.
inline std::int64_t utc_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000ll + static_cast<std::int64_t>(ts.tv_nsec);
}

/// Sleeps until an absolute CLOCK_MONOTONIC time (no drift accumulates across frames).
inline void sleep_until_ns(std::uint64_t deadline_ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000ull);
  ts.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000ull);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {
  }
}

}  // namespace fedsim::util
