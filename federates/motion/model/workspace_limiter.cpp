#include "motion/model/workspace_limiter.hpp"

#include <stdexcept>

#include "common/control/parameter_checks.hpp"

namespace fedsim::motion {
namespace {
constexpr int kScanSteps = 16;
constexpr int kBisections = 40;
}  // namespace

WorkspaceLimiter::WorkspaceLimiter(const StewartKinematics& kinematics, double margin_m)
    : kinematics_(&kinematics) {
  control::require_non_negative("WorkspaceLimiter", "margin_m", margin_m);
  const StewartGeometry& g = kinematics.geometry();
  if (!(2.0 * margin_m < g.stroke_m())) {
    throw std::invalid_argument("WorkspaceLimiter: margin_m must be below half the stroke");
  }
  lower_m_ = g.min_length_m + margin_m;
  upper_m_ = g.max_length_m - margin_m;
  if (!within(kinematics.neutral_lengths_m(), lower_m_, upper_m_)) {
    throw std::invalid_argument("WorkspaceLimiter: the neutral pose lies outside the soft limits");
  }
}

LimitedPose WorkspaceLimiter::limit(const PlatformPose& demand) const {
  LimitedPose result;
  result.pose = demand;
  result.lengths_m = kinematics_->inverse(demand);
  if (within(result.lengths_m, lower_m_, upper_m_)) return result;

  double inside = 0.0;   // a scale known to be inside
  double outside = 1.0;  // a scale known to be outside
  for (int k = 1; k < kScanSteps; ++k) {
    const double candidate = static_cast<double>(k) / kScanSteps;
    if (!within(kinematics_->inverse(scaled(demand, candidate)), lower_m_, upper_m_)) {
      outside = candidate;
      break;
    }
    inside = candidate;
  }
  for (int i = 0; i < kBisections; ++i) {
    const double middle = 0.5 * (inside + outside);
    if (within(kinematics_->inverse(scaled(demand, middle)), lower_m_, upper_m_)) {
      inside = middle;
    } else {
      outside = middle;
    }
  }
  result.scale = inside;
  result.limited = true;
  result.pose = scaled(demand, inside);
  result.lengths_m = kinematics_->inverse(result.pose);
  return result;
}

}  // namespace fedsim::motion
