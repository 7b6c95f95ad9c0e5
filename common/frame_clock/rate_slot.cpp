#include "common/frame_clock/rate_slot.hpp"

#include <cmath>

namespace fedsim::timing {

std::int64_t rate_slot(std::uint64_t frame, double period_s, double hz) {
  constexpr double kTolerance = 1e-6;  // of a slot: far above the product's rounding error
  return static_cast<std::int64_t>(std::floor(static_cast<double>(frame) * period_s * hz + kTolerance));
}

}  // namespace fedsim::timing
