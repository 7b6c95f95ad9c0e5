// Running statistics of durations (count, mean, percentiles, max) without per-sample allocation:
// a log-spaced histogram from 100 ns to ~100 s with 1% resolution.
#pragma once

#include <array>
#include <cstdint>

namespace fedsim::util {

class LatencyStats {
 public:
  void add_ns(std::uint64_t value_ns);
  void reset();
  std::uint64_t count() const { return count_; }
  double mean_us() const;
  double max_us() const { return static_cast<double>(max_ns_) / 1000.0; }
  double min_us() const;
  /// Percentile in [0, 100], accurate to the 1% bin width.
  double percentile_us(double pct) const;
  void merge(const LatencyStats& other);

 private:
  static constexpr int kBins = 1400;  // 100 ns * 1.01^1400 ~ 110 s
  static int bin_of(std::uint64_t value_ns);
  static double bin_value_ns(int bin);

  std::array<std::uint32_t, kBins> bins_{};
  std::uint64_t count_ = 0;
  long double sum_ns_ = 0;
  std::uint64_t max_ns_ = 0;
  std::uint64_t min_ns_ = UINT64_MAX;
};

}  // namespace fedsim::util
