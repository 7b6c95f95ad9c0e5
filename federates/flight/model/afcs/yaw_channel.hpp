// The autopilot's rudder channel.
//   coordination (every airborne mode but ALIGN): rudder = PI(K_beta beta), + beta (wind from
//     the right) -> + rudder (nose right), so the slip ball stays centred in turns (the 737
//     pack has no aileron-yaw or Cn_p term, but Cn_r opposes every turn);
//   ALIGN (decrab): the heading command moves from the crab heading to the runway course at
//     align_heading_rate and rudder = PI(K_psi (psi_c - psi)) - K_r r: the aircraft sideslips
//     into the wind while the roll loop holds the localizer track with a bank into the wind.
// The yaw damper is the aircraft's own (model/systems, on the pack's yaw rate); it adds to
// this command downstream.
#pragma once

#include "common/control/pid.hpp"
#include "common/control/rate_limiter.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

class YawChannel {
 public:
  YawChannel(const YawChannelGains& gains, double dt_s);
  /// Coordination takes over from the present rudder command.
  void engage_coordination(double rudder, double sideslip_rad);
  double coordinate(double sideslip_rad);
  /// ALIGN starts from the present rudder and heading.
  void engage_align(double rudder, double heading_rad);
  /// The rudder that turns the heading to `course_rad` (true) while damping the yaw rate.
  double align(double course_rad, double heading_rad, double yaw_rate_radps);
  /// The rate-limited heading command of ALIGN [rad].
  double align_heading_command_rad() const { return heading_command_rad_; }

 private:
  YawChannelGains gains_;
  control::Pid coordination_;
  control::Pid align_;
  double heading_command_rad_ = 0.0;
  double dt_s_;
};

}  // namespace fedsim::flight::afcs
