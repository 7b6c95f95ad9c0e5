// Rollout on the localizer and the autobrake (after main-gear touchdown in an autoland).
//   steering = K_y y_left + K_psi (course - psi) - K_r r, limited to +-steering_limit of the
//     nose wheel's travel (a high-speed rollout steers a few degrees, not the tiller's 35);
//   rudder   = PI(the same law): rudder_scale x law plus its integral (the integral holds the
//     rudder a crosswind needs against the weathervane moment without a standing heading error);
//   autobrake: from autobrake_delay after touchdown (wheel spin-up), brake = PI(target
//     deceleration - measured deceleration), the targets of the 737's settings 1, 2, 3, MAX
//     (4, 5, 7.2, 14 ft/s^2, FCOM "Landing gear: autobrake"); full brakes once stopped (hold).
//     The measured deceleration is low-passed (deceleration_filter_s: it answers the brake
//     within the frame, and unfiltered at any useful gain the loop chatters frame to frame),
//     the brake pressure builds and releases at brake_rate_per_s;
//   ground spoilers deploy at touchdown (auto speedbrake) at spoiler_rate.
#pragma once

#include "common/control/first_order_lag.hpp"
#include "common/control/pid.hpp"
#include "common/control/rate_limiter.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

struct RolloutCommand {
  double steering = 0.0;  // -1..1, + nose right
  double rudder = 0.0;    // -1..1
  double brake = 0.0;     // 0..1 both sides
  double spoilers = 0.0;  // 0..1
};

class RolloutControl {
 public:
  RolloutControl(const RolloutGains& gains, double dt_s);
  /// At touchdown: brakes off, spoilers stowed, the clock since touchdown at 0, the rudder
  /// continuing from `rudder` (the align mode's decrab rudder).
  void reset(double rudder);
  RolloutCommand step(double cross_track_left_m, double heading_error_rad, double yaw_rate_radps,
                      double ground_speed_mps, double deceleration_mps2, int autobrake_setting);
  double time_since_touchdown_s() const { return time_s_; }
  /// The deceleration target of an autobrake setting (0: off) [m/s^2].
  double deceleration_target_mps2(int setting) const;

 private:
  RolloutGains gains_;
  control::Pid rudder_;
  control::Pid brake_;
  control::FirstOrderLag deceleration_;
  control::RateLimiter brake_rate_;
  control::RateLimiter spoilers_;
  double dt_s_;
  double time_s_ = 0.0;
  bool braking_ = false;
};

}  // namespace fedsim::flight::afcs
