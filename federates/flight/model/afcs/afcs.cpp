#include "flight/model/afcs/afcs.hpp"

#include "flight/model/afcs/lateral_guidance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::flight::afcs {

namespace {

constexpr double kG = units::kStandardGravityMps2;

double checked_dt(double dt_s) {
  if (!(std::isfinite(dt_s) && dt_s > 0.0 && dt_s <= 0.1)) {
    throw std::invalid_argument("Afcs: dt_s = " + std::to_string(dt_s) + " must lie in (0, 0.1] s");
  }
  return dt_s;
}

const AfcsParameters& checked(const AfcsParameters& p) {
  p.validate();
  return p;
}

control::PidParameters speed_on_elevator_pid(const SpeedOnElevatorGains& g) {
  // gamma_c = (CAS - CAS_sel) / (g tau) + integral: a speed error of g tau gamma removes itself
  // through the path change gamma (dV/dt = -g dgamma at constant thrust) in about tau.
  const double kp = 1.0 / (kG * g.time_constant_s);
  return control::pi_parameters(kp, kp / g.integral_time_s, g.min_descent_path_rad,
                                g.max_climb_path_rad);
}

// Source ids for the faders: a mode enum, or a group of modes that share a law.
int bank_law(const ModeState& m) {
  return static_cast<int>(m.lateral) + (m.vor ? 100 : 0) + (m.vor_over_station ? 100 : 0);
}

int rudder_law(LateralMode mode) {
  switch (mode) {
    case LateralMode::kAlign: return 1;
    case LateralMode::kRollout: return 2;
    default: return 0;
  }
}

}  // namespace

struct Afcs::Guidance {
  double schedule = 1.0;          // (reference CAS / CAS)^2, limited
  double path_rad = 0.0;          // gamma over the ground
  double altitude_error_m = 0.0;  // MCP altitude - altitude
  bool localizer_valid = false;
  double cross_track_left_m = 0.0;
  VorEstimate vor;                // NAV1's VOR (vor_guidance)
  bool glide_slope_valid = false;
  double height_error_m = 0.0;    // below the glide path
  double deceleration_mps2 = 0.0;
  // Euler-angle rates (the attitude loops damp these: in a steady turn the body pitch rate
  // q = psi_dot sin(phi) cos(theta) is not zero, and damping q would fight the turn).
  double pitch_attitude_rate_radps = 0.0;  // theta_dot = q cos(phi) - r sin(phi)
  double bank_rate_radps = 0.0;            // phi_dot = p + tan(theta) (q sin(phi) + r cos(phi))
};

Afcs::Afcs(const AfcsParameters& parameters, double dt_s, TransitionCallback on_transition)
    : parameters_(checked(parameters)),
      dt_s_(checked_dt(dt_s)),
      logic_(std::move(on_transition), parameters_.vor),
      pitch_loop_(parameters_.pitch, dt_s_),
      roll_loop_(parameters_.roll, dt_s_),
      yaw_(parameters_.yaw, dt_s_),
      path_loop_(parameters_.path, dt_s_),
      speed_on_elevator_(speed_on_elevator_pid(parameters_.speed_on_elevator), dt_s_),
      autothrottle_(parameters_.autothrottle, dt_s_),
      rollout_(parameters_.rollout, dt_s_),
      vor_(parameters_.vor, dt_s_),
      bank_fader_(std::max(parameters_.fade_time_s, dt_s_), dt_s_),
      path_fader_(std::max(parameters_.fade_time_s, dt_s_), dt_s_),
      pitch_fader_(std::max(parameters_.fade_time_s, dt_s_), dt_s_),
      rudder_fader_(std::max(parameters_.fade_time_s, dt_s_), dt_s_),
      elevator_fader_(std::max(parameters_.fade_time_s, dt_s_), dt_s_),
      bank_rate_(parameters_.roll.bank_rate_limit_radps, dt_s_),
      side_force_(parameters_.lateral.side_force_filter_s, dt_s_),
      trim_load_(parameters_.trim_filter_s, dt_s_),
      pitch_command_rate_(parameters_.command_rate_filter_s, dt_s_),
      bank_command_rate_(parameters_.command_rate_filter_s, dt_s_) {}

void Afcs::reset() {
  logic_.reset();
  vor_.reset();
  outputs_ = AfcsOutputs{};
  input_problem_ = {};
  first_frame_ = true;
  trim_elevator_time_s_ = 0.0;
  trim_command_ = 0;
}

// ---- Per frame -------------------------------------------------------------------------------

const AfcsOutputs& Afcs::step(const AfcsInputs& in) {
  input_problem_ = afcs_input_problem(in);
  if (!input_problem_.empty()) {
    ModeConditions bad;
    bad.inputs_valid = false;
    bad.autopilot_failed = in.failures.autopilot;
    bad.autothrottle_failed = in.failures.autothrottle;
    logic_.update(std::isfinite(in.aircraft.time_s) ? in.aircraft.time_s : 0.0, in.buttons, in.mcp, bad);
    hold_after_bad_sample();
    return outputs_;
  }
  side_force_.step(in.aircraft.lateral_specific_force_mps2);
  vor_.step(in.ils.vor, in.aircraft.ground_speed_mps, in.aircraft.track_true_rad);
  const Guidance g = evaluate_guidance(in);
  const ModeConditions c = conditions(in, g);
  const ModeState before = logic_.state();
  logic_.update(in.aircraft.time_s, in.buttons, in.mcp, c);
  enter_modes(before, in, g);
  previous_mcp_altitude_m_ = in.mcp.altitude_m;
  first_frame_ = false;

  const ModeState& m = logic_.state();
  const bool modes_active = m.lateral != LateralMode::kNone || m.vertical != VerticalMode::kNone;
  double bank_c = in.aircraft.roll_rad;
  double pitch_c = in.aircraft.pitch_rad;
  if (modes_active) {
    bank_c = bank_command_rad(in, g);
    pitch_c = pitch_command_rad(in, g);
  } else {
    bank_fader_.reset(0, bank_c);
    pitch_fader_.reset(0, pitch_c);
    bank_rate_.reset(bank_c);
  }
  previous_bank_command_rad_ = bank_command_rad_;
  previous_pitch_command_rad_ = pitch_command_rad_;
  bank_command_rad_ = bank_c;
  pitch_command_rad_ = pitch_c;
  if (m.autopilot_engaged) {
    if (!before.autopilot_engaged) track_pilot(in, g);  // engagement: take over from the pilot
    fly_surfaces(in, g, pitch_c, bank_c);
    fly_rudder_and_rollout(in, g);
    auto_trim(in, g.schedule);
  } else {
    track_pilot(in, g);
  }
  fly_throttle(in, g);
  fill_annunciation(g, pitch_c, bank_c);
  return outputs_;
}

Afcs::Guidance Afcs::evaluate_guidance(const AfcsInputs& in) const {
  const AfcsAircraftState& a = in.aircraft;
  const AfcsIlsSignals& ils = in.ils;
  Guidance g;
  const double cas = std::max(a.calibrated_airspeed_mps, 20.0);
  const double ratio = parameters_.reference_cas_mps / cas;
  g.schedule = std::clamp(ratio * ratio, parameters_.min_gain_schedule, parameters_.max_gain_schedule);
  g.path_rad = flight_path_angle_rad(a.vertical_speed_mps, a.ground_speed_mps);
  g.altitude_error_m = in.mcp.altitude_m - a.altitude_m;
  g.localizer_valid = ils.localizer_valid;
  if (g.localizer_valid) {
    g.cross_track_left_m = localizer_cross_track_left_m(ils.localizer_deviation, ils.localizer_half_width_rad,
                                                        ils.localizer_distance_m);
  }
  g.vor = vor_.estimate();
  g.glide_slope_valid = ils.glide_slope_valid;
  if (g.glide_slope_valid) {
    g.height_error_m = glide_path_height_error_m(ils.glide_slope_deviation, ils.glide_path_angle_rad,
                                                 ils.glide_slope_distance_m);
  }
  g.deceleration_mps2 = -a.longitudinal_acceleration_mps2;
  const double sin_phi = std::sin(a.roll_rad), cos_phi = std::cos(a.roll_rad);
  g.pitch_attitude_rate_radps = a.pitch_rate_radps * cos_phi - a.yaw_rate_radps * sin_phi;
  g.bank_rate_radps = a.roll_rate_radps + std::tan(std::clamp(a.pitch_rad, -1.4, 1.4)) *
                                              (a.pitch_rate_radps * sin_phi + a.yaw_rate_radps * cos_phi);
  return g;
}

ModeConditions Afcs::conditions(const AfcsInputs& in, const Guidance& g) const {
  const AfcsAircraftState& a = in.aircraft;
  const AfcsParameters& p = parameters_;
  const ModeState& m = logic_.state();
  ModeConditions c;
  c.inputs_valid = true;
  c.autopilot_failed = in.failures.autopilot;
  c.autothrottle_failed = in.failures.autothrottle;
  c.on_ground = a.main_gear_on_ground;
  c.stopped = a.main_gear_on_ground && a.ground_speed_mps < p.rollout.taxi_speed_mps;
  c.localizer_valid = g.localizer_valid;
  c.glide_slope_valid = g.glide_slope_valid;
  if (g.localizer_valid) {
    c.localizer_capture = localizer_capture_point(in.ils.localizer_deviation, g.cross_track_left_m,
                                                  in.ils.localizer_course_true_rad, a.track_true_rad,
                                                  a.ground_speed_mps, p.lateral);
  }
  c.vor_tuned = in.ils.vor.tuned;
  c.vor_valid = in.ils.vor.tuned && g.vor.valid;
  c.vor_cone_of_confusion = in.ils.vor.tuned && in.ils.vor.cone_of_confusion;
  c.vor_station_passage = g.vor.erratic || g.vor.passed_station;
  if (c.vor_valid) {
    // On scale by the raw deviation (what the CDI shows), the lead on the filtered one.
    c.vor_capture = course_capture_point(in.ils.vor.deviation, g.vor.cross_track_left_m, in.ils.vor.course_true_rad,
                                         a.track_true_rad, a.ground_speed_mps,
                                         vor_course_law(p.lateral, p.vor, in.mcp.bank_limit_rad));
  }
  if (g.glide_slope_valid) {
    c.glide_slope_capture = glide_slope_capture_point(in.ils.glide_slope_deviation, g.height_error_m,
                                                      in.ils.glide_path_angle_rad, a.ground_speed_mps,
                                                      g.path_rad, p.glide_slope);
  }
  c.altitude_capture = altitude_capture_point(g.altitude_error_m, a.vertical_speed_mps, p.altitude);
  c.altitude_captured = std::abs(g.altitude_error_m) < p.altitude.hold_band_m;
  c.selected_altitude_changed = !first_frame_ && std::abs(in.mcp.altitude_m - previous_mcp_altitude_m_) > 0.1;
  c.selected_altitude_above = g.altitude_error_m > 0.0;
  // "Ahead": in the direction the mode is taking the aircraft.
  double direction = a.vertical_speed_mps;
  if (m.vertical == VerticalMode::kVerticalSpeed || in.buttons.vertical_speed) direction = in.mcp.vertical_speed_mps;
  if (m.vertical == VerticalMode::kLevelChange) direction = level_change_direction_;
  if (m.vertical == VerticalMode::kGoAround) direction = 1.0;
  c.selected_altitude_ahead = g.altitude_error_m * direction > 0.0 &&
                              std::abs(g.altitude_error_m) >= p.altitude.hold_band_m;
  const double h = a.radio_height_m;
  c.below_flare_arm_height = h < p.autoland.flare_arm_height_m;
  c.below_align_height = h < p.autoland.align_height_m;
  c.below_flare_height = h < p.autoland.flare_height_m;
  c.below_retard_height = h < p.autoland.retard_height_m;
  const double bank = std::abs(a.roll_rad);
  c.attitude_engage_limits = bank <= p.engage_bank_limit_rad && a.pitch_rad >= p.engage_pitch_min_rad &&
                             a.pitch_rad <= p.engage_pitch_max_rad;
  c.attitude_authority_limits = bank <= p.authority_bank_limit_rad && a.pitch_rad >= p.authority_pitch_min_rad &&
                                a.pitch_rad <= p.authority_pitch_max_rad;
  c.wings_level = bank < p.wings_level_bank_rad;
  return c;
}

// ---- Mode entry: capture the references a mode holds -----------------------------------------

void Afcs::enter_modes(const ModeState& before, const AfcsInputs& in, const Guidance& g) {
  const ModeState& m = logic_.state();
  const AfcsAircraftState& a = in.aircraft;
  if (m.lateral != before.lateral) {
    switch (m.lateral) {
      case LateralMode::kHeadingHold: hold_heading_rad_ = a.heading_true_rad; break;
      case LateralMode::kRollAttitude: hold_bank_rad_ = a.roll_rad; break;
      case LateralMode::kGoAround: hold_track_rad_ = a.track_true_rad; break;
      case LateralMode::kAlign: yaw_.engage_align(outputs_.rudder, a.heading_true_rad); break;
      case LateralMode::kRollout: rollout_.reset(outputs_.rudder); break;
      default: break;
    }
    if (rudder_law(before.lateral) != 0 && rudder_law(m.lateral) == 0) {
      yaw_.engage_coordination(outputs_.rudder, a.sideslip_rad);
    }
  }
  if (m.vor_over_station && !before.vor_over_station) {
    over_station_course_rad_ = g.vor.course_true_rad;  // the last valid course: the cone flags the reading
  }
  if (!m.vor_over_station && before.vor_over_station) vor_.station_passed();
  if (m.vertical != before.vertical) {
    switch (m.vertical) {
      case VerticalMode::kPitchAttitude: hold_pitch_rad_ = a.pitch_rad; break;
      case VerticalMode::kAltitudeHold:
        hold_altitude_m_ = logic_.altitude_hold_at_present_altitude() ? a.altitude_m : in.mcp.altitude_m;
        break;
      case VerticalMode::kLevelChange:
        level_change_direction_ = g.altitude_error_m > 0.0 ? 1.0 : -1.0;
        speed_on_elevator_.engage(a.calibrated_airspeed_mps - in.mcp.calibrated_airspeed_mps,
                                  std::clamp(g.path_rad, parameters_.speed_on_elevator.min_descent_path_rad,
                                             parameters_.speed_on_elevator.max_climb_path_rad));
        break;
      case VerticalMode::kGoAround:
        go_around_speed_mps_ = std::max(in.mcp.calibrated_airspeed_mps, a.calibrated_airspeed_mps);
        speed_on_elevator_.engage(a.calibrated_airspeed_mps - go_around_speed_mps_,
                                  std::clamp(g.path_rad, parameters_.speed_on_elevator.go_around_min_path_rad,
                                             parameters_.speed_on_elevator.max_climb_path_rad));
        break;
      case VerticalMode::kFlare:
        flare_ = FlareLaw::at_entry(a.radio_height_m, a.vertical_speed_mps, parameters_.autoland);
        break;
      case VerticalMode::kRollout: derotation_pitch_rad_ = a.pitch_rad; break;
      default: break;
    }
    if (is_path_mode(m.vertical) && !is_path_mode(before.vertical)) {
      path_loop_.engage(pitch_command_rad_, 0.0, a.roll_rad, g.schedule, a.angle_of_attack_rad);
      path_fader_.reset(static_cast<int>(m.vertical), g.path_rad);
    }
  }
  if (m.autothrottle_engaged && !before.autothrottle_engaged) autothrottle_.engage(a.throttle);
}

// ---- Commands --------------------------------------------------------------------------------

double Afcs::bank_command_rad(const AfcsInputs& in, const Guidance& g) {
  const AfcsAircraftState& a = in.aircraft;
  const LateralGains& lat = parameters_.lateral;
  const double tau = lat.heading_time_constant_s;
  const double v = a.true_airspeed_mps;
  double bank = a.roll_rad;
  switch (logic_.state().lateral) {
    case LateralMode::kRollAttitude:
      hold_bank_rad_ = std::clamp(hold_bank_rad_ + parameters_.cws_roll_rate_radps * in.mcp.pilot_roll_input * dt_s_,
                                  -parameters_.engage_bank_limit_rad, parameters_.engage_bank_limit_rad);
      bank = hold_bank_rad_;
      break;
    case LateralMode::kWingLevel:
    case LateralMode::kRollout:
      bank = 0.0;
      break;
    case LateralMode::kHeadingHold:
      bank = bank_for_direction_error_rad(hold_heading_rad_ - a.heading_true_rad, v, tau, in.mcp.bank_limit_rad);
      break;
    case LateralMode::kHeadingSelect:
      bank = bank_for_direction_error_rad(in.mcp.heading_true_rad - a.heading_true_rad, v, tau,
                                          in.mcp.bank_limit_rad);
      break;
    case LateralMode::kLocalizer:
      if (logic_.state().vor) {
        bank = vor_bank_command_rad(in, g);
        break;
      }
      bank = bank_for_direction_error_rad(
          localizer_track_command_rad(g.cross_track_left_m, in.ils.localizer_course_true_rad, a.ground_speed_mps, lat) -
              a.track_true_rad,
          v, tau, lat.approach_bank_limit_rad);
      break;
    case LateralMode::kAlign: {
      // Decrabbed, the aircraft sideslips into the wind and the side force Y = m f_y pushes it
      // downwind; the bank that holds the track against it is asin(-f_y / g) (the forward slip),
      // plus the localizer law's own correction, within the low-height bank limit.
      const double limit = lat.low_height_bank_limit_rad;
      const double slip_bank = std::asin(std::clamp(-side_force_.output() / kG, -std::sin(limit), std::sin(limit)));
      const double track_c = localizer_track_command_rad(g.cross_track_left_m, in.ils.localizer_course_true_rad,
                                                         a.ground_speed_mps, lat);
      bank = std::clamp(slip_bank + bank_for_direction_error_rad(track_c - a.track_true_rad, v, tau, limit), -limit,
                        limit);
      break;
    }
    case LateralMode::kGoAround:
      bank = bank_for_direction_error_rad(hold_track_rad_ - a.track_true_rad, v, tau, 15.0 * units::kDegToRad);
      break;
    case LateralMode::kNone:
      break;
  }
  const double faded = bank_fader_.step(bank_law(logic_.state()), bank);
  return bank_rate_.step(faded);
}

double Afcs::vor_bank_command_rad(const AfcsInputs& in, const Guidance& g) const {
  // The localizer's law on the VOR's lateral distance (lateral_guidance), within the MCP's bank
  // limit (the 737's bank angle selector limits VOR/LOC as HDG SEL); over the station the
  // course is held as a track: the bearing there is lost or meaningless.
  const AfcsAircraftState& a = in.aircraft;
  const LateralGains& lat = parameters_.lateral;
  const double limit = std::min(in.mcp.bank_limit_rad, lat.approach_bank_limit_rad);
  const double track_c =
      logic_.state().vor_over_station
          ? over_station_course_rad_
          : course_track_command_rad(g.vor.cross_track_left_m, g.vor.course_true_rad, a.ground_speed_mps,
                                     vor_course_law(lat, parameters_.vor, in.mcp.bank_limit_rad));
  return bank_for_direction_error_rad(track_c - a.track_true_rad, a.true_airspeed_mps, lat.heading_time_constant_s,
                                      limit);
}

double Afcs::path_command_rad(const AfcsInputs& in, const Guidance& g) {
  const AfcsAircraftState& a = in.aircraft;
  const AfcsParameters& p = parameters_;
  const double vg = std::max(a.ground_speed_mps, 10.0);
  auto path_for_rate = [vg](double climb_rate_mps) { return std::atan2(climb_rate_mps, vg); };
  switch (logic_.state().vertical) {
    case VerticalMode::kAltitudeHold: {
      const double rate = std::clamp(altitude_rate_command_mps(hold_altitude_m_ - a.altitude_m, p.altitude),
                                     -p.altitude.max_hold_rate_mps, p.altitude.max_hold_rate_mps);
      return path_for_rate(rate);
    }
    case VerticalMode::kAltitudeCapture:
      return path_for_rate(altitude_rate_command_mps(g.altitude_error_m, p.altitude));
    case VerticalMode::kVerticalSpeed:
      return path_for_rate(in.mcp.vertical_speed_mps);
    case VerticalMode::kLevelChange: {
      const double gamma = speed_on_elevator_.step(a.calibrated_airspeed_mps - in.mcp.calibrated_airspeed_mps);
      return level_change_direction_ > 0.0 ? std::max(gamma, 0.0) : std::min(gamma, 0.0);
    }
    case VerticalMode::kGoAround: {
      const double gamma = speed_on_elevator_.step(a.calibrated_airspeed_mps - go_around_speed_mps_);
      return std::max(gamma, p.speed_on_elevator.go_around_min_path_rad);
    }
    case VerticalMode::kGlideSlope:
      return glide_slope_path_command_rad(g.height_error_m, in.ils.glide_path_angle_rad, a.ground_speed_mps,
                                          p.glide_slope);
    case VerticalMode::kFlare:
      return path_for_rate(flare_.climb_rate_command_mps(a.radio_height_m));
    default:
      return g.path_rad;
  }
}

double Afcs::pitch_command_rad(const AfcsInputs& in, const Guidance& g) {
  const AfcsAircraftState& a = in.aircraft;
  const AfcsParameters& p = parameters_;
  const VerticalMode mode = logic_.state().vertical;
  double pitch = a.pitch_rad;
  path_command_rad_ = 0.0;
  if (is_path_mode(mode)) {
    const double gamma_c = path_fader_.step(static_cast<int>(mode), path_command_rad(in, g));
    path_command_rad_ = gamma_c;
    const double pitch_max = mode == VerticalMode::kGoAround ? p.speed_on_elevator.go_around_pitch_max_rad
                                                             : p.path.pitch_max_rad;
    // The flare's lead: gamma follows pitch with the path lag T, so the pitch leads the
    // commanded path by T d(gamma_c)/dt = T (-hdot / tau_flare) / V (the law's hdot_c changes at
    // -hdot / tau).
    // The flare is short (6-8 s, a few path-loop time constants): its path error also acts
    // through an extra proportional gain (not integrated), so the sink rate follows the law
    // instead of lagging it into the runway.
    const double lead = mode == VerticalMode::kFlare
                            ? p.path.path_lag_s * (-a.vertical_speed_mps) /
                                      (flare_.time_constant_s * std::max(a.ground_speed_mps, 10.0)) +
                                  p.autoland.flare_extra_path_gain * p.path.proportional_gain * (gamma_c - g.path_rad)
                            : 0.0;
    pitch = path_loop_.step(gamma_c, g.path_rad, a.roll_rad, pitch_max, g.schedule, a.angle_of_attack_rad, lead);
  } else if (mode == VerticalMode::kPitchAttitude) {
    hold_pitch_rad_ = std::clamp(hold_pitch_rad_ + p.cws_pitch_rate_radps * in.mcp.pilot_pitch_input * dt_s_,
                                 p.engage_pitch_min_rad, p.engage_pitch_max_rad);
    pitch = hold_pitch_rad_;
  } else if (mode == VerticalMode::kRollout) {
    // Derotation: the nose comes down at a constant rate to the ground attitude.
    derotation_pitch_rad_ = std::max(derotation_pitch_rad_ - p.autoland.derotation_rate_radps * dt_s_,
                                     p.autoland.rollout_pitch_rad);
    pitch = derotation_pitch_rad_;
  }
  if (!is_path_mode(mode)) path_loop_.engage(pitch, 0.0, a.roll_rad, g.schedule, a.angle_of_attack_rad);
  return pitch_fader_.step(static_cast<int>(mode), pitch);
}

void Afcs::fly_surfaces(const AfcsInputs& in, const Guidance& g, double pitch_c, double bank_c) {
  const AfcsAircraftState& a = in.aircraft;
  constexpr double kMaxCommandRateRadps = 10.0 * units::kDegToRad;
  // The commands' own rates, smoothed: a rate that steps (a rate limit starting or ending) must
  // not step a surface.
  const double pitch_c_rate = pitch_command_rate_.step(std::clamp(
      (pitch_c - previous_pitch_command_rad_) / dt_s_, -kMaxCommandRateRadps, kMaxCommandRateRadps));
  const double bank_c_rate = bank_command_rate_.step(std::clamp(
      (bank_c - previous_bank_command_rad_) / dt_s_, -kMaxCommandRateRadps, kMaxCommandRateRadps));
  const double pitch_rate_error = g.pitch_attitude_rate_radps - pitch_c_rate;
  // The loop's demand is elevator + trim: the elevator servo takes the part the trim does not.
  const double demand = pitch_loop_.step(pitch_c, a.pitch_rad, pitch_rate_error, g.schedule);
  double elevator = std::clamp(demand - a.pitch_trim, -1.0, 1.0);
  // With the nose wheel down in the rollout the column is released to neutral (faded).
  const bool nose_down = logic_.state().vertical == VerticalMode::kRollout && a.nose_gear_on_ground;
  elevator = elevator_fader_.step(nose_down ? 1 : 0, nose_down ? 0.0 : elevator);
  if (nose_down) pitch_loop_.engage(elevator + a.pitch_trim, pitch_c - a.pitch_rad, pitch_rate_error, g.schedule);
  outputs_.elevator = elevator;
  outputs_.aileron = roll_loop_.step(bank_c, a.roll_rad, g.bank_rate_radps - bank_c_rate, g.schedule);
}

void Afcs::fly_rudder_and_rollout(const AfcsInputs& in, const Guidance& g) {
  const AfcsAircraftState& a = in.aircraft;
  const LateralMode lateral = logic_.state().lateral;
  double rudder = 0.0;
  outputs_.rollout_engaged = false;
  if (lateral == LateralMode::kAlign) {
    rudder = yaw_.align(in.ils.localizer_course_true_rad, a.heading_true_rad, a.yaw_rate_radps);
  } else if (lateral == LateralMode::kRollout) {
    const RolloutCommand r = rollout_.step(g.cross_track_left_m,
                                           wrap_angle_rad(in.ils.localizer_course_true_rad - a.heading_true_rad),
                                           a.yaw_rate_radps, a.ground_speed_mps, g.deceleration_mps2,
                                           in.mcp.autobrake_setting);
    rudder = r.rudder;
    outputs_.rollout_engaged = true;
    outputs_.steering = a.nose_gear_on_ground ? r.steering : 0.0;
    outputs_.brake_left = r.brake;
    outputs_.brake_right = r.brake;
    outputs_.spoilers = r.spoilers;
  } else {
    rudder = yaw_.coordinate(a.sideslip_rad);
  }
  outputs_.rudder = rudder_fader_.step(rudder_law(lateral), rudder);
}

void Afcs::auto_trim(const AfcsInputs& in, double schedule) {
  // Unload the elevator servo onto the trim (the stabiliser of the 737): run the trim motor in
  // the elevator's sense while the elevator's steady load (low-passed) has been off neutral for
  // trim_delay, until it is back within trim_stop. The trim is a second, slow integrator beside
  // the pitch loop's: acting on the raw elevator with a narrow hysteresis it limit-cycled with
  // the phugoid (+-0.07 of trim every 13 s at 250 KCAS); on the steady load it does not.
  const double e = trim_load_.step(outputs_.elevator);
  const AfcsParameters& p = parameters_;
  const bool on_runway = logic_.state().vertical == VerticalMode::kRollout || in.aircraft.main_gear_on_ground;
  trim_output_ = 0;
  if (on_runway || !p.auto_trim) {
    trim_load_.reset(outputs_.elevator);
    trim_command_ = 0;
    trim_elevator_time_s_ = 0.0;
    return;
  }
  if (trim_command_ != 0) {
    if (std::abs(e) < p.trim_stop_elevator || (e > 0) != (trim_command_ > 0)) trim_command_ = 0;
  } else {
    trim_elevator_time_s_ = std::abs(e) > p.trim_start_elevator ? trim_elevator_time_s_ + dt_s_ : 0.0;
    if (trim_elevator_time_s_ > p.trim_delay_s) trim_command_ = e > 0 ? 1 : -1;
  }
  if (trim_command_ == 0) {
    trim_duty_credit_ = 0.0;
    return;
  }
  trim_elevator_time_s_ = 0.0;
  // Pulses: on in a share `schedule` of the frames (at most all of them).
  trim_duty_credit_ += std::min(schedule, 1.0);
  if (trim_duty_credit_ >= 1.0) {
    trim_duty_credit_ -= 1.0;
    trim_output_ = trim_command_;
  }
}

void Afcs::track_pilot(const AfcsInputs& in, const Guidance& g) {
  // Autopilot off: its servos follow the pilot's commands, so that engagement takes over there.
  const AfcsAircraftState& a = in.aircraft;
  pitch_loop_.engage(std::clamp(a.elevator + a.pitch_trim, -1.0, 1.0), pitch_command_rad_ - a.pitch_rad,
                     g.pitch_attitude_rate_radps, g.schedule);
  roll_loop_.engage(a.aileron, bank_command_rad_ - a.roll_rad, g.bank_rate_radps, g.schedule);
  previous_pitch_command_rad_ = pitch_command_rad_;
  previous_bank_command_rad_ = bank_command_rad_;
  yaw_.engage_coordination(a.rudder, a.sideslip_rad);
  elevator_fader_.reset(0, a.elevator);
  rudder_fader_.reset(rudder_law(logic_.state().lateral), a.rudder);
  outputs_.elevator = a.elevator;
  outputs_.aileron = a.aileron;
  outputs_.rudder = a.rudder;
  outputs_.rollout_engaged = false;
  trim_command_ = 0;
  trim_output_ = 0;
  trim_elevator_time_s_ = 0.0;
  trim_load_.reset(a.elevator);
}

void Afcs::fly_throttle(const AfcsInputs& in, const Guidance&) {
  const AfcsAircraftState& a = in.aircraft;
  const ModeState& m = logic_.state();
  if (!m.autothrottle_engaged) {
    autothrottle_.engage(a.throttle);
    outputs_.throttle = a.throttle;
    return;
  }
  const double cas_error = in.mcp.calibrated_airspeed_mps - a.calibrated_airspeed_mps;
  const double climb_error = parameters_.speed_on_elevator.go_around_climb_rate_mps - a.vertical_speed_mps;
  outputs_.throttle = autothrottle_.step(m.thrust, cas_error, climb_error, a.throttle);
}

void Afcs::fill_annunciation(const Guidance& g, double pitch_c, double bank_c) {
  const ModeState& m = logic_.state();
  outputs_.autopilot_engaged = m.autopilot_engaged;
  outputs_.autothrottle_engaged = m.autothrottle_engaged && m.thrust != ThrustMode::kArm;
  outputs_.pitch_trim_command = m.autopilot_engaged ? trim_output_ : 0;
  if (!outputs_.rollout_engaged) {
    outputs_.steering = 0.0;
    outputs_.brake_left = outputs_.brake_right = 0.0;
    outputs_.spoilers = 0.0;
  }
  outputs_.flight_director_roll_valid = m.lateral != LateralMode::kNone;
  outputs_.flight_director_roll_rad = outputs_.flight_director_roll_valid ? bank_c : 0.0;
  outputs_.flight_director_pitch_valid = m.vertical != VerticalMode::kNone;
  outputs_.flight_director_pitch_rad = outputs_.flight_director_pitch_valid ? pitch_c : 0.0;
  outputs_.fma = Fma{m.thrust, m.lateral, m.lateral_armed, m.vertical, m.vertical_armed,
                     m.autopilot_engaged, m.flight_director_on, m.autothrottle_engaged, m.alerts,
                     m.vor, m.vor_over_station};
  outputs_.flight_path_command_rad = path_command_rad_;
  outputs_.cross_track_left_m = m.vor ? g.vor.cross_track_left_m : g.cross_track_left_m;
  outputs_.glide_path_height_error_m = g.height_error_m;
}

void Afcs::hold_after_bad_sample() {
  // Nothing from the bad sample reaches a law: the commands are not applied (disengaged) and
  // keep their last values for the display.
  const ModeState& m = logic_.state();
  outputs_.autopilot_engaged = m.autopilot_engaged;
  outputs_.autothrottle_engaged = m.autothrottle_engaged && m.thrust != ThrustMode::kArm;
  outputs_.rollout_engaged = false;
  outputs_.pitch_trim_command = 0;
  outputs_.flight_director_roll_valid = false;
  outputs_.flight_director_pitch_valid = false;
  outputs_.fma = Fma{m.thrust, m.lateral, m.lateral_armed, m.vertical, m.vertical_armed,
                     m.autopilot_engaged, m.flight_director_on, m.autothrottle_engaged, m.alerts,
                     m.vor, m.vor_over_station};
}

}  // namespace fedsim::flight::afcs
