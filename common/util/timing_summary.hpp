// Render-time figures of a run of frames, as the benchmarks (fedsim-bench-visual,
// fedsim-bench-displays) report them: median, p99 (nearest rank: the smallest value with at least
// 99 % of the frames at or below it), max and mean, in milliseconds. One definition for both.
#pragma once

#include <vector>

namespace fedsim::util {

struct TimingSummary {
  double median_ms = 0.0, p99_ms = 0.0, max_ms = 0.0, mean_ms = 0.0;
};

/// The summary of `ms` (one value per frame); all zero for none.
TimingSummary summarize_ms(std::vector<double> ms);

}  // namespace fedsim::util
