#include "common/util/timing_summary.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fedsim::util {

TimingSummary summarize_ms(std::vector<double> ms) {
  TimingSummary s;
  if (ms.empty()) return s;
  std::sort(ms.begin(), ms.end());
  s.median_ms = ms[ms.size() / 2];
  const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(ms.size())));
  s.p99_ms = ms[std::min(ms.size(), std::max<std::size_t>(rank, 1)) - 1];
  s.max_ms = ms.back();
  s.mean_ms = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
  return s;
}

}  // namespace fedsim::util
