#include "flight/model/afcs/rollout_control.hpp"

#include <algorithm>

namespace fedsim::flight::afcs {

namespace {
control::PidParameters brake_pid(const RolloutGains& g) {
  return control::pi_parameters(g.brake_proportional_per_mps2, g.brake_integral_per_mps2_s, 0.0,
                                1.0);
}
control::PidParameters rudder_pid(const RolloutGains& g) {
  return control::pi_parameters(g.rudder_scale, g.rudder_integral_per_s, -1.0, 1.0);
}
}  // namespace

RolloutControl::RolloutControl(const RolloutGains& gains, double dt_s)
    : gains_(gains),
      rudder_(rudder_pid(gains), dt_s),
      brake_(brake_pid(gains), dt_s),
      deceleration_(gains.deceleration_filter_s, dt_s),
      brake_rate_(gains.brake_rate_per_s, dt_s),
      spoilers_(gains.spoiler_rate_per_s, dt_s),
      dt_s_(dt_s) {}

void RolloutControl::reset(double rudder) {
  rudder_.engage(0.0, std::clamp(rudder, -1.0, 1.0));
  brake_.reset();
  deceleration_.reset(0.0);
  brake_rate_.reset(0.0);
  spoilers_.reset(0.0);
  time_s_ = 0.0;
  braking_ = false;
}

double RolloutControl::deceleration_target_mps2(int setting) const {
  switch (setting) {
    case 1: return gains_.deceleration_1_mps2;
    case 2: return gains_.deceleration_2_mps2;
    case 3: return gains_.deceleration_3_mps2;
    case 4: return gains_.deceleration_max_mps2;
    default: return 0.0;
  }
}

RolloutCommand RolloutControl::step(double cross_track_left_m, double heading_error_rad,
                                    double yaw_rate_radps, double ground_speed_mps,
                                    double deceleration_mps2, int autobrake_setting) {
  time_s_ += dt_s_;
  RolloutCommand c;
  const double law = gains_.cross_track_gain_per_m * cross_track_left_m +
                     gains_.heading_gain_per_rad * heading_error_rad -
                     gains_.yaw_rate_gain_per_radps * yaw_rate_radps;
  c.steering = std::clamp(law, -gains_.steering_limit, gains_.steering_limit);
  c.rudder = rudder_.step(law);
  c.spoilers = spoilers_.step(1.0);
  const double deceleration = deceleration_.step(deceleration_mps2);
  const double target = deceleration_target_mps2(autobrake_setting);
  double brake = 0.0;
  if (target > 0.0 && time_s_ >= gains_.autobrake_delay_s) {
    if (ground_speed_mps < gains_.taxi_speed_mps) {
      brake = 1.0;  // stopped: hold
    } else {
      if (!braking_) brake_.engage(target - deceleration, 0.0);
      braking_ = true;
      brake = brake_.step(target - deceleration);
    }
  }
  c.brake = brake_rate_.step(brake);
  return c;
}

}  // namespace fedsim::flight::afcs
