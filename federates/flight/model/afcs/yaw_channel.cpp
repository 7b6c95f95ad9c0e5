#include "flight/model/afcs/yaw_channel.hpp"

#include "flight/model/afcs/lateral_guidance.hpp"

#include <algorithm>

namespace fedsim::flight::afcs {

namespace {
control::PidParameters pi(double kp, double ki) { return control::pi_parameters(kp, ki, -1.0, 1.0); }
}  // namespace

YawChannel::YawChannel(const YawChannelGains& gains, double dt_s)
    : gains_(gains),
      coordination_(pi(gains.sideslip_gain_per_rad, gains.sideslip_integral_gain_per_rad_s), dt_s),
      align_(pi(gains.align_heading_gain_per_rad, gains.align_heading_integral_per_rad_s), dt_s),
      dt_s_(dt_s) {}

void YawChannel::engage_coordination(double rudder, double sideslip_rad) {
  coordination_.engage(sideslip_rad, std::clamp(rudder, -1.0, 1.0));
}

double YawChannel::coordinate(double sideslip_rad) { return coordination_.step(sideslip_rad); }

void YawChannel::engage_align(double rudder, double heading_rad) {
  heading_command_rad_ = heading_rad;
  align_.engage(0.0, std::clamp(rudder, -1.0, 1.0));
}

double YawChannel::align(double course_rad, double heading_rad, double yaw_rate_radps) {
  // The heading command walks towards the course at the decrab rate (no yaw kick).
  const double step = gains_.align_heading_rate_radps * dt_s_;
  const double to_course = wrap_angle_rad(course_rad - heading_command_rad_);
  heading_command_rad_ = wrap_angle_rad(heading_command_rad_ + std::clamp(to_course, -step, step));
  const double error = wrap_angle_rad(heading_command_rad_ - heading_rad);
  return std::clamp(align_.step(error) - gains_.align_yaw_rate_gain_per_radps * yaw_rate_radps, -1.0, 1.0);
}

}  // namespace fedsim::flight::afcs
