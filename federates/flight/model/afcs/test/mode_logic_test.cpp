// The AFCS mode logic on its own: engagement, arming and capture, the approach lock after G/S
// capture, the protections against flagged signals, and the transition report.
#include "flight/model/afcs/mode_logic.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fedsim::flight::afcs {
namespace {

struct Recorder {
  std::vector<ModeTransition> log;
  ModeLogic logic{[this](const ModeTransition& t) { log.push_back(t); }};
  McpSelections mcp;
  ModeConditions airborne() const {
    ModeConditions c;
    c.localizer_valid = true;
    c.glide_slope_valid = true;
    c.wings_level = true;
    return c;
  }
  const ModeState& press(bool McpButtons::*which, ModeConditions c) {
    McpButtons b;
    b.*which = true;
    return logic.update(0.0, b, mcp, c);
  }
  const ModeState& frame(ModeConditions c) { return logic.update(0.0, McpButtons{}, mcp, c); }
  bool logged(ModeTransition::Channel channel, std::string_view to) const {
    for (const auto& t : log) if (t.channel == channel && t.to == to) return true;
    return false;
  }
};

TEST(ModeLogic, CmdEngagesInHeadingHoldAndPitchAttitudeWhenWingsLevel) {
  Recorder r;
  const ModeState& s = r.press(&McpButtons::autopilot_engage, r.airborne());
  EXPECT_TRUE(s.autopilot_engaged);
  EXPECT_EQ(s.lateral, LateralMode::kHeadingHold);
  EXPECT_EQ(s.vertical, VerticalMode::kPitchAttitude);
  EXPECT_TRUE(r.logged(ModeTransition::Channel::kAutopilot, "CMD"));
}

TEST(ModeLogic, CmdEngagesInRollAttitudeWhenBanked) {
  Recorder r;
  ModeConditions c = r.airborne();
  c.wings_level = false;
  EXPECT_EQ(r.press(&McpButtons::autopilot_engage, c).lateral, LateralMode::kRollAttitude);
}

TEST(ModeLogic, EngagementIsRefusedOnTheGroundWithAnAlert) {
  Recorder r;
  ModeConditions c = r.airborne();
  c.on_ground = true;
  const ModeState& s = r.press(&McpButtons::autopilot_engage, c);
  EXPECT_FALSE(s.autopilot_engaged);
  EXPECT_TRUE(s.alerts & kAlertEngageRefused);
  // Negative control: airborne it engages and clears the alert.
  const ModeState& s2 = r.press(&McpButtons::autopilot_engage, r.airborne());
  EXPECT_TRUE(s2.autopilot_engaged);
  EXPECT_FALSE(s2.alerts & kAlertEngageRefused);
}

TEST(ModeLogic, DisconnectLatchesTheWarningUntilTheSecondPress) {
  Recorder r;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  const ModeState& off = r.press(&McpButtons::autopilot_disconnect, r.airborne());
  EXPECT_FALSE(off.autopilot_engaged);
  EXPECT_TRUE(off.alerts & kAlertAutopilotDisconnect);
  EXPECT_TRUE(r.frame(r.airborne()).alerts & kAlertAutopilotDisconnect);  // still latched
  EXPECT_FALSE(r.press(&McpButtons::autopilot_disconnect, r.airborne()).alerts & kAlertAutopilotDisconnect);
}

TEST(ModeLogic, ApproachArmsThenCapturesLocalizerBeforeGlideSlope) {
  Recorder r;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  const ModeState& armed = r.press(&McpButtons::approach, r.airborne());
  EXPECT_TRUE(armed.lateral_armed.localizer);
  EXPECT_TRUE(armed.vertical_armed.glide_slope);
  // The glide-slope capture point first: it waits for the localizer.
  ModeConditions c = r.airborne();
  c.glide_slope_capture = true;
  EXPECT_EQ(r.frame(c).vertical, VerticalMode::kPitchAttitude);
  c.localizer_capture = true;
  const ModeState& both = r.frame(c);
  EXPECT_EQ(both.lateral, LateralMode::kLocalizer);
  EXPECT_EQ(both.vertical, VerticalMode::kGlideSlope);
  EXPECT_FALSE(both.lateral_armed.localizer);
  EXPECT_FALSE(both.vertical_armed.glide_slope);
}

TEST(ModeLogic, AFlaggedLocalizerIsNeverCaptured) {
  Recorder r;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  r.press(&McpButtons::vor_localizer, r.airborne());
  ModeConditions c = r.airborne();
  c.localizer_capture = true;
  c.localizer_valid = false;
  const ModeState& s = r.frame(c);
  EXPECT_EQ(s.lateral, LateralMode::kHeadingHold);
  EXPECT_TRUE(s.lateral_armed.localizer);
  c.localizer_valid = true;  // negative control
  EXPECT_EQ(r.frame(c).lateral, LateralMode::kLocalizer);
}

TEST(ModeLogic, FlaggedSignalsWhileFlownDisengageWithAnAlert) {
  Recorder r;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  r.press(&McpButtons::approach, r.airborne());
  ModeConditions c = r.airborne();
  c.localizer_capture = c.glide_slope_capture = true;
  r.frame(c);
  c.glide_slope_valid = false;
  const ModeState& gs_lost = r.frame(c);
  EXPECT_FALSE(gs_lost.autopilot_engaged);
  EXPECT_TRUE(gs_lost.alerts & kAlertGlideSlopeInvalid);
  EXPECT_TRUE(gs_lost.alerts & kAlertAutopilotDisconnect);
  EXPECT_NE(gs_lost.vertical, VerticalMode::kGlideSlope);  // the flight director drops it too

  Recorder l;
  l.press(&McpButtons::autopilot_engage, l.airborne());
  l.press(&McpButtons::vor_localizer, l.airborne());
  ModeConditions lc = l.airborne();
  lc.localizer_capture = true;
  l.frame(lc);
  lc.localizer_valid = false;
  const ModeState& loc_lost = l.frame(lc);
  EXPECT_FALSE(loc_lost.autopilot_engaged);
  EXPECT_TRUE(loc_lost.alerts & kAlertLocalizerInvalid);
  EXPECT_EQ(loc_lost.lateral, LateralMode::kHeadingHold);
}

TEST(ModeLogic, AnInvalidInputSampleDisengagesAutopilotAndAutothrottle) {
  Recorder r;
  r.mcp.autothrottle_armed = true;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  EXPECT_TRUE(r.logic.state().autothrottle_engaged);
  ModeConditions bad;
  bad.inputs_valid = false;
  const ModeState& s = r.frame(bad);
  EXPECT_FALSE(s.autopilot_engaged);
  EXPECT_FALSE(s.autothrottle_engaged);
  EXPECT_TRUE(s.alerts & kAlertInputInvalid);
  // The A/T does not re-engage until its switch is cycled.
  EXPECT_FALSE(r.frame(r.airborne()).autothrottle_engaged);
  r.mcp.autothrottle_armed = false;
  r.frame(r.airborne());
  r.mcp.autothrottle_armed = true;
  EXPECT_TRUE(r.frame(r.airborne()).autothrottle_engaged);
}

TEST(ModeLogic, AFailedAutopilotDisengagesRefusesCmdAndEngagesOnceRestored) {
  Recorder r;
  ASSERT_TRUE(r.press(&McpButtons::autopilot_engage, r.airborne()).autopilot_engaged);
  ModeConditions failed = r.airborne();
  failed.autopilot_failed = true;
  const ModeState& s = r.frame(failed);
  EXPECT_FALSE(s.autopilot_engaged);
  EXPECT_TRUE(s.alerts & kAlertAutopilotFailed);
  EXPECT_TRUE(s.alerts & kAlertAutopilotDisconnect);
  EXPECT_TRUE(r.logged(ModeTransition::Channel::kAlert, "AP FAILED"));
  // While failed, CMD is refused with an alert.
  EXPECT_FALSE(r.press(&McpButtons::autopilot_engage, failed).autopilot_engaged);
  EXPECT_TRUE(r.logic.state().alerts & kAlertEngageRefused);
  // Restored: CMD engages again (the negative control of the refusal).
  EXPECT_TRUE(r.press(&McpButtons::autopilot_engage, r.airborne()).autopilot_engaged);
}

TEST(ModeLogic, AFailedAutothrottleDisengagesAndStaysOffUntilRestoredAndCycled) {
  Recorder r;
  r.mcp.autothrottle_armed = true;
  ASSERT_TRUE(r.frame(r.airborne()).autothrottle_engaged);
  ModeConditions failed = r.airborne();
  failed.autothrottle_failed = true;
  EXPECT_FALSE(r.frame(failed).autothrottle_engaged);
  EXPECT_TRUE(r.logic.state().alerts & kAlertAutothrottleFailed);
  EXPECT_FALSE(r.frame(failed).autothrottle_engaged);
  // Restored, the arm switch must be cycled (the disconnect released its latch).
  EXPECT_FALSE(r.frame(r.airborne()).autothrottle_engaged);
  r.mcp.autothrottle_armed = false;
  r.frame(r.airborne());
  r.mcp.autothrottle_armed = true;
  EXPECT_TRUE(r.frame(r.airborne()).autothrottle_engaged);
}

TEST(ModeLogic, AfterGlideSlopeCaptureOnlyGoAroundLeavesTheApproach) {
  Recorder r;
  r.mcp.autothrottle_armed = true;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  r.press(&McpButtons::approach, r.airborne());
  ModeConditions c = r.airborne();
  c.localizer_capture = c.glide_slope_capture = true;
  r.frame(c);
  for (bool McpButtons::*b : {&McpButtons::heading_select, &McpButtons::altitude_hold, &McpButtons::vertical_speed,
                              &McpButtons::level_change, &McpButtons::vor_localizer, &McpButtons::wing_level}) {
    const ModeState& s = r.press(b, c);
    EXPECT_EQ(s.lateral, LateralMode::kLocalizer);
    EXPECT_EQ(s.vertical, VerticalMode::kGlideSlope);
  }
  // A new MCP altitude arms nothing (no climb or descent to it on the glide slope).
  ModeConditions changed = c;
  changed.selected_altitude_changed = true;
  changed.selected_altitude_ahead = true;
  changed.altitude_capture = true;
  const ModeState& s = r.frame(changed);
  EXPECT_FALSE(s.vertical_armed.altitude_capture);
  EXPECT_EQ(s.vertical, VerticalMode::kGlideSlope);
  // TO/GA does.
  changed.selected_altitude_above = true;
  changed.altitude_capture = false;
  const ModeState& ga = r.press(&McpButtons::takeoff_go_around, changed);
  EXPECT_EQ(ga.lateral, LateralMode::kGoAround);
  EXPECT_EQ(ga.vertical, VerticalMode::kGoAround);
  EXPECT_EQ(ga.thrust, ThrustMode::kGoAround);
  EXPECT_TRUE(ga.vertical_armed.altitude_capture);
}

TEST(ModeLogic, AutolandSequenceFromGlideSlopeToRollout) {
  Recorder r;
  r.mcp.autothrottle_armed = true;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  r.press(&McpButtons::speed, r.airborne());
  r.press(&McpButtons::approach, r.airborne());
  ModeConditions c = r.airborne();
  c.localizer_capture = c.glide_slope_capture = true;
  r.frame(c);
  c.below_flare_arm_height = true;
  EXPECT_TRUE(r.frame(c).vertical_armed.flare);
  EXPECT_TRUE(r.logic.state().lateral_armed.rollout);
  c.below_align_height = true;
  EXPECT_EQ(r.frame(c).lateral, LateralMode::kAlign);
  c.below_flare_height = true;
  EXPECT_EQ(r.frame(c).vertical, VerticalMode::kFlare);
  EXPECT_EQ(r.logic.state().thrust, ThrustMode::kSpeed);
  c.below_retard_height = true;
  EXPECT_EQ(r.frame(c).thrust, ThrustMode::kRetard);
  c.on_ground = true;
  const ModeState& ground = r.frame(c);
  EXPECT_EQ(ground.lateral, LateralMode::kRollout);
  EXPECT_EQ(ground.vertical, VerticalMode::kRollout);
  c.stopped = true;
  EXPECT_FALSE(r.frame(c).autothrottle_engaged);
  EXPECT_TRUE(r.logic.state().autopilot_engaged);
}

TEST(ModeLogic, NoFlightDirectorAutoland) {
  // FD only (AP off): G/S is flown on the bars, FLARE is never armed.
  Recorder r;
  r.mcp.flight_director_on = true;
  r.frame(r.airborne());
  r.press(&McpButtons::approach, r.airborne());
  ModeConditions c = r.airborne();
  c.localizer_capture = c.glide_slope_capture = true;
  r.frame(c);
  EXPECT_EQ(r.logic.state().vertical, VerticalMode::kGlideSlope);
  c.below_flare_arm_height = c.below_align_height = c.below_flare_height = true;
  const ModeState& s = r.frame(c);
  EXPECT_FALSE(s.vertical_armed.flare);
  EXPECT_EQ(s.vertical, VerticalMode::kGlideSlope);
  EXPECT_EQ(s.lateral, LateralMode::kLocalizer);
}

TEST(ModeLogic, NewAltitudeDuringCaptureReturnsToVerticalSpeed) {
  Recorder r;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  ModeConditions c = r.airborne();
  c.selected_altitude_ahead = true;
  r.press(&McpButtons::vertical_speed, c);
  EXPECT_TRUE(r.logic.state().vertical_armed.altitude_capture);
  c.altitude_capture = true;
  EXPECT_EQ(r.frame(c).vertical, VerticalMode::kAltitudeCapture);
  c.altitude_capture = false;
  c.selected_altitude_changed = true;
  const ModeState& back = r.frame(c);
  EXPECT_EQ(back.vertical, VerticalMode::kVerticalSpeed);
  EXPECT_TRUE(back.vertical_armed.altitude_capture);
  // A new altitude behind the aircraft: level off where it is.
  c.selected_altitude_changed = false;
  c.altitude_capture = true;
  r.frame(c);
  c.altitude_capture = false;
  c.selected_altitude_changed = true;
  c.selected_altitude_ahead = false;
  EXPECT_EQ(r.frame(c).vertical, VerticalMode::kAltitudeHold);
  EXPECT_TRUE(r.logic.altitude_hold_at_present_altitude());
}

TEST(ModeLogic, EveryChangeIsReportedOnceInOrder) {
  Recorder r;
  r.press(&McpButtons::autopilot_engage, r.airborne());
  r.press(&McpButtons::autopilot_engage, r.airborne());  // again: nothing new
  r.press(&McpButtons::vor_localizer, r.airborne());
  ModeConditions c = r.airborne();
  c.localizer_capture = true;
  r.frame(c);
  r.frame(c);
  std::vector<std::string> seen;
  for (const auto& t : r.log) seen.push_back(std::string(to_string(t.channel)) + ":" + std::string(t.from) + ">" + std::string(t.to));
  const std::vector<std::string> expected = {
      "flight_director:OFF>FD", "lateral:>HDG HOLD", "vertical:>CWS P", "autopilot:OFF>CMD",
      "lateral_armed:>VOR/LOC", "lateral_armed:VOR/LOC>", "lateral:HDG HOLD>VOR/LOC"};
  EXPECT_EQ(seen, expected);
  for (const auto& t : r.log) EXPECT_FALSE(t.reason.empty());
}

// ---- VOR/LOC on a VOR ------------------------------------------------------------------------

/// Engaged, NAV1 on a valid VOR, VOR/LOC armed and captured at t = 1 s; frames then at `t`.
struct VorRecorder {
  std::vector<ModeTransition> log;
  ModeLogic logic{[this](const ModeTransition& t) { log.push_back(t); }};
  McpSelections mcp;
  static ModeConditions on_vor() {
    ModeConditions c;
    c.wings_level = true;
    c.vor_tuned = c.vor_valid = true;
    return c;
  }
  const ModeState& at(double t, const ModeConditions& c, McpButtons b = {}) { return logic.update(t, b, mcp, c); }
  void capture() {
    McpButtons cmd;
    cmd.autopilot_engage = true;
    at(0.0, on_vor(), cmd);
    McpButtons vor_loc;
    vor_loc.vor_localizer = true;
    at(0.5, on_vor(), vor_loc);
    ModeConditions c = on_vor();
    c.vor_capture = true;
    at(1.0, c);
  }
};

TEST(ModeLogic, VorLocCapturesOnlyAValidVorAndApproachArmsNoGlideSlopeOnIt) {
  VorRecorder r;
  McpButtons cmd, app;
  cmd.autopilot_engage = true;
  app.approach = true;
  r.at(0.0, VorRecorder::on_vor(), cmd);
  const ModeState& armed = r.at(0.1, VorRecorder::on_vor(), app);
  EXPECT_TRUE(armed.lateral_armed.localizer);
  EXPECT_FALSE(armed.vertical_armed.glide_slope);  // a VOR has none
  ModeConditions c = VorRecorder::on_vor();
  c.vor_capture = true;
  c.vor_valid = false;
  EXPECT_EQ(r.at(0.2, c).lateral, LateralMode::kHeadingHold);  // flagged: never captured
  EXPECT_EQ(r.logic.state().alerts, kAlertNone);                 // ... nor alerted (not flown)
  c.vor_valid = true;  // negative control
  const ModeState& captured = r.at(0.3, c);
  EXPECT_EQ(captured.lateral, LateralMode::kLocalizer);
  EXPECT_TRUE(captured.vor);
  EXPECT_FALSE(captured.lateral_armed.localizer);
  // A glide slope (there is none on a VOR: defence in depth) is not captured on it.
  VorRecorder g;
  g.at(0.0, VorRecorder::on_vor(), cmd);
  ModeConditions loc = VorRecorder::on_vor();
  loc.vor_tuned = loc.vor_valid = false;
  loc.localizer_valid = loc.glide_slope_valid = true;
  g.at(0.1, loc, app);  // APP on a localizer: G/S armed
  ModeConditions vor = VorRecorder::on_vor();
  vor.vor_capture = vor.glide_slope_valid = vor.glide_slope_capture = true;
  const ModeState& s = g.at(0.2, vor);
  EXPECT_TRUE(s.vor);
  EXPECT_FALSE(s.vertical_armed.glide_slope);
  EXPECT_NE(s.vertical, VerticalMode::kGlideSlope);
}

TEST(ModeLogic, OverTheStationTheVorCourseIsHeldThroughTheConeThenTrackedAgain) {
  const VorGains gains;
  VorRecorder r;
  r.capture();
  ModeConditions cone = VorRecorder::on_vor();
  cone.vor_valid = false;
  cone.vor_cone_of_confusion = true;
  for (double t = 10.0; t < 30.0; t += 0.5) {
    const ModeState& s = r.at(t, cone);
    ASSERT_TRUE(s.vor_over_station) << t;
    ASSERT_TRUE(s.autopilot_engaged) << t;
    ASSERT_EQ(s.alerts, kAlertNone) << t;
  }
  // Valid again: the course is still held for the hold time after the last cue (t = 29.5 s).
  EXPECT_TRUE(r.at(30.0, VorRecorder::on_vor()).vor_over_station);
  EXPECT_TRUE(r.at(29.5 + gains.over_station_hold_s - 0.1, VorRecorder::on_vor()).vor_over_station);
  const ModeState& s = r.at(29.5 + gains.over_station_hold_s, VorRecorder::on_vor());
  EXPECT_FALSE(s.vor_over_station);
  EXPECT_EQ(s.lateral, LateralMode::kLocalizer);
  EXPECT_TRUE(s.vor);
  std::vector<std::string> seen;
  for (const auto& t : r.log) {
    if (t.channel == ModeTransition::Channel::kLateralSubmode) seen.push_back(std::string(t.from) + ">" + std::string(t.to));
  }
  EXPECT_EQ(seen, (std::vector<std::string>{">OVER STATION", "OVER STATION>"}));
  // An erratic deviation (or TO turning FROM) is a cue as well.
  ModeConditions erratic = VorRecorder::on_vor();
  erratic.vor_station_passage = true;
  EXPECT_TRUE(r.at(100.0, erratic).vor_over_station);
}

TEST(ModeLogic, AFlaggedVorOtherThanTheConeDisengagesWithAnAlert) {
  ModeConditions failed = VorRecorder::on_vor();
  failed.vor_valid = false;  // receiver failed, off the air, out of range: not the cone
  ModeConditions cone = failed;
  cone.vor_cone_of_confusion = true;
  ModeConditions retuned = VorRecorder::on_vor();
  retuned.vor_tuned = retuned.vor_valid = false;
  const auto expect_disengaged = [](const ModeState& s) {
    EXPECT_FALSE(s.autopilot_engaged);
    EXPECT_TRUE(s.alerts & kAlertVorInvalid);
    EXPECT_TRUE(s.alerts & kAlertAutopilotDisconnect);
    EXPECT_EQ(s.lateral, LateralMode::kHeadingHold);
    EXPECT_FALSE(s.vor);
    EXPECT_FALSE(s.vor_over_station);
  };
  {  // tracking
    VorRecorder r;
    r.capture();
    expect_disengaged(r.at(5.0, failed));
  }
  {  // retuned to a localizer (or nothing)
    VorRecorder r;
    r.capture();
    expect_disengaged(r.at(5.0, retuned));
  }
  {  // over the station, a failure is not waited out
    VorRecorder r;
    r.capture();
    EXPECT_TRUE(r.at(5.0, cone).vor_over_station);
    expect_disengaged(r.at(6.0, failed));
  }
  {  // a cone flag that outlasts any station passage
    const VorGains gains;
    VorRecorder r;
    r.capture();
    r.at(5.0, cone);
    EXPECT_TRUE(r.at(5.0 + gains.max_over_station_s, cone).autopilot_engaged);
    expect_disengaged(r.at(5.1 + gains.max_over_station_s, cone));
  }
  {  // the second disconnect press acknowledges it
    VorRecorder r;
    r.capture();
    r.at(5.0, failed);
    McpButtons off;
    off.autopilot_disconnect = true;
    EXPECT_EQ(r.at(6.0, failed, off).alerts, kAlertNone);
  }
}

}  // namespace
}  // namespace fedsim::flight::afcs
