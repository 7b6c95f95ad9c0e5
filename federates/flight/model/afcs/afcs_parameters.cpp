#include "flight/model/afcs/afcs_parameters.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::flight::afcs {

namespace {

[[noreturn]] void fail(const char* name, double value, const char* rule) {
  throw std::invalid_argument("AfcsParameters: " + std::string(name) + " = " +
                              std::to_string(value) + " " + rule);
}
void positive(const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0)) fail(name, value, "must be finite and positive");
}
void non_negative(const char* name, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) fail(name, value, "must be finite and >= 0");
}
void within(const char* name, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value >= lo && value <= hi)) {
    fail(name, value, ("must lie within [" + std::to_string(lo) + ", " + std::to_string(hi) + "]").c_str());
  }
}
constexpr double kDeg = units::kDegToRad;

}  // namespace

void AfcsParameters::validate() const {
  positive("reference_cas_mps", reference_cas_mps);
  within("min_gain_schedule", min_gain_schedule, 0.01, 1.0);
  within("max_gain_schedule", max_gain_schedule, 1.0, 100.0);
  positive("fade_time_s", fade_time_s);
  positive("command_rate_filter_s", command_rate_filter_s);
  positive("cws_pitch_rate_radps", cws_pitch_rate_radps);
  positive("cws_roll_rate_radps", cws_roll_rate_radps);
  within("cws_breakout_force_n", cws_breakout_force_n, 0.0, 200.0);
  within("cws_full_column_force_n", cws_full_column_force_n, cws_breakout_force_n + 1.0, 1000.0);
  within("cws_full_wheel_force_n", cws_full_wheel_force_n, cws_breakout_force_n + 1.0, 1000.0);
  within("engage_bank_limit_rad", engage_bank_limit_rad, 1 * kDeg, 60 * kDeg);
  within("engage_pitch_min_rad", engage_pitch_min_rad, -45 * kDeg, 0.0);
  within("engage_pitch_max_rad", engage_pitch_max_rad, 0.0, 45 * kDeg);
  within("authority_bank_limit_rad", authority_bank_limit_rad, engage_bank_limit_rad, 90 * kDeg);
  within("authority_pitch_min_rad", authority_pitch_min_rad, -60 * kDeg, engage_pitch_min_rad);
  within("authority_pitch_max_rad", authority_pitch_max_rad, engage_pitch_max_rad, 60 * kDeg);
  within("wings_level_bank_rad", wings_level_bank_rad, 0.0, 30 * kDeg);
  within("trim_start_elevator", trim_start_elevator, 0.0, 1.0);
  within("trim_stop_elevator", trim_stop_elevator, 0.0, trim_start_elevator);
  non_negative("trim_delay_s", trim_delay_s);
  positive("trim_filter_s", trim_filter_s);

  positive("pitch.attitude_gain_per_rad", pitch.attitude_gain_per_rad);
  non_negative("pitch.integral_gain_per_rad_s", pitch.integral_gain_per_rad_s);
  non_negative("pitch.rate_gain_per_radps", pitch.rate_gain_per_radps);
  positive("roll.attitude_gain_per_rad", roll.attitude_gain_per_rad);
  non_negative("roll.integral_gain_per_rad_s", roll.integral_gain_per_rad_s);
  non_negative("roll.rate_gain_per_radps", roll.rate_gain_per_radps);
  positive("roll.bank_rate_limit_radps", roll.bank_rate_limit_radps);
  non_negative("yaw.sideslip_gain_per_rad", yaw.sideslip_gain_per_rad);
  non_negative("yaw.sideslip_integral_gain_per_rad_s", yaw.sideslip_integral_gain_per_rad_s);
  positive("yaw.align_heading_gain_per_rad", yaw.align_heading_gain_per_rad);
  non_negative("yaw.align_heading_integral_per_rad_s", yaw.align_heading_integral_per_rad_s);
  non_negative("yaw.align_yaw_rate_gain_per_radps", yaw.align_yaw_rate_gain_per_radps);
  positive("yaw.align_heading_rate_radps", yaw.align_heading_rate_radps);

  positive("path.proportional_gain", path.proportional_gain);
  non_negative("path.integral_gain_per_s", path.integral_gain_per_s);
  within("path.pitch_min_rad", path.pitch_min_rad, -45 * kDeg, 0.0);
  within("path.pitch_max_rad", path.pitch_max_rad, 0.0, 45 * kDeg);
  within("path.turn_compensation_rad", path.turn_compensation_rad, 0.0, 30 * kDeg);
  non_negative("path.path_lag_s", path.path_lag_s);
  positive("altitude.time_constant_s", altitude.time_constant_s);
  positive("altitude.capture_acceleration_mps2", altitude.capture_acceleration_mps2);
  positive("altitude.hold_band_m", altitude.hold_band_m);
  positive("altitude.max_hold_rate_mps", altitude.max_hold_rate_mps);
  positive("speed_on_elevator.time_constant_s", speed_on_elevator.time_constant_s);
  positive("speed_on_elevator.integral_time_s", speed_on_elevator.integral_time_s);
  within("speed_on_elevator.max_climb_path_rad", speed_on_elevator.max_climb_path_rad, 0.0, 30 * kDeg);
  within("speed_on_elevator.min_descent_path_rad", speed_on_elevator.min_descent_path_rad, -30 * kDeg, 0.0);
  within("speed_on_elevator.go_around_min_path_rad", speed_on_elevator.go_around_min_path_rad, 0.0,
         speed_on_elevator.max_climb_path_rad);
  within("speed_on_elevator.go_around_pitch_max_rad", speed_on_elevator.go_around_pitch_max_rad, 0.0, 30 * kDeg);
  positive("speed_on_elevator.go_around_climb_rate_mps", speed_on_elevator.go_around_climb_rate_mps);
  positive("glide_slope.path_time_constant_s", glide_slope.path_time_constant_s);
  within("glide_slope.capture_margin_rad", glide_slope.capture_margin_rad, 0.0, 5 * kDeg);
  within("glide_slope.max_descent_factor", glide_slope.max_descent_factor, 1.0, 5.0);
  within("glide_slope.max_on_scale_deviation", glide_slope.max_on_scale_deviation, 0.1, 1.0);
  positive("lateral.heading_time_constant_s", lateral.heading_time_constant_s);
  positive("lateral.localizer_time_constant_s", lateral.localizer_time_constant_s);
  within("lateral.max_intercept_rad", lateral.max_intercept_rad, 5 * kDeg, 90 * kDeg);
  within("lateral.approach_bank_limit_rad", lateral.approach_bank_limit_rad, 5 * kDeg, 35 * kDeg);
  within("lateral.capture_bank_rad", lateral.capture_bank_rad, 5 * kDeg, lateral.approach_bank_limit_rad);
  non_negative("lateral.roll_in_time_s", lateral.roll_in_time_s);
  within("lateral.max_on_scale_deviation", lateral.max_on_scale_deviation, 0.1, 1.0);
  within("lateral.low_height_bank_limit_rad", lateral.low_height_bank_limit_rad, 1 * kDeg, 15 * kDeg);
  positive("lateral.side_force_filter_s", lateral.side_force_filter_s);

  positive("vor.track_time_constant_s", vor.track_time_constant_s);
  positive("vor.deviation_filter_s", vor.deviation_filter_s);
  positive("vor.min_nominal_distance_m", vor.min_nominal_distance_m);
  within("vor.max_nominal_distance_m", vor.max_nominal_distance_m, vor.min_nominal_distance_m, 500000.0);
  within("vor.nominal_distance_m", vor.nominal_distance_m, vor.min_nominal_distance_m, vor.max_nominal_distance_m);
  positive("vor.erratic_rate_per_s", vor.erratic_rate_per_s);
  positive("vor.erratic_filter_s", vor.erratic_filter_s);
  non_negative("vor.over_station_hold_s", vor.over_station_hold_s);
  within("vor.max_over_station_s", vor.max_over_station_s, vor.over_station_hold_s, 3600.0);

  positive("autoland.flare_arm_height_m", autoland.flare_arm_height_m);
  within("autoland.align_height_m", autoland.align_height_m, 0.0, autoland.flare_arm_height_m);
  within("autoland.flare_height_m", autoland.flare_height_m, 1.0, autoland.flare_arm_height_m);
  within("autoland.retard_height_m", autoland.retard_height_m, 0.0, autoland.flare_height_m);
  within("autoland.touchdown_sink_rate_mps", autoland.touchdown_sink_rate_mps, 0.05, 3.0);
  within("autoland.flare_extra_path_gain", autoland.flare_extra_path_gain, 0.0, 10.0);
  positive("autoland.derotation_rate_radps", autoland.derotation_rate_radps);
  within("autoland.rollout_pitch_rad", autoland.rollout_pitch_rad, -5 * kDeg, 5 * kDeg);

  non_negative("rollout.cross_track_gain_per_m", rollout.cross_track_gain_per_m);
  non_negative("rollout.heading_gain_per_rad", rollout.heading_gain_per_rad);
  non_negative("rollout.yaw_rate_gain_per_radps", rollout.yaw_rate_gain_per_radps);
  non_negative("rollout.rudder_scale", rollout.rudder_scale);
  non_negative("rollout.rudder_integral_per_s", rollout.rudder_integral_per_s);
  within("rollout.steering_limit", rollout.steering_limit, 0.0, 1.0);
  positive("rollout.taxi_speed_mps", rollout.taxi_speed_mps);
  non_negative("rollout.autobrake_delay_s", rollout.autobrake_delay_s);
  positive("rollout.deceleration_1_mps2", rollout.deceleration_1_mps2);
  within("rollout.deceleration_2_mps2", rollout.deceleration_2_mps2, rollout.deceleration_1_mps2, 20.0);
  within("rollout.deceleration_3_mps2", rollout.deceleration_3_mps2, rollout.deceleration_2_mps2, 20.0);
  within("rollout.deceleration_max_mps2", rollout.deceleration_max_mps2, rollout.deceleration_3_mps2, 20.0);
  non_negative("rollout.brake_proportional_per_mps2", rollout.brake_proportional_per_mps2);
  non_negative("rollout.brake_integral_per_mps2_s", rollout.brake_integral_per_mps2_s);
  positive("rollout.spoiler_rate_per_s", rollout.spoiler_rate_per_s);
  positive("rollout.deceleration_filter_s", rollout.deceleration_filter_s);
  positive("rollout.brake_rate_per_s", rollout.brake_rate_per_s);

  non_negative("autothrottle.speed_proportional_per_mps", autothrottle.speed_proportional_per_mps);
  non_negative("autothrottle.speed_integral_per_mps_s", autothrottle.speed_integral_per_mps_s);
  non_negative("autothrottle.speed_derivative_s", autothrottle.speed_derivative_s);
  positive("autothrottle.derivative_filter_s", autothrottle.derivative_filter_s);
  non_negative("autothrottle.climb_rate_proportional_per_mps", autothrottle.climb_rate_proportional_per_mps);
  non_negative("autothrottle.climb_rate_integral_per_mps_s", autothrottle.climb_rate_integral_per_mps_s);
  positive("autothrottle.lever_rate_per_s", autothrottle.lever_rate_per_s);
  positive("autothrottle.retard_rate_per_s", autothrottle.retard_rate_per_s);
  within("autothrottle.idle_throttle", autothrottle.idle_throttle, 0.0, 1.0);
  within("autothrottle.climb_throttle", autothrottle.climb_throttle, autothrottle.idle_throttle, 1.0);
}

}  // namespace fedsim::flight::afcs
