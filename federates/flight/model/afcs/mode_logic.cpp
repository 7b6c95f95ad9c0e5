#include "flight/model/afcs/mode_logic.hpp"

#include <utility>

namespace fedsim::flight::afcs {

namespace {
std::string_view on_off(bool on, std::string_view on_name) { return on ? on_name : "OFF"; }
std::string_view armed_name(bool armed, std::string_view mode) { return armed ? mode : ""; }
}  // namespace

std::string_view to_string(ModeTransition::Channel channel) {
  using C = ModeTransition::Channel;
  switch (channel) {
    case C::kAutopilot: return "autopilot";
    case C::kAutothrottle: return "autothrottle";
    case C::kFlightDirector: return "flight_director";
    case C::kLateral: return "lateral";
    case C::kLateralArmed: return "lateral_armed";
    case C::kVertical: return "vertical";
    case C::kVerticalArmed: return "vertical_armed";
    case C::kThrust: return "thrust";
    case C::kAlert: return "alert";
    case C::kLateralSubmode: return "lateral_submode";
  }
  return "?";
}

std::string_view alert_name(AfcsAlert alert) {
  switch (alert) {
    case kAlertNone: return "";
    case kAlertAutopilotDisconnect: return "AP DISCONNECT";
    case kAlertAutothrottleDisconnect: return "A/T DISCONNECT";
    case kAlertLocalizerInvalid: return "LOC FLAG";
    case kAlertGlideSlopeInvalid: return "G/S FLAG";
    case kAlertInputInvalid: return "INPUT INVALID";
    case kAlertEngageRefused: return "ENGAGE REFUSED";
    case kAlertAttitudeLimit: return "ATTITUDE LIMIT";
    case kAlertAutopilotFailed: return "AP FAILED";
    case kAlertAutothrottleFailed: return "A/T FAILED";
    case kAlertVorInvalid: return "VOR FLAG";
  }
  return "?";
}

ModeLogic::ModeLogic(TransitionCallback on_transition, const VorGains& vor)
    : on_transition_(std::move(on_transition)), vor_gains_(vor) {}

void ModeLogic::reset() {
  state_ = ModeState{};
  capture_from_ = VerticalMode::kNone;
  hold_present_altitude_ = false;
  autothrottle_tripped_ = false;
}

const ModeState& ModeLogic::update(double time_s, const McpButtons& buttons,
                                   const McpSelections& mcp, const ModeConditions& c) {
  time_s_ = time_s;
  hold_present_altitude_ = false;
  acknowledge(buttons);
  protect(c);
  disconnect(buttons);
  flight_director(mcp);
  autothrottle_switch(mcp, c);
  engage(buttons, c);
  if (c.inputs_valid && modes_available()) {
    go_around(buttons, c);
    if (!approach_locked()) {
      lateral_buttons(buttons, c);
      vertical_buttons(buttons, c);
    }
    automatic_lateral(c);
    automatic_vertical(c);
  }
  if (c.inputs_valid && state_.autothrottle_engaged) {
    thrust_buttons(buttons);
    automatic_thrust(c);
  }
  clear_when_unavailable();
  return state_;
}

bool ModeLogic::approach_locked() const {
  return state_.vertical == VerticalMode::kGlideSlope || state_.vertical == VerticalMode::kFlare ||
         state_.vertical == VerticalMode::kRollout;
}

// ---- Engagement ------------------------------------------------------------------------------

void ModeLogic::acknowledge(const McpButtons& buttons) {
  // A press of the disconnect switch with the autopilot already off silences its warning (the
  // FCOM's "second push"); the same for the autothrottle. The other alerts clear with it.
  if (buttons.autopilot_disconnect && !state_.autopilot_engaged) {
    for (AfcsAlert a : {kAlertAutopilotDisconnect, kAlertLocalizerInvalid, kAlertGlideSlopeInvalid,
                        kAlertInputInvalid, kAlertEngageRefused, kAlertAttitudeLimit,
                        kAlertAutopilotFailed, kAlertVorInvalid}) {
      clear_alert(a, "acknowledged");
    }
  }
  if (buttons.autothrottle_disconnect && !state_.autothrottle_engaged) {
    clear_alert(kAlertAutothrottleDisconnect, "acknowledged");
    clear_alert(kAlertAutothrottleFailed, "acknowledged");
  }
}

void ModeLogic::protect(const ModeConditions& c) {
  if (c.autopilot_failed && state_.autopilot_engaged) {
    raise(kAlertAutopilotFailed, "autopilot failed");
    raise(kAlertAutopilotDisconnect, "autopilot failed");
    set_autopilot(false, "autopilot failed");
  }
  if (c.autothrottle_failed && state_.autothrottle_engaged) {
    raise(kAlertAutothrottleFailed, "autothrottle failed");
    raise(kAlertAutothrottleDisconnect, "autothrottle failed");
    set_autothrottle(false, "autothrottle failed");
  }
  if (!c.inputs_valid) {
    if (state_.autopilot_engaged || state_.autothrottle_engaged) raise(kAlertInputInvalid, "input sample invalid");
    if (state_.autopilot_engaged) {
      raise(kAlertAutopilotDisconnect, "input sample invalid");
      set_autopilot(false, "input sample invalid");
    }
    if (state_.autothrottle_engaged) {
      raise(kAlertAutothrottleDisconnect, "input sample invalid");
      set_autothrottle(false, "input sample invalid");
    }
    return;
  }
  const bool flies_localizer = (state_.lateral == LateralMode::kLocalizer && !state_.vor) ||
                               state_.lateral == LateralMode::kAlign ||
                               state_.lateral == LateralMode::kRollout;
  if (flies_localizer && !c.localizer_valid) {
    raise(kAlertLocalizerInvalid, "localizer flagged");
    if (state_.autopilot_engaged) {
      raise(kAlertAutopilotDisconnect, "localizer flagged");
      set_autopilot(false, "localizer flagged");
    }
    set_lateral(c.on_ground ? LateralMode::kNone : LateralMode::kHeadingHold, "localizer flagged");
  }
  protect_vor(c);
  // An armed localizer, VOR or glide slope waits while flagged: automatic_*() capture only a
  // valid signal (no alert: it is not flown yet).
  if (state_.vertical == VerticalMode::kGlideSlope && !c.glide_slope_valid) {
    raise(kAlertGlideSlopeInvalid, "glide slope flagged");
    if (state_.autopilot_engaged) {
      raise(kAlertAutopilotDisconnect, "glide slope flagged");
      set_autopilot(false, "glide slope flagged");
    }
    arm_flare(false, "glide slope flagged");
    arm_rollout(false, "glide slope flagged");
    set_vertical(VerticalMode::kPitchAttitude, "glide slope flagged");
  }
  if (state_.autopilot_engaged && !c.attitude_authority_limits && !c.on_ground) {
    raise(kAlertAttitudeLimit, "attitude beyond the autopilot's authority");
    raise(kAlertAutopilotDisconnect, "attitude beyond the autopilot's authority");
    set_autopilot(false, "attitude beyond the autopilot's authority");
  }
}

void ModeLogic::protect_vor(const ModeConditions& c) {
  if (state_.lateral != LateralMode::kLocalizer || !state_.vor) return;
  if (!c.vor_tuned) {
    vor_flagged("NAV1 no longer on a VOR", c);
    return;
  }
  // Overhead, the bearing is lost (the receiver flags the cone) or swings (erratic); TO turning
  // FROM is the passage itself. The course is held through it, never the flagged signal flown.
  const bool overhead = c.vor_cone_of_confusion || (c.vor_valid && c.vor_station_passage);
  if (overhead) {
    if (!state_.vor_over_station) {
      over_station_since_s_ = time_s_;
      set_over_station(true, c.vor_cone_of_confusion ? "cone of confusion" : "station passage");
    }
    last_overhead_s_ = time_s_;
  }
  if (!c.vor_valid && !c.vor_cone_of_confusion) {
    vor_flagged("VOR flagged", c);  // failed, off the air, out of range: not the station passage
    return;
  }
  if (!state_.vor_over_station) return;
  if (!c.vor_valid && time_s_ - over_station_since_s_ > vor_gains_.max_over_station_s) {
    vor_flagged("VOR flagged beyond the station passage time", c);
    return;
  }
  if (c.vor_valid && time_s_ - last_overhead_s_ >= vor_gains_.over_station_hold_s) {
    set_over_station(false, "station passed: tracking the course");
  }
}

void ModeLogic::vor_flagged(std::string_view reason, const ModeConditions& c) {
  raise(kAlertVorInvalid, reason);
  if (state_.autopilot_engaged) {
    raise(kAlertAutopilotDisconnect, reason);
    set_autopilot(false, reason);
  }
  set_lateral(c.on_ground ? LateralMode::kNone : LateralMode::kHeadingHold, reason);
}

void ModeLogic::disconnect(const McpButtons& buttons) {
  if (buttons.autopilot_disconnect && state_.autopilot_engaged) {
    raise(kAlertAutopilotDisconnect, "disconnect switch");
    set_autopilot(false, "disconnect switch");
  }
  if (buttons.autothrottle_disconnect && state_.autothrottle_engaged) {
    raise(kAlertAutothrottleDisconnect, "disconnect switch");
    set_autothrottle(false, "disconnect switch");
  }
}

void ModeLogic::flight_director(const McpSelections& mcp) {
  if (mcp.flight_director_on != state_.flight_director_on) {
    report(ModeTransition::Channel::kFlightDirector, on_off(state_.flight_director_on, "FD"),
           on_off(mcp.flight_director_on, "FD"), "FD switch");
    state_.flight_director_on = mcp.flight_director_on;
  }
}

void ModeLogic::autothrottle_switch(const McpSelections& mcp, const ModeConditions& c) {
  if (!mcp.autothrottle_armed) {
    autothrottle_tripped_ = false;
    if (state_.autothrottle_engaged) set_autothrottle(false, "A/T ARM switch off");
  }
  // Engages when the switch is on, unless a disconnect tripped it: the switch must then be
  // cycled (the 737's arm switch is magnetically latched and released by the disconnect).
  if (mcp.autothrottle_armed && !state_.autothrottle_engaged && c.inputs_valid &&
      !c.autothrottle_failed && !autothrottle_tripped_) {
    set_autothrottle(true, "A/T ARM switch on");
  }
}

void ModeLogic::engage(const McpButtons& buttons, const ModeConditions& c) {
  if (!buttons.autopilot_engage && !buttons.control_wheel_steering) return;
  if (c.autopilot_failed) {
    raise(kAlertEngageRefused, "autopilot failed");
    return;
  }
  if (!c.inputs_valid || c.on_ground || !c.attitude_engage_limits) {
    raise(kAlertEngageRefused, c.on_ground ? "on the ground" : "engage conditions not met");
    return;
  }
  clear_alert(kAlertEngageRefused, "engaged");
  clear_alert(kAlertAutopilotDisconnect, "engaged");
  if (buttons.control_wheel_steering) {
    // CWS: attitude hold in both axes, whatever was selected (not on an approach once locked).
    if (!approach_locked()) {
      set_lateral(LateralMode::kRollAttitude, "CWS engaged");
      arm_localizer(false, "CWS engaged");
      set_vertical(VerticalMode::kPitchAttitude, "CWS engaged");
      arm_glide_slope(false, "CWS engaged");
      arm_altitude_capture(false, "CWS engaged");
    }
  } else {
    if (state_.lateral == LateralMode::kNone) {
      set_lateral(c.wings_level ? LateralMode::kHeadingHold : LateralMode::kRollAttitude,
                  "CMD engaged without a roll mode");
    }
    if (state_.vertical == VerticalMode::kNone) {
      set_vertical(VerticalMode::kPitchAttitude, "CMD engaged without a pitch mode");
    }
  }
  if (!state_.autopilot_engaged) set_autopilot(true, buttons.control_wheel_steering ? "CWS" : "CMD");
}

// ---- Buttons ---------------------------------------------------------------------------------

void ModeLogic::lateral_buttons(const McpButtons& b, const ModeConditions& c) {
  const bool on_runway_modes =
      state_.lateral == LateralMode::kAlign || state_.lateral == LateralMode::kRollout;
  if (on_runway_modes) return;
  if (b.heading_select) {
    if (state_.lateral == LateralMode::kLocalizer) arm_localizer(false, "HDG SEL");
    set_lateral(LateralMode::kHeadingSelect, "HDG SEL");
  }
  if (b.wing_level) set_lateral(LateralMode::kWingLevel, "WLV");
  if (b.vor_localizer && state_.lateral != LateralMode::kLocalizer) {
    arm_localizer(!state_.lateral_armed.localizer, "VOR LOC");
    if (!state_.lateral_armed.localizer && state_.vertical_armed.glide_slope) {
      arm_glide_slope(false, "VOR LOC (approach disarmed)");
    }
  }
  if (b.approach && c.vor_tuned) {
    // A VOR has no glide slope: APP arms VOR/LOC alone (press again: disarm).
    arm_glide_slope(false, "APP on a VOR (no glide slope)");
    if (state_.lateral != LateralMode::kLocalizer) arm_localizer(!state_.lateral_armed.localizer, "APP on a VOR");
  } else if (b.approach) {
    // First press arms what is not yet captured; a second press before G/S capture disarms.
    const bool disarm = state_.vertical_armed.glide_slope;
    arm_glide_slope(!disarm, "APP");
    if (state_.lateral != LateralMode::kLocalizer) arm_localizer(!disarm, "APP");
  }
}

void ModeLogic::vertical_buttons(const McpButtons& b, const ModeConditions& c) {
  if (b.altitude_hold) {
    arm_altitude_capture(false, "ALT HLD");
    set_vertical(VerticalMode::kAltitudeHold, "ALT HLD");
    hold_present_altitude_ = true;
  }
  if (b.vertical_speed) {
    set_vertical(VerticalMode::kVerticalSpeed, "V/S");
    arm_altitude_capture(c.selected_altitude_ahead, "V/S");
  }
  if (b.level_change && !c.altitude_captured) {
    set_vertical(VerticalMode::kLevelChange, "LVL CHG");
    arm_altitude_capture(true, "LVL CHG");
    if (state_.autothrottle_engaged) enter_climb_or_descent_thrust(c.selected_altitude_above, "LVL CHG");
  }
}

void ModeLogic::thrust_buttons(const McpButtons& b) {
  const bool speed_on_elevator = state_.vertical == VerticalMode::kLevelChange ||
                                 state_.vertical == VerticalMode::kGoAround;
  if (b.speed && !speed_on_elevator && state_.thrust != ThrustMode::kRetard) {
    set_thrust(ThrustMode::kSpeed, "SPEED");
  }
  if (b.thrust && state_.thrust != ThrustMode::kRetard) set_thrust(ThrustMode::kClimb, "N1");
}

void ModeLogic::go_around(const McpButtons& b, const ModeConditions& c) {
  if (!b.takeoff_go_around || c.on_ground) return;
  arm_localizer(false, "TO/GA");
  arm_glide_slope(false, "TO/GA");
  arm_flare(false, "TO/GA");
  arm_rollout(false, "TO/GA");
  set_lateral(LateralMode::kGoAround, "TO/GA");
  set_vertical(VerticalMode::kGoAround, "TO/GA");
  arm_altitude_capture(c.selected_altitude_above, "TO/GA");
  if (state_.autothrottle_engaged) set_thrust(ThrustMode::kGoAround, "TO/GA");
}

// ---- Automatic transitions -------------------------------------------------------------------

void ModeLogic::automatic_lateral(const ModeConditions& c) {
  if (state_.lateral_armed.localizer && c.localizer_valid && c.localizer_capture) {
    arm_localizer(false, "localizer capture point");
    set_lateral(LateralMode::kLocalizer, "localizer capture point");
  } else if (state_.lateral_armed.localizer && c.vor_tuned && c.vor_valid && c.vor_capture) {
    arm_localizer(false, "VOR capture point");
    arm_glide_slope(false, "VOR captured (no glide slope)");
    set_lateral(LateralMode::kLocalizer, "VOR capture point");
    state_.vor = true;
  }
  const bool autoland = state_.autopilot_engaged && !state_.vor &&
                        (state_.vertical == VerticalMode::kGlideSlope || state_.vertical == VerticalMode::kFlare);
  if (autoland && state_.lateral == LateralMode::kLocalizer && c.below_flare_arm_height &&
      !state_.lateral_armed.rollout) {
    arm_rollout(true, "below the flare-arm height");
  }
  if (autoland && state_.lateral == LateralMode::kLocalizer && c.below_align_height) {
    set_lateral(LateralMode::kAlign, "below the align height");
  }
  if (state_.lateral_armed.rollout && c.on_ground) {
    arm_rollout(false, "main gear touchdown");
    set_lateral(LateralMode::kRollout, "main gear touchdown");
  }
}

void ModeLogic::automatic_vertical(const ModeConditions& c) {
  VerticalArmed& armed = state_.vertical_armed;
  const bool climb_or_descent = state_.vertical == VerticalMode::kVerticalSpeed ||
                                state_.vertical == VerticalMode::kLevelChange ||
                                state_.vertical == VerticalMode::kGoAround;
  if (climb_or_descent && c.selected_altitude_changed) {
    arm_altitude_capture(c.selected_altitude_ahead, "MCP altitude changed");
  }
  if (state_.vertical == VerticalMode::kAltitudeCapture && c.selected_altitude_changed) {
    if (c.selected_altitude_ahead && capture_from_ != VerticalMode::kNone) {
      set_vertical(capture_from_, "MCP altitude changed during ALT ACQ");
      arm_altitude_capture(true, "MCP altitude changed during ALT ACQ");
    } else {
      set_vertical(VerticalMode::kAltitudeHold, "MCP altitude changed during ALT ACQ");
      hold_present_altitude_ = true;
    }
  }
  if (armed.altitude_capture && c.altitude_capture) {
    capture_from_ = state_.vertical;
    arm_altitude_capture(false, "altitude capture point");
    set_vertical(VerticalMode::kAltitudeCapture, "altitude capture point");
  }
  if (state_.vertical == VerticalMode::kAltitudeCapture && c.altitude_captured) {
    set_vertical(VerticalMode::kAltitudeHold, "within the altitude hold band");
  }
  if (armed.glide_slope && c.glide_slope_valid && c.glide_slope_capture &&
      state_.lateral == LateralMode::kLocalizer && !state_.vor) {
    arm_glide_slope(false, "glide-slope capture point");
    arm_altitude_capture(false, "glide slope captured");
    set_vertical(VerticalMode::kGlideSlope, "glide-slope capture point");
  }
  if (state_.vertical == VerticalMode::kGlideSlope && state_.autopilot_engaged &&
      c.below_flare_arm_height && !armed.flare) {
    arm_flare(true, "below the flare-arm height");
  }
  if (armed.flare && c.below_flare_height && state_.autopilot_engaged) {
    arm_flare(false, "flare height");
    set_vertical(VerticalMode::kFlare, "flare height");
  }
  if (state_.vertical == VerticalMode::kFlare && c.on_ground) {
    set_vertical(VerticalMode::kRollout, "main gear touchdown");
  }
}

void ModeLogic::automatic_thrust(const ModeConditions& c) {
  const VerticalMode v = state_.vertical;
  const bool thrust_fixed = state_.thrust == ThrustMode::kClimb || state_.thrust == ThrustMode::kIdle;
  const bool speed_mode_vertical = v == VerticalMode::kAltitudeCapture ||
                                   v == VerticalMode::kAltitudeHold ||
                                   v == VerticalMode::kVerticalSpeed ||
                                   v == VerticalMode::kGlideSlope;
  if (thrust_fixed && speed_mode_vertical) set_thrust(ThrustMode::kSpeed, "speed on thrust");
  if (state_.thrust == ThrustMode::kGoAround && speed_mode_vertical) {
    set_thrust(ThrustMode::kSpeed, "go-around level-off");
  }
  if ((v == VerticalMode::kFlare || v == VerticalMode::kRollout) && c.below_retard_height &&
      state_.thrust != ThrustMode::kRetard && state_.thrust != ThrustMode::kGoAround) {
    set_thrust(ThrustMode::kRetard, "retard height");
  }
  if (state_.thrust == ThrustMode::kRetard && c.stopped) {
    set_autothrottle(false, "stopped after landing");
  }
}

void ModeLogic::clear_when_unavailable() {
  if (modes_available()) return;
  arm_localizer(false, "AP and FD off");
  arm_rollout(false, "AP and FD off");
  arm_altitude_capture(false, "AP and FD off");
  arm_glide_slope(false, "AP and FD off");
  arm_flare(false, "AP and FD off");
  set_lateral(LateralMode::kNone, "AP and FD off");
  set_vertical(VerticalMode::kNone, "AP and FD off");
}

void ModeLogic::enter_climb_or_descent_thrust(bool climbing, std::string_view reason) {
  set_thrust(climbing ? ThrustMode::kClimb : ThrustMode::kIdle, reason);
}

// ---- State changes, each reported once -------------------------------------------------------

void ModeLogic::set_autopilot(bool engaged, std::string_view reason) {
  if (state_.autopilot_engaged == engaged) return;
  report(ModeTransition::Channel::kAutopilot, on_off(state_.autopilot_engaged, "CMD"),
         on_off(engaged, "CMD"), reason);
  state_.autopilot_engaged = engaged;
  if (!engaged) {
    // The autoland modes need the autopilot.
    if (state_.lateral == LateralMode::kAlign) set_lateral(LateralMode::kLocalizer, reason);
    if (state_.lateral == LateralMode::kRollout) set_lateral(LateralMode::kNone, reason);
    if (state_.vertical == VerticalMode::kFlare || state_.vertical == VerticalMode::kRollout) {
      set_vertical(VerticalMode::kNone, reason);
    }
    arm_flare(false, reason);
    arm_rollout(false, reason);
  }
}

void ModeLogic::set_autothrottle(bool engaged, std::string_view reason) {
  if (state_.autothrottle_engaged == engaged) return;
  report(ModeTransition::Channel::kAutothrottle, on_off(state_.autothrottle_engaged, "A/T"),
         on_off(engaged, "A/T"), reason);
  state_.autothrottle_engaged = engaged;
  if (!engaged) autothrottle_tripped_ = true;
  set_thrust(engaged ? ThrustMode::kArm : ThrustMode::kNone, reason);
}

void ModeLogic::set_lateral(LateralMode mode, std::string_view reason) {
  if (state_.lateral == mode) return;
  report(ModeTransition::Channel::kLateral, to_string(state_.lateral), to_string(mode), reason);
  state_.lateral = mode;
  // A mode entered is the localizer's until automatic_lateral() says it captured a VOR.
  set_over_station(false, reason);
  state_.vor = false;
}

void ModeLogic::set_over_station(bool over, std::string_view reason) {
  if (state_.vor_over_station == over) return;
  state_.vor_over_station = over;
  report(ModeTransition::Channel::kLateralSubmode, armed_name(!over, "OVER STATION"),
         armed_name(over, "OVER STATION"), reason);
}

void ModeLogic::set_vertical(VerticalMode mode, std::string_view reason) {
  if (state_.vertical == mode) return;
  report(ModeTransition::Channel::kVertical, to_string(state_.vertical), to_string(mode), reason);
  state_.vertical = mode;
}

void ModeLogic::set_thrust(ThrustMode mode, std::string_view reason) {
  if (state_.thrust == mode) return;
  report(ModeTransition::Channel::kThrust, to_string(state_.thrust), to_string(mode), reason);
  state_.thrust = mode;
}

void ModeLogic::arm_localizer(bool armed, std::string_view reason) {
  if (state_.lateral_armed.localizer == armed) return;
  state_.lateral_armed.localizer = armed;
  report(ModeTransition::Channel::kLateralArmed, armed_name(!armed, "VOR/LOC"),
         armed_name(armed, "VOR/LOC"), reason);
}

void ModeLogic::arm_rollout(bool armed, std::string_view reason) {
  if (state_.lateral_armed.rollout == armed) return;
  state_.lateral_armed.rollout = armed;
  report(ModeTransition::Channel::kLateralArmed, armed_name(!armed, "ROLLOUT"),
         armed_name(armed, "ROLLOUT"), reason);
}

void ModeLogic::arm_altitude_capture(bool armed, std::string_view reason) {
  if (state_.vertical_armed.altitude_capture == armed) return;
  state_.vertical_armed.altitude_capture = armed;
  report(ModeTransition::Channel::kVerticalArmed, armed_name(!armed, "ALT ACQ"),
         armed_name(armed, "ALT ACQ"), reason);
}

void ModeLogic::arm_glide_slope(bool armed, std::string_view reason) {
  if (state_.vertical_armed.glide_slope == armed) return;
  state_.vertical_armed.glide_slope = armed;
  report(ModeTransition::Channel::kVerticalArmed, armed_name(!armed, "G/S"),
         armed_name(armed, "G/S"), reason);
}

void ModeLogic::arm_flare(bool armed, std::string_view reason) {
  if (state_.vertical_armed.flare == armed) return;
  state_.vertical_armed.flare = armed;
  report(ModeTransition::Channel::kVerticalArmed, armed_name(!armed, "FLARE"),
         armed_name(armed, "FLARE"), reason);
}

void ModeLogic::raise(AfcsAlert alert, std::string_view reason) {
  if (state_.alerts & alert) return;
  state_.alerts |= alert;
  report(ModeTransition::Channel::kAlert, "", alert_name(alert), reason);
}

void ModeLogic::clear_alert(AfcsAlert alert, std::string_view reason) {
  if (!(state_.alerts & alert)) return;
  state_.alerts &= ~static_cast<std::uint32_t>(alert);
  report(ModeTransition::Channel::kAlert, alert_name(alert), "", reason);
}

void ModeLogic::report(ModeTransition::Channel channel, std::string_view from, std::string_view to,
                       std::string_view reason) {
  if (on_transition_) on_transition_(ModeTransition{time_s_, channel, from, to, reason});
}

}  // namespace fedsim::flight::afcs
