// The AFCS's translation layer in the flight federate: MCP samples checked and turned into
// selections and presses, NAV1's ILS passed on only when valid, the FMA filled from the AFCS.
#include "flight/federate/autopilot_adapter.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fedsim::flight {
namespace {

msg::McpPanel good_panel() {
  msg::McpPanel m;
  m.heading_true_rad(1.0);
  m.altitude_msl_m(900.0);
  m.vertical_speed_mps(-5.0);
  m.airspeed_cas_mps(75.0);
  m.bank_limit_rad(25.0 * units::kDegToRad);
  m.flight_director_on(true);
  m.autothrottle_armed(true);
  m.autobrake(2);
  return m;
}

TEST(CheckMcp, AcceptsAGoodPanelAndNamesTheFieldOfABadOne) {
  EXPECT_FALSE(check_mcp(good_panel()).has_value());

  msg::McpPanel nan_heading = good_panel();
  nan_heading.heading_true_rad(std::numeric_limits<double>::quiet_NaN());
  ASSERT_TRUE(check_mcp(nan_heading).has_value());
  EXPECT_NE(check_mcp(nan_heading)->find("heading_true_rad"), std::string::npos);
  msg::McpPanel huge_heading = good_panel();
  huge_heading.heading_true_rad(1e300);  // finite, but no heading
  ASSERT_TRUE(check_mcp(huge_heading).has_value());
  EXPECT_NE(check_mcp(huge_heading)->find("heading_true_rad"), std::string::npos);

  msg::McpPanel inf_altitude = good_panel();
  inf_altitude.altitude_msl_m(std::numeric_limits<double>::infinity());
  ASSERT_TRUE(check_mcp(inf_altitude).has_value());
  EXPECT_NE(check_mcp(inf_altitude)->find("altitude_msl_m"), std::string::npos);

  msg::McpPanel slow = good_panel();
  slow.airspeed_cas_mps(10.0);
  ASSERT_TRUE(check_mcp(slow).has_value());
  EXPECT_NE(check_mcp(slow)->find("airspeed_cas_mps"), std::string::npos);

  msg::McpPanel steep = good_panel();
  steep.vertical_speed_mps(-60.0);
  EXPECT_TRUE(check_mcp(steep).has_value());

  msg::McpPanel wide_bank = good_panel();
  wide_bank.bank_limit_rad(45.0 * units::kDegToRad);
  EXPECT_TRUE(check_mcp(wide_bank).has_value());

  msg::McpPanel autobrake = good_panel();
  autobrake.autobrake(5);
  ASSERT_TRUE(check_mcp(autobrake).has_value());
  EXPECT_NE(check_mcp(autobrake)->find("autobrake"), std::string::npos);
}

TEST(McpSelections, CarryThePanelsValuesInSi) {
  const afcs::McpSelections s = mcp_selections(good_panel());
  EXPECT_DOUBLE_EQ(s.heading_true_rad, 1.0);
  EXPECT_DOUBLE_EQ(s.altitude_m, 900.0);
  EXPECT_DOUBLE_EQ(s.vertical_speed_mps, -5.0);
  EXPECT_DOUBLE_EQ(s.calibrated_airspeed_mps, 75.0);
  EXPECT_TRUE(s.autothrottle_armed);
  EXPECT_EQ(s.autobrake_setting, 2);
}

TEST(McpPressTracker, TheFirstSampleIsTheBaselineAndEachIncreaseOnePress) {
  McpPressTracker tracker;
  msg::McpPanel m = good_panel();
  m.presses()[msg::MCP_APP] = 3;  // pressed before this federate joined
  EXPECT_FALSE(tracker.presses(m).approach);

  EXPECT_FALSE(tracker.presses(m).approach);  // a repeated sample presses nothing
  m.presses()[msg::MCP_APP] = 4;
  m.presses()[msg::MCP_CMD] = 1;
  afcs::McpButtons b = tracker.presses(m);
  EXPECT_TRUE(b.approach);
  EXPECT_TRUE(b.autopilot_engage);
  EXPECT_FALSE(b.altitude_hold);
  EXPECT_FALSE(b.takeoff_go_around);

  m.presses()[msg::MCP_TOGA] = 2;  // two presses in lost samples: still one press now
  b = tracker.presses(m);
  EXPECT_TRUE(b.takeoff_go_around);
  EXPECT_FALSE(b.approach);

  m.presses()[msg::MCP_TOGA] = 0;  // the I/O federate restarted: a new baseline, no press
  EXPECT_FALSE(tracker.presses(m).takeoff_go_around);
  m.presses()[msg::MCP_TOGA] = 1;
  EXPECT_TRUE(tracker.presses(m).takeoff_go_around);
}

TEST(McpPressTracker, EveryButtonIndexReachesItsButton) {
  McpPressTracker tracker;
  msg::McpPanel m;
  tracker.presses(m);
  int pressed_total = 0;
  for (std::size_t i = 0; i < msg::MCP_BUTTON_COUNT; ++i) {
    m.presses()[i] += 1;
    const afcs::McpButtons b = tracker.presses(m);
    const int count = b.autopilot_engage + b.control_wheel_steering + b.autopilot_disconnect +
                      b.autothrottle_disconnect + b.heading_select + b.wing_level + b.vor_localizer +
                      b.approach + b.altitude_hold + b.vertical_speed + b.level_change + b.speed +
                      b.thrust + b.takeoff_go_around;
    EXPECT_EQ(count, 1) << "button index " << i;
    pressed_total += count;
  }
  EXPECT_EQ(pressed_total, static_cast<int>(msg::MCP_BUTTON_COUNT));
}

msg::NavReceiver localizer_receiver() {
  msg::NavReceiver r;
  r.status(msg::SIGNAL_VALID);
  r.signal(msg::NAV_SIGNAL_LOCALIZER);
  r.course_deviation(0.3);
  r.course_true_rad(4.8);
  r.localizer_half_width_rad(0.04);
  r.localizer_distance_m(9000.0);
  r.threshold_distance_m(6000.0);
  r.glideslope_status(msg::SIGNAL_VALID);
  r.glideslope_deviation(-0.2);
  r.glide_path_angle_rad(3.0 * units::kDegToRad);
  r.glideslope_distance_m(6300.0);
  return r;
}

TEST(IlsSignals, AValidLocalizerAndGlideSlopePassTheirReadings) {
  const afcs::AfcsIlsSignals s = ils_signals_from_receiver(localizer_receiver());
  ASSERT_TRUE(s.localizer_valid);
  ASSERT_TRUE(s.glide_slope_valid);
  EXPECT_DOUBLE_EQ(s.localizer_deviation, 0.3);
  EXPECT_DOUBLE_EQ(s.localizer_half_width_rad, 0.04);
  EXPECT_DOUBLE_EQ(s.localizer_course_true_rad, 4.8);
  EXPECT_DOUBLE_EQ(s.distance_to_threshold_m, 6000.0);
  EXPECT_DOUBLE_EQ(s.glide_slope_deviation, -0.2);
  EXPECT_DOUBLE_EQ(s.glide_slope_distance_m, 6300.0);
}

TEST(IlsSignals, AFlaggedSignalPassesNoNumbers) {
  msg::NavReceiver off = localizer_receiver();
  off.status(msg::SIGNAL_RECEIVER_FAILED);
  afcs::AfcsIlsSignals s = ils_signals_from_receiver(off);
  EXPECT_FALSE(s.localizer_valid);
  EXPECT_FALSE(s.glide_slope_valid);
  EXPECT_EQ(s.localizer_deviation, 0.0);
  EXPECT_EQ(s.glide_slope_deviation, 0.0);

  msg::NavReceiver vor = localizer_receiver();
  vor.signal(msg::NAV_SIGNAL_VOR);  // a VOR is no localizer
  EXPECT_FALSE(ils_signals_from_receiver(vor).localizer_valid);

  msg::NavReceiver no_gs = localizer_receiver();
  no_gs.glideslope_status(msg::SIGNAL_OUTSIDE_COVERAGE);
  s = ils_signals_from_receiver(no_gs);
  EXPECT_TRUE(s.localizer_valid);
  EXPECT_FALSE(s.glide_slope_valid);
  EXPECT_EQ(s.glide_slope_deviation, 0.0);
}

msg::NavReceiver vor_receiver() {
  msg::NavReceiver r;
  r.status(msg::SIGNAL_VALID);
  r.signal(msg::NAV_SIGNAL_VOR);
  r.course_deviation(-0.4);
  r.course_true_rad(4.49);
  r.to_from(msg::TO_FROM_FROM);
  r.dme_status(msg::SIGNAL_VALID);
  r.dme_slant_range_m(33000.0);
  return r;
}

TEST(VorSignals, AValidVorPassesItsReadingAndItsDme) {
  const afcs::AfcsIlsSignals s = ils_signals_from_receiver(vor_receiver());
  EXPECT_FALSE(s.localizer_valid);  // a VOR is no localizer
  EXPECT_FALSE(s.glide_slope_valid);
  ASSERT_TRUE(s.vor.tuned);
  ASSERT_TRUE(s.vor.valid);
  EXPECT_FALSE(s.vor.cone_of_confusion);
  EXPECT_DOUBLE_EQ(s.vor.deviation, -0.4);
  EXPECT_DOUBLE_EQ(s.vor.course_true_rad, 4.49);
  EXPECT_NEAR(s.vor.full_scale_rad, 10.0 * units::kDegToRad, 1e-12);  // common/radio's CDI
  EXPECT_EQ(s.vor.to_from, afcs::VorToFrom::kFrom);
  EXPECT_TRUE(s.vor.dme_valid);
  EXPECT_DOUBLE_EQ(s.vor.dme_slant_range_m, 33000.0);
  msg::NavReceiver to = vor_receiver();
  to.to_from(msg::TO_FROM_TO);
  EXPECT_EQ(vor_signals_from_receiver(to).to_from, afcs::VorToFrom::kTo);
  msg::NavReceiver no_dme = vor_receiver();
  no_dme.dme_status(msg::SIGNAL_STATION_OFF_AIR);
  no_dme.dme_slant_range_m(-1.0);  // the navigation federate's "no reading"
  EXPECT_FALSE(vor_signals_from_receiver(no_dme).dme_valid);
  EXPECT_EQ(vor_signals_from_receiver(no_dme).dme_slant_range_m, 0.0);
  // A localizer is no VOR.
  EXPECT_FALSE(vor_signals_from_receiver(localizer_receiver()).tuned);
}

TEST(VorSignals, AFlaggedVorPassesNoNumbersButSaysWhetherItIsTheCone) {
  msg::NavReceiver cone = vor_receiver();
  cone.status(msg::SIGNAL_CONE_OF_CONFUSION);
  afcs::AfcsVorSignals v = vor_signals_from_receiver(cone);
  EXPECT_TRUE(v.tuned);
  EXPECT_FALSE(v.valid);
  EXPECT_TRUE(v.cone_of_confusion);
  EXPECT_EQ(v.deviation, 0.0);
  EXPECT_EQ(v.course_true_rad, 0.0);
  EXPECT_EQ(v.to_from, afcs::VorToFrom::kOff);
  msg::NavReceiver off = vor_receiver();
  off.status(msg::SIGNAL_STATION_OFF_AIR);
  v = vor_signals_from_receiver(off);
  EXPECT_TRUE(v.tuned);
  EXPECT_FALSE(v.valid);
  EXPECT_FALSE(v.cone_of_confusion);
  msg::NavReceiver failed = vor_receiver();
  failed.status(msg::SIGNAL_RECEIVER_FAILED);
  failed.signal(msg::NAV_SIGNAL_NONE);  // a failed receiver receives nothing
  EXPECT_FALSE(vor_signals_from_receiver(failed).tuned);
}

TEST(AutopilotState, CarriesTheFmaAndCommandsOfTheAfcs) {
  afcs::Afcs afcs(afcs::AfcsParameters{}, 1.0 / 60.0);
  afcs::AfcsInputs in;
  in.aircraft.calibrated_airspeed_mps = 75.0;
  in.aircraft.true_airspeed_mps = 78.0;
  in.aircraft.ground_speed_mps = 78.0;
  in.aircraft.altitude_m = 900.0;
  in.aircraft.radio_height_m = 900.0;
  in.aircraft.angle_of_attack_rad = 0.05;
  in.aircraft.throttle = 0.5;
  in.mcp = mcp_selections(good_panel());
  in.buttons.autopilot_engage = true;
  in.buttons.altitude_hold = true;
  afcs.step(in);
  in.buttons = {};
  in.aircraft.time_s = 1.0 / 60.0;
  afcs.step(in);

  msg::AutopilotState out;
  fill_autopilot_state(afcs, 3, out);
  EXPECT_TRUE(out.fma().autopilot_engaged());
  EXPECT_EQ(out.fma().pitch(), msg::FMA_PITCH_ALTITUDE_HOLD);
  EXPECT_EQ(out.transitions(), 3u);
  EXPECT_DOUBLE_EQ(out.hold_altitude_msl_m(), afcs.hold_altitude_m());
  EXPECT_DOUBLE_EQ(out.elevator(), afcs.outputs().elevator);
  EXPECT_TRUE(out.input_problem().to_string().empty());

  in.aircraft.altitude_m = std::numeric_limits<double>::quiet_NaN();  // a bad sample
  afcs.step(in);
  fill_autopilot_state(afcs, 4, out);
  EXPECT_FALSE(out.fma().autopilot_engaged());
  EXPECT_NE(out.fma().alerts() & msg::AFCS_ALERT_AP_DISCONNECT, 0u);
  EXPECT_EQ(out.input_problem().to_string(), "aircraft.altitude_m");
}

}  // namespace
}  // namespace fedsim::flight

namespace fedsim::flight {
namespace {

msg::PilotControls with_forces(float column_n, float wheel_n, float pedals_n, bool sensors = true) {
  msg::PilotControls c;
  c.pilot_force_n()[0] = column_n;
  c.pilot_force_n()[1] = wheel_n;
  c.pilot_force_n()[2] = pedals_n;
  c.discretes(sensors ? msg::DISCRETE_FORCE_SENSORS : 0u);
  return c;
}

TEST(CwsForces, DeadBandThenLinearToFullScaleThenHeld) {
  EXPECT_EQ(cws_input_from_force(0.0, 10.0, 110.0), 0.0);
  EXPECT_EQ(cws_input_from_force(9.9, 10.0, 110.0), 0.0);    // within the breakout
  EXPECT_EQ(cws_input_from_force(-10.0, 10.0, 110.0), 0.0);
  EXPECT_NEAR(cws_input_from_force(60.0, 10.0, 110.0), 0.5, 1e-12);
  EXPECT_NEAR(cws_input_from_force(-60.0, 10.0, 110.0), -0.5, 1e-12);
  EXPECT_NEAR(cws_input_from_force(110.0, 10.0, 110.0), 1.0, 1e-12);
  EXPECT_EQ(cws_input_from_force(900.0, 10.0, 110.0), 1.0);  // clamped
  EXPECT_EQ(cws_input_from_force(-900.0, 10.0, 110.0), -1.0);
  EXPECT_EQ(cws_input_from_force(std::nan(""), 10.0, 110.0), 0.0);
}

TEST(CwsForces, ColumnPullIsNoseUpWheelRightIsRightWingDown) {
  const afcs::AfcsParameters p;
  const double column_mid = 0.5 * (p.cws_breakout_force_n + p.cws_full_column_force_n);
  const double wheel_mid = 0.5 * (p.cws_breakout_force_n + p.cws_full_wheel_force_n);
  // Column + push on the topic: a pull (negative) is nose up (+ pitch input).
  CwsInputs pull = cws_inputs(with_forces(static_cast<float>(-column_mid), static_cast<float>(wheel_mid), 0), p);
  EXPECT_NEAR(pull.pitch, 0.5, 1e-6);
  EXPECT_NEAR(pull.roll, 0.5, 1e-6);
  CwsInputs push = cws_inputs(with_forces(static_cast<float>(p.cws_full_column_force_n), -300.0f, 0), p);
  EXPECT_NEAR(push.pitch, -1.0, 1e-9);
  EXPECT_EQ(push.roll, -1.0);  // beyond full scale: held at full input
  // Within the breakout: hands off.
  CwsInputs resting = cws_inputs(with_forces(5.0f, -5.0f, 40.0f), p);
  EXPECT_EQ(resting.pitch, 0.0);
  EXPECT_EQ(resting.roll, 0.0);
  // The pedals' force steers nothing.
  EXPECT_EQ(cws_inputs(with_forces(0.0f, 0.0f, 300.0f), p).roll, 0.0);
}

TEST(CwsForces, WithoutTheForceSensorsBitOrWithTheDeviceLostItIsHandsOff) {
  const afcs::AfcsParameters p;
  const CwsInputs no_sensors = cws_inputs(with_forces(-100.0f, 50.0f, 0, false), p);
  EXPECT_EQ(no_sensors.pitch, 0.0);
  EXPECT_EQ(no_sensors.roll, 0.0);
  msg::PilotControls lost = with_forces(-100.0f, 50.0f, 0);
  lost.discretes(msg::DISCRETE_FORCE_SENSORS | msg::DISCRETE_INPUTS_INVALID);
  EXPECT_EQ(cws_inputs(lost, p).pitch, 0.0);
}

TEST(CwsForces, NonFiniteOrAbsurdForcesAreRefusedByAxis) {
  EXPECT_FALSE(check_pilot_forces(with_forces(-60.0f, 30.0f, 0.0f)).has_value());
  EXPECT_FALSE(check_pilot_forces(with_forces(-2000.0f, 2000.0f, 1999.0f)).has_value());
  const auto nan_column = check_pilot_forces(with_forces(std::nanf(""), 0.0f, 0.0f));
  ASSERT_TRUE(nan_column.has_value());
  EXPECT_NE(nan_column->find("column"), std::string::npos) << *nan_column;
  const auto inf_wheel = check_pilot_forces(with_forces(0.0f, std::numeric_limits<float>::infinity(), 0.0f));
  ASSERT_TRUE(inf_wheel.has_value());
  EXPECT_NE(inf_wheel->find("wheel"), std::string::npos) << *inf_wheel;
  const auto absurd_pedals = check_pilot_forces(with_forces(0.0f, 0.0f, -2500.0f));
  ASSERT_TRUE(absurd_pedals.has_value());
  EXPECT_NE(absurd_pedals->find("pedals"), std::string::npos) << *absurd_pedals;
}

TEST(CwsForces, ParametersAreCheckedByName) {
  afcs::AfcsParameters p;
  p.cws_full_wheel_force_n = p.cws_breakout_force_n;  // no range to scale over
  try {
    p.validate();
    FAIL() << "accepted a full-scale force at the breakout";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cws_full_wheel_force_n"), std::string::npos) << e.what();
  }
  afcs::AfcsParameters q;
  q.cws_breakout_force_n = std::nan("");
  EXPECT_THROW(q.validate(), std::invalid_argument);
  EXPECT_NO_THROW(afcs::AfcsParameters{}.validate());
}

}  // namespace
}  // namespace fedsim::flight
