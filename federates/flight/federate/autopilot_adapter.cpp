#include "flight/federate/autopilot_adapter.hpp"

#include "common/radio/vor_receiver.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight {

namespace {
bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

std::string out_of_range(const char* field, double value, const char* range) {
  return std::string("mcp.") + field + " = " + std::to_string(value) + " (must be " + range + ")";
}
}  // namespace

std::optional<std::string> check_mcp(const msg::McpPanel& m) {
  constexpr double kDeg = units::kDegToRad;
  // One turn either way (the I/O sends 0..2 pi; an outside writer may send -pi..pi): 1e300 is
  // finite but no heading.
  if (!in(m.heading_true_rad(), -units::kTwoPi, units::kTwoPi)) {
    return out_of_range("heading_true_rad", m.heading_true_rad(), "within -2 pi..2 pi rad");
  }
  if (!in(m.altitude_msl_m(), -1000.0, 20000.0)) {
    return out_of_range("altitude_msl_m", m.altitude_msl_m(), "within -1000..20000 m");
  }
  if (!in(m.vertical_speed_mps(), -40.0, 40.0)) {
    return out_of_range("vertical_speed_mps", m.vertical_speed_mps(), "within -40..40 m/s");
  }
  if (!in(m.airspeed_cas_mps(), 40.0, 200.0)) {
    return out_of_range("airspeed_cas_mps", m.airspeed_cas_mps(), "within 40..200 m/s");
  }
  if (!in(m.bank_limit_rad(), 5.0 * kDeg - 1e-9, 30.0 * kDeg + 1e-9)) {
    return out_of_range("bank_limit_rad", m.bank_limit_rad(), "within 5..30 deg");
  }
  if (m.autobrake() > 4) return out_of_range("autobrake", m.autobrake(), "0..4");
  return std::nullopt;
}

afcs::McpSelections mcp_selections(const msg::McpPanel& m) {
  afcs::McpSelections s;
  s.heading_true_rad = m.heading_true_rad();
  s.altitude_m = m.altitude_msl_m();
  s.vertical_speed_mps = m.vertical_speed_mps();
  s.calibrated_airspeed_mps = m.airspeed_cas_mps();
  s.bank_limit_rad = m.bank_limit_rad();
  s.flight_director_on = m.flight_director_on();
  s.autothrottle_armed = m.autothrottle_armed();
  s.autobrake_setting = m.autobrake();
  // Control-wheel steering: from the pilot's forces, not the panel (cws_inputs()).
  s.pilot_pitch_input = 0.0;
  s.pilot_roll_input = 0.0;
  return s;
}

double cws_input_from_force(double force_n, double breakout_n, double full_n) {
  if (!std::isfinite(force_n)) return 0.0;
  const double beyond = std::abs(force_n) - breakout_n;
  if (beyond <= 0.0) return 0.0;
  return std::copysign(std::min(1.0, beyond / (full_n - breakout_n)), force_n);
}

std::optional<std::string> check_pilot_forces(const msg::PilotControls& pilot) {
  static constexpr const char* kAxis[3] = {"column", "wheel", "pedals"};
  for (std::size_t i = 0; i < 3; ++i) {
    const double f = pilot.pilot_force_n()[i];
    if (!in(f, -kMaxPilotForceN, kMaxPilotForceN)) {
      return std::string("pilot_force_n[") + std::to_string(i) + "] (" + kAxis[i] + ") = " + std::to_string(f) +
             " (must be finite, within +-2000 N)";
    }
  }
  return std::nullopt;
}

CwsInputs cws_inputs(const msg::PilotControls& pilot, const afcs::AfcsParameters& p) {
  CwsInputs c;
  if ((pilot.discretes() & msg::DISCRETE_FORCE_SENSORS) == 0) return c;
  if ((pilot.discretes() & msg::DISCRETE_INPUTS_INVALID) != 0) return c;
  // Column + push = nose down: the pitch input (+ nose up) has the opposite sign.
  c.pitch = -cws_input_from_force(pilot.pilot_force_n()[0], p.cws_breakout_force_n, p.cws_full_column_force_n);
  c.roll = cws_input_from_force(pilot.pilot_force_n()[1], p.cws_breakout_force_n, p.cws_full_wheel_force_n);
  return c;
}

afcs::McpSelections mcp_before_first_sample(const afcs::AfcsAircraftState& a) {
  afcs::McpSelections s;
  s.heading_true_rad = std::isfinite(a.heading_true_rad) ? a.heading_true_rad : 0.0;
  s.altitude_m = std::isfinite(a.altitude_m) ? std::clamp(a.altitude_m, -1000.0, 20000.0) : 0.0;
  s.vertical_speed_mps = 0.0;
  s.calibrated_airspeed_mps =
      std::isfinite(a.calibrated_airspeed_mps) ? std::clamp(a.calibrated_airspeed_mps, 40.0, 200.0) : 40.0;
  s.autothrottle_armed = false;
  return s;
}

afcs::McpButtons McpPressTracker::presses(const msg::McpPanel& mcp) {
  std::array<bool, msg::MCP_BUTTON_COUNT> pressed{};
  for (std::size_t i = 0; i < counts_.size(); ++i) {
    const std::uint32_t now = mcp.presses()[i];
    pressed[i] = seen_ && now > counts_[i];
    counts_[i] = now;  // also the baseline after a restart (a count that went down)
  }
  seen_ = true;
  afcs::McpButtons b;
  b.autopilot_engage = pressed[msg::MCP_CMD];
  b.control_wheel_steering = pressed[msg::MCP_CWS];
  b.autopilot_disconnect = pressed[msg::MCP_AP_DISCONNECT];
  b.autothrottle_disconnect = pressed[msg::MCP_AT_DISCONNECT];
  b.heading_select = pressed[msg::MCP_HDG_SEL];
  b.wing_level = pressed[msg::MCP_WLV];
  b.vor_localizer = pressed[msg::MCP_VOR_LOC];
  b.approach = pressed[msg::MCP_APP];
  b.altitude_hold = pressed[msg::MCP_ALT_HLD];
  b.vertical_speed = pressed[msg::MCP_VS];
  b.level_change = pressed[msg::MCP_LVL_CHG];
  b.speed = pressed[msg::MCP_SPEED];
  b.thrust = pressed[msg::MCP_N1];
  b.takeoff_go_around = pressed[msg::MCP_TOGA];
  return b;
}

afcs::AfcsIlsSignals ils_signals_from_receiver(const msg::NavReceiver& nav) {
  afcs::AfcsIlsSignals s;
  s.localizer_valid = nav.status() == msg::SIGNAL_VALID && nav.signal() == msg::NAV_SIGNAL_LOCALIZER;
  if (s.localizer_valid) {
    s.localizer_deviation = nav.course_deviation();
    s.localizer_half_width_rad = nav.localizer_half_width_rad();
    s.localizer_course_true_rad = nav.course_true_rad();
    s.localizer_distance_m = nav.localizer_distance_m();
    s.distance_to_threshold_m = nav.threshold_distance_m();
  }
  s.glide_slope_valid = s.localizer_valid && nav.glideslope_status() == msg::SIGNAL_VALID;
  if (s.glide_slope_valid) {
    s.glide_slope_deviation = nav.glideslope_deviation();
    s.glide_path_angle_rad = nav.glide_path_angle_rad();
    s.glide_slope_distance_m = nav.glideslope_distance_m();
  }
  s.vor = vor_signals_from_receiver(nav);
  return s;
}

namespace {
afcs::VorToFrom to_from(msg::ToFromFlag flag) {
  switch (flag) {
    case msg::TO_FROM_TO: return afcs::VorToFrom::kTo;
    case msg::TO_FROM_FROM: return afcs::VorToFrom::kFrom;
    default: return afcs::VorToFrom::kOff;
  }
}
}  // namespace

afcs::AfcsVorSignals vor_signals_from_receiver(const msg::NavReceiver& nav) {
  afcs::AfcsVorSignals v;
  v.tuned = nav.signal() == msg::NAV_SIGNAL_VOR;
  if (!v.tuned) return v;
  v.valid = nav.status() == msg::SIGNAL_VALID;
  v.cone_of_confusion = nav.status() == msg::SIGNAL_CONE_OF_CONFUSION;
  if (v.valid) {
    v.deviation = nav.course_deviation();
    v.full_scale_rad = radio::VorReceiverSettings{}.full_scale_rad;
    v.course_true_rad = nav.course_true_rad();
    v.to_from = to_from(nav.to_from());
  }
  v.dme_valid = nav.dme_status() == msg::SIGNAL_VALID;
  if (v.dme_valid) v.dme_slant_range_m = nav.dme_slant_range_m();
  return v;
}

// The IDL enums list the modes in afcs_modes.hpp's order: the casts below rely on it.
static_assert(static_cast<int>(afcs::ThrustMode::kGoAround) == msg::FMA_THRUST_GO_AROUND);
static_assert(static_cast<int>(afcs::ThrustMode::kRetard) == msg::FMA_THRUST_RETARD);
static_assert(static_cast<int>(afcs::LateralMode::kGoAround) == msg::FMA_ROLL_GO_AROUND);
static_assert(static_cast<int>(afcs::LateralMode::kLocalizer) == msg::FMA_ROLL_LOCALIZER);
static_assert(static_cast<int>(afcs::VerticalMode::kGoAround) == msg::FMA_PITCH_GO_AROUND);
static_assert(static_cast<int>(afcs::VerticalMode::kGlideSlope) == msg::FMA_PITCH_GLIDE_SLOPE);
static_assert(afcs::kAlertAutothrottleFailed == msg::AFCS_ALERT_AT_FAILED);
static_assert(afcs::kAlertAttitudeLimit == msg::AFCS_ALERT_ATTITUDE_LIMIT);

msg::FmaThrustMode to_message(afcs::ThrustMode mode) {
  return static_cast<msg::FmaThrustMode>(static_cast<int>(mode));
}
msg::FmaRollMode to_message(afcs::LateralMode mode) {
  return static_cast<msg::FmaRollMode>(static_cast<int>(mode));
}
msg::FmaPitchMode to_message(afcs::VerticalMode mode) {
  return static_cast<msg::FmaPitchMode>(static_cast<int>(mode));
}

void fill_autopilot_state(const afcs::Afcs& afcs, std::uint32_t transitions, msg::AutopilotState& out) {
  const afcs::AfcsOutputs& o = afcs.outputs();
  const afcs::Fma& f = o.fma;
  msg::FlightModeAnnunciator& fma = out.fma();
  fma.thrust(to_message(f.thrust));
  fma.roll(to_message(f.lateral));
  fma.roll_armed_localizer(f.lateral_armed.localizer);
  fma.roll_armed_rollout(f.lateral_armed.rollout);
  fma.pitch(to_message(f.vertical));
  fma.pitch_armed_altitude(f.vertical_armed.altitude_capture);
  fma.pitch_armed_glide_slope(f.vertical_armed.glide_slope);
  fma.pitch_armed_flare(f.vertical_armed.flare);
  fma.autopilot_engaged(f.autopilot_engaged);
  fma.flight_director_on(f.flight_director_on);
  fma.autothrottle_engaged(f.autothrottle_engaged);
  fma.alerts(f.alerts);
  out.transitions(transitions);
  out.fd_roll_valid(o.flight_director_roll_valid);
  out.fd_roll_rad(o.flight_director_roll_rad);
  out.fd_pitch_valid(o.flight_director_pitch_valid);
  out.fd_pitch_rad(o.flight_director_pitch_rad);
  out.hold_altitude_msl_m(afcs.hold_altitude_m());
  out.flight_path_command_rad(o.flight_path_command_rad);
  out.cross_track_left_m(o.cross_track_left_m);
  out.glide_path_below_m(o.glide_path_height_error_m);
  out.elevator(o.elevator);
  out.aileron(o.aileron);
  out.rudder(o.rudder);
  out.pitch_trim_command(static_cast<int16_t>(o.pitch_trim_command));
  out.throttle(o.throttle);
  out.rollout_engaged(o.rollout_engaged);
  out.steering(o.steering);
  out.brake_left(o.brake_left);
  out.brake_right(o.brake_right);
  out.spoilers(o.spoilers);
  const std::string_view problem = afcs.last_input_problem();
  out.input_problem(std::string(problem.substr(0, 32)));
}

}  // namespace fedsim::flight
