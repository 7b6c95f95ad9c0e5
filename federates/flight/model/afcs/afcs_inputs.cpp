#include "flight/model/afcs/afcs_inputs.hpp"

#include "common/units/units.hpp"

#include <cmath>

namespace fedsim::flight::afcs {

namespace {

bool in(double value, double lo, double hi) { return std::isfinite(value) && value >= lo && value <= hi; }
constexpr double kPi = units::kPi;
constexpr double kDeg = units::kDegToRad;

std::string_view aircraft_problem(const AfcsAircraftState& a) {
  if (!std::isfinite(a.time_s)) return "aircraft.time_s";
  if (!in(a.roll_rad, -kPi, kPi)) return "aircraft.roll_rad";
  if (!in(a.pitch_rad, -kPi / 2, kPi / 2)) return "aircraft.pitch_rad";
  if (!std::isfinite(a.heading_true_rad)) return "aircraft.heading_true_rad";
  if (!in(a.roll_rate_radps, -10.0, 10.0)) return "aircraft.roll_rate_radps";
  if (!in(a.pitch_rate_radps, -10.0, 10.0)) return "aircraft.pitch_rate_radps";
  if (!in(a.yaw_rate_radps, -10.0, 10.0)) return "aircraft.yaw_rate_radps";
  if (!in(a.calibrated_airspeed_mps, 0.0, 400.0)) return "aircraft.calibrated_airspeed_mps";
  if (!in(a.true_airspeed_mps, 0.0, 400.0)) return "aircraft.true_airspeed_mps";
  if (!in(a.ground_speed_mps, 0.0, 400.0)) return "aircraft.ground_speed_mps";
  if (!std::isfinite(a.track_true_rad)) return "aircraft.track_true_rad";
  if (!in(a.altitude_m, -1000.0, 20000.0)) return "aircraft.altitude_m";
  if (!in(a.vertical_speed_mps, -150.0, 150.0)) return "aircraft.vertical_speed_mps";
  if (!in(a.radio_height_m, -10.0, 10000.0)) return "aircraft.radio_height_m";
  if (!in(a.angle_of_attack_rad, -kPi, kPi)) return "aircraft.angle_of_attack_rad";
  if (!in(a.sideslip_rad, -kPi / 2, kPi / 2)) return "aircraft.sideslip_rad";
  if (!in(a.lateral_specific_force_mps2, -50.0, 50.0)) return "aircraft.lateral_specific_force_mps2";
  if (!in(a.longitudinal_acceleration_mps2, -100.0, 100.0)) return "aircraft.longitudinal_acceleration_mps2";
  if (!in(a.elevator, -1.0, 1.0)) return "aircraft.elevator";
  if (!in(a.aileron, -1.0, 1.0)) return "aircraft.aileron";
  if (!in(a.rudder, -1.0, 1.0)) return "aircraft.rudder";
  if (!in(a.throttle, 0.0, 1.0)) return "aircraft.throttle";
  if (!in(a.pitch_trim, -1.0, 1.0)) return "aircraft.pitch_trim";
  return {};
}

std::string_view vor_problem(const AfcsVorSignals& v) {
  if (v.valid) {
    if (!v.tuned) return "ils.vor.tuned";  // a valid VOR reading comes from a receiver tuned to it
    if (!in(v.deviation, -1.0, 1.0)) return "ils.vor.deviation";
    if (!(std::isfinite(v.full_scale_rad) && v.full_scale_rad > 0.0 && v.full_scale_rad <= 20.0 * kDeg)) {
      return "ils.vor.full_scale_rad";
    }
    if (!std::isfinite(v.course_true_rad)) return "ils.vor.course_true_rad";
    if (v.to_from != VorToFrom::kOff && v.to_from != VorToFrom::kTo && v.to_from != VorToFrom::kFrom) {
      return "ils.vor.to_from";
    }
  }
  if (v.dme_valid && !in(v.dme_slant_range_m, 0.0, 500000.0)) return "ils.vor.dme_slant_range_m";
  return {};
}

std::string_view ils_problem(const AfcsIlsSignals& s) {
  if (s.localizer_valid) {
    if (!in(s.localizer_deviation, -1.0, 1.0)) return "ils.localizer_deviation";
    if (!(std::isfinite(s.localizer_half_width_rad) && s.localizer_half_width_rad > 0.0 &&
          s.localizer_half_width_rad <= 0.2)) {
      return "ils.localizer_half_width_rad";
    }
    if (!std::isfinite(s.localizer_course_true_rad)) return "ils.localizer_course_true_rad";
    if (!in(s.localizer_distance_m, 0.0, 100000.0)) return "ils.localizer_distance_m";
  }
  if (s.glide_slope_valid) {
    if (!in(s.glide_slope_deviation, -1.0, 1.0)) return "ils.glide_slope_deviation";
    if (!in(s.glide_path_angle_rad, 0.5 * kDeg, 10.0 * kDeg)) return "ils.glide_path_angle_rad";
    if (!in(s.glide_slope_distance_m, 0.0, 100000.0)) return "ils.glide_slope_distance_m";
  }
  if (!in(s.distance_to_threshold_m, -100000.0, 100000.0)) return "ils.distance_to_threshold_m";
  return vor_problem(s.vor);
}

std::string_view mcp_problem(const McpSelections& m) {
  if (!std::isfinite(m.heading_true_rad)) return "mcp.heading_true_rad";
  if (!in(m.altitude_m, -1000.0, 20000.0)) return "mcp.altitude_m";
  if (!in(m.vertical_speed_mps, -40.0, 40.0)) return "mcp.vertical_speed_mps";
  if (!in(m.calibrated_airspeed_mps, 40.0, 200.0)) return "mcp.calibrated_airspeed_mps";
  if (!in(m.bank_limit_rad, 5.0 * kDeg - 1e-9, 30.0 * kDeg + 1e-9)) return "mcp.bank_limit_rad";
  if (m.autobrake_setting < 0 || m.autobrake_setting > 4) return "mcp.autobrake_setting";
  if (!in(m.pilot_pitch_input, -1.0, 1.0)) return "mcp.pilot_pitch_input";
  if (!in(m.pilot_roll_input, -1.0, 1.0)) return "mcp.pilot_roll_input";
  return {};
}

}  // namespace

std::string_view afcs_input_problem(const AfcsInputs& inputs) {
  if (auto p = aircraft_problem(inputs.aircraft); !p.empty()) return p;
  if (auto p = ils_problem(inputs.ils); !p.empty()) return p;
  return mcp_problem(inputs.mcp);
}

McpButtons& operator|=(McpButtons& a, const McpButtons& b) {
  a.autopilot_engage |= b.autopilot_engage;
  a.control_wheel_steering |= b.control_wheel_steering;
  a.autopilot_disconnect |= b.autopilot_disconnect;
  a.autothrottle_disconnect |= b.autothrottle_disconnect;
  a.heading_select |= b.heading_select;
  a.wing_level |= b.wing_level;
  a.vor_localizer |= b.vor_localizer;
  a.approach |= b.approach;
  a.altitude_hold |= b.altitude_hold;
  a.vertical_speed |= b.vertical_speed;
  a.level_change |= b.level_change;
  a.speed |= b.speed;
  a.thrust |= b.thrust;
  a.takeoff_go_around |= b.takeoff_go_around;
  return a;
}

}  // namespace fedsim::flight::afcs
