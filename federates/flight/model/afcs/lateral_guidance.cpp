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

double vor_cross_track_left_m(double deviation, double full_scale_rad, double distance_m) {
  return std::sin(deviation * full_scale_rad) * distance_m;
}

CourseLaw localizer_course_law(const LateralGains& gains) {
  return {gains.localizer_time_constant_s, gains.max_intercept_rad, gains.capture_bank_rad, gains.roll_in_time_s,
          gains.max_on_scale_deviation};
}

CourseLaw vor_course_law(const LateralGains& lateral, const VorGains& vor, double mcp_bank_limit_rad) {
  // The capture turn is flown within the MCP's bank limit: its lead must assume a bank the
  // limit leaves room for (the track law's bank grows as the intercept closes).
  return {vor.track_time_constant_s, lateral.max_intercept_rad,
          std::min(lateral.capture_bank_rad, 0.8 * mcp_bank_limit_rad),
          lateral.roll_in_time_s + vor.deviation_filter_s, lateral.max_on_scale_deviation};
}

double course_track_command_rad(double cross_track_left_m, double course_true_rad, double ground_speed_mps,
                                const CourseLaw& law) {
  const double speed = std::max(ground_speed_mps, 10.0);
  const double s = std::clamp(cross_track_left_m / (speed * law.track_time_constant_s),
                              -std::sin(law.max_intercept_rad), std::sin(law.max_intercept_rad));
  return course_true_rad + std::asin(s);
}

double course_capture_lead_m(double intercept_rad, double ground_speed_mps, const CourseLaw& law) {
  const double v = std::max(ground_speed_mps, 10.0);
  const double radius = v * v / (units::kStandardGravityMps2 * std::tan(law.capture_bank_rad));
  const double a = std::min(std::abs(intercept_rad), units::kHalfPi);
  return radius * (1.0 - std::cos(a)) + v * std::sin(a) * law.lead_time_s;
}

bool course_capture_point(double deviation, double cross_track_left_m, double course_true_rad,
                          double track_true_rad, double ground_speed_mps, const CourseLaw& law) {
  if (std::abs(deviation) > law.max_on_scale_deviation) return false;
  // + = the track points right of the course; moving right reduces the distance left of it.
  const double intercept = wrap_angle_rad(track_true_rad - course_true_rad);
  if (std::abs(intercept) >= units::kHalfPi) return false;  // flying against the course
  const bool closing = cross_track_left_m * intercept > 0.0;
  const double lead = course_capture_lead_m(intercept, ground_speed_mps, law);
  if (!closing) {
    // Parallel to or diverging from the course: capture once close enough that the track law
    // itself would turn towards it (its command lies beyond the present intercept).
    return std::abs(cross_track_left_m) <=
               lead + 0.5 * ground_speed_mps * law.track_time_constant_s * std::sin(law.max_intercept_rad) &&
           std::abs(intercept) < 5.0 * units::kDegToRad;
  }
  return std::abs(cross_track_left_m) <= lead;
}

double localizer_track_command_rad(double cross_track_left_m, double course_true_rad,
                                   double ground_speed_mps, const LateralGains& gains) {
  return course_track_command_rad(cross_track_left_m, course_true_rad, ground_speed_mps, localizer_course_law(gains));
}

double localizer_capture_lead_m(double intercept_rad, double ground_speed_mps,
                                const LateralGains& gains) {
  return course_capture_lead_m(intercept_rad, ground_speed_mps, localizer_course_law(gains));
}

bool localizer_capture_point(double deviation, double cross_track_left_m, double course_true_rad,
                             double track_true_rad, double ground_speed_mps,
                             const LateralGains& gains) {
  return course_capture_point(deviation, cross_track_left_m, course_true_rad, track_true_rad, ground_speed_mps,
                              localizer_course_law(gains));
}

}  // namespace fedsim::flight::afcs
