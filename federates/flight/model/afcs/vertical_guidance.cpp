#include "flight/model/afcs/vertical_guidance.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight::afcs {

double altitude_rate_command_mps(double altitude_error_m, const AltitudeGains& gains) {
  const double a_tau = gains.capture_acceleration_mps2 * gains.time_constant_s;
  const double rate = std::sqrt(a_tau * a_tau + 2.0 * gains.capture_acceleration_mps2 * std::abs(altitude_error_m)) - a_tau;
  return std::copysign(rate, altitude_error_m);
}

bool altitude_capture_point(double altitude_error_m, double vertical_speed_mps,
                            const AltitudeGains& gains) {
  const bool towards = altitude_error_m * vertical_speed_mps > 0.0;
  if (!towards) return false;
  return std::abs(altitude_rate_command_mps(altitude_error_m, gains)) <= std::abs(vertical_speed_mps);
}

double glide_path_height_error_m(double deviation, double glide_path_angle_rad,
                                 double distance_from_antenna_m) {
  constexpr double kFullScaleOfPathAngle = 0.24;  // ICAO Annex 10 Vol I 3.1.5.6: 0.24 theta
  return deviation * kFullScaleOfPathAngle * glide_path_angle_rad * distance_from_antenna_m;
}

double glide_slope_path_command_rad(double height_error_m, double glide_path_angle_rad,
                                    double ground_speed_mps, const GlideSlopeGains& gains) {
  const double speed = std::max(ground_speed_mps, 10.0);
  const double correction = std::atan(height_error_m / (speed * gains.path_time_constant_s));
  return std::clamp(-glide_path_angle_rad + correction,
                    -gains.max_descent_factor * glide_path_angle_rad, 0.0);
}

bool glide_slope_capture_point(double deviation, double height_error_m, double glide_path_angle_rad,
                               double ground_speed_mps, double path_rad, const GlideSlopeGains& gains) {
  if (std::abs(deviation) > gains.max_on_scale_deviation) return false;
  // The law before its limits: far below the path the limited law (level) would equal a level
  // path at once.
  const double speed = std::max(ground_speed_mps, 10.0);
  const double law = -glide_path_angle_rad + std::atan(height_error_m / (speed * gains.path_time_constant_s));
  const double side = height_error_m >= 0.0 ? 1.0 : -1.0;  // below: +1, above: -1
  return side * (law - path_rad) <= gains.capture_margin_rad;
}

FlareLaw FlareLaw::at_entry(double height_m, double vertical_speed_mps, const AutolandGains& gains) {
  FlareLaw law;
  law.touchdown_sink_rate_mps = gains.touchdown_sink_rate_mps;
  const double sink_to_remove = std::max(-vertical_speed_mps - gains.touchdown_sink_rate_mps, 0.1);
  law.time_constant_s = std::clamp(std::max(height_m, 0.0) / sink_to_remove, 2.0, 10.0);
  return law;
}

double FlareLaw::climb_rate_command_mps(double height_m) const {
  return -std::max(height_m, 0.0) / time_constant_s - touchdown_sink_rate_mps;
}

}  // namespace fedsim::flight::afcs
