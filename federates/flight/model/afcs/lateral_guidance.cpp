#include "flight/model/afcs/lateral_guidance.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight::afcs {

double wrap_angle_rad(double angle_rad) {
  double a = std::remainder(angle_rad, units::kTwoPi);
  if (a <= -units::kPi) a += units::kTwoPi;
  return a;
}

double bank_for_direction_error_rad(double error_rad, double speed_mps, double time_constant_s,
                                    double bank_limit_rad) {
  const double bank = std::atan(std::max(speed_mps, 0.0) * wrap_angle_rad(error_rad) /
                                (units::kStandardGravityMps2 * time_constant_s));
  return std::clamp(bank, -bank_limit_rad, bank_limit_rad);
}

double localizer_cross_track_left_m(double deviation, double half_width_rad,
                                    double distance_from_antenna_m) {
  return std::tan(deviation * half_width_rad) * distance_from_antenna_m;
}

double localizer_track_command_rad(double cross_track_left_m, double course_true_rad,
                                   double ground_speed_mps, const LateralGains& gains) {
  const double speed = std::max(ground_speed_mps, 10.0);
  const double s = std::clamp(cross_track_left_m / (speed * gains.localizer_time_constant_s),
                              -std::sin(gains.max_intercept_rad), std::sin(gains.max_intercept_rad));
  return course_true_rad + std::asin(s);
}

double localizer_capture_lead_m(double intercept_rad, double ground_speed_mps,
                                const LateralGains& gains) {
  const double v = std::max(ground_speed_mps, 10.0);
  const double radius = v * v / (units::kStandardGravityMps2 * std::tan(gains.capture_bank_rad));
  const double a = std::min(std::abs(intercept_rad), units::kHalfPi);
  return radius * (1.0 - std::cos(a)) + v * std::sin(a) * gains.roll_in_time_s;
}

bool localizer_capture_point(double deviation, double cross_track_left_m, double course_true_rad,
                             double track_true_rad, double ground_speed_mps,
                             const LateralGains& gains) {
  if (std::abs(deviation) > gains.max_on_scale_deviation) return false;
  // + = the track points right of the course; moving right reduces the distance left of it.
  const double intercept = wrap_angle_rad(track_true_rad - course_true_rad);
  if (std::abs(intercept) >= units::kHalfPi) return false;  // flying away from the runway
  const bool closing = cross_track_left_m * intercept > 0.0;
  const double lead = localizer_capture_lead_m(intercept, ground_speed_mps, gains);
  if (!closing) {
    // Parallel to or diverging from the course: capture once close enough that the track law
    // itself would turn towards it (its command lies beyond the present intercept).
    return std::abs(cross_track_left_m) <= lead + 0.5 * ground_speed_mps * gains.localizer_time_constant_s *
                                                       std::sin(gains.max_intercept_rad) &&
           std::abs(intercept) < 5.0 * units::kDegToRad;
  }
  return std::abs(cross_track_left_m) <= lead;
}

}  // namespace fedsim::flight::afcs
