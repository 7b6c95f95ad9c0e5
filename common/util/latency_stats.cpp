#include "common/util/latency_stats.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::util {

namespace {
constexpr double kFloorNs = 100.0;
const double kLogStep = std::log(1.01);
}  // namespace

int LatencyStats::bin_of(std::uint64_t value_ns) {
  if (value_ns <= kFloorNs) return 0;
  const int bin = static_cast<int>(std::log(static_cast<double>(value_ns) / kFloorNs) / kLogStep);
  return std::clamp(bin, 0, kBins - 1);
}

double LatencyStats::bin_value_ns(int bin) {
  // Geometric centre of the bin.
  return kFloorNs * std::exp((bin + 0.5) * kLogStep);
}

void LatencyStats::add_ns(std::uint64_t value_ns) {
  ++bins_[static_cast<std::size_t>(bin_of(value_ns))];
  ++count_;
  sum_ns_ += value_ns;
  max_ns_ = std::max(max_ns_, value_ns);
  min_ns_ = std::min(min_ns_, value_ns);
}

void LatencyStats::reset() { *this = LatencyStats{}; }

double LatencyStats::mean_us() const {
  return count_ ? static_cast<double>(sum_ns_ / count_) / 1000.0 : 0.0;
}

double LatencyStats::min_us() const {
  return count_ ? static_cast<double>(min_ns_) / 1000.0 : 0.0;
}

double LatencyStats::percentile_us(double pct) const {
  if (count_ == 0) return 0.0;
  const auto rank = static_cast<std::uint64_t>(std::ceil(pct / 100.0 * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (int b = 0; b < kBins; ++b) {
    seen += bins_[static_cast<std::size_t>(b)];
    if (seen >= std::max<std::uint64_t>(rank, 1)) {
      const double value = std::min(bin_value_ns(b), static_cast<double>(max_ns_));
      return std::max(value, static_cast<double>(min_ns_)) / 1000.0;
    }
  }
  return max_us();
}

void LatencyStats::merge(const LatencyStats& other) {
  for (int b = 0; b < kBins; ++b) bins_[static_cast<std::size_t>(b)] += other.bins_[static_cast<std::size_t>(b)];
  count_ += other.count_;
  sum_ns_ += other.sum_ns_;
  max_ns_ = std::max(max_ns_, other.max_ns_);
  min_ns_ = std::min(min_ns_, other.min_ns_);
}

}  // namespace fedsim::util
