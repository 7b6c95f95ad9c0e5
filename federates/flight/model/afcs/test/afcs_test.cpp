// The Afcs class on synthetic frames (no flight model): parameter and input checks,
// disengagement on a bad sample, bumpless engagement, faded mode changes, the FD bars.
#include "flight/model/afcs/afcs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::flight::afcs {
namespace {

constexpr double kDeg = units::kDegToRad;

AfcsInputs cruise_frame(double t) {
  AfcsInputs in;
  AfcsAircraftState& a = in.aircraft;
  a.time_s = t;
  a.pitch_rad = 3.0 * kDeg;
  a.heading_true_rad = 1.0;
  a.track_true_rad = 1.0;
  a.calibrated_airspeed_mps = 75.0;
  a.true_airspeed_mps = 78.0;
  a.ground_speed_mps = 78.0;
  a.altitude_m = 900.0;
  a.radio_height_m = 895.0;
  a.elevator = -0.4;
  a.aileron = 0.02;
  a.rudder = -0.01;
  a.throttle = 0.55;
  in.mcp.altitude_m = 900.0;
  in.mcp.calibrated_airspeed_mps = 75.0;
  in.mcp.heading_true_rad = 1.0;
  return in;
}

TEST(Afcs, ParametersAreCheckedByName) {
  AfcsParameters p;
  p.pitch.attitude_gain_per_rad = -1.0;
  try {
    Afcs afcs(p, 0.02);
    FAIL() << "accepted a negative gain";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pitch.attitude_gain_per_rad"), std::string::npos) << e.what();
  }
  AfcsParameters q;
  q.autoland.flare_height_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Afcs(q, 0.02), std::invalid_argument);
  EXPECT_THROW(Afcs(AfcsParameters{}, 0.0), std::invalid_argument);
  EXPECT_NO_THROW(Afcs(AfcsParameters{}, 0.02));
}

TEST(Afcs, EngagementIsBumpless) {
  Afcs afcs(AfcsParameters{}, 0.02);
  AfcsInputs in = cruise_frame(0.0);
  in.buttons.autopilot_engage = true;
  const AfcsOutputs& out = afcs.step(in);
  ASSERT_TRUE(out.autopilot_engaged);
  EXPECT_NEAR(out.elevator, in.aircraft.elevator, 1e-9);
  EXPECT_NEAR(out.aileron, in.aircraft.aileron, 1e-9);
  EXPECT_NEAR(out.rudder, in.aircraft.rudder, 1e-9);
  EXPECT_EQ(out.fma.lateral, LateralMode::kHeadingHold);
  EXPECT_EQ(out.fma.vertical, VerticalMode::kPitchAttitude);
}

TEST(Afcs, ABadSampleDisengagesAndReachesNoLaw) {
  std::vector<ModeTransition> log;
  Afcs afcs(AfcsParameters{}, 0.02, [&](const ModeTransition& t) { log.push_back(t); });
  AfcsInputs in = cruise_frame(0.0);
  in.buttons.autopilot_engage = true;
  afcs.step(in);
  const double elevator = afcs.outputs().elevator;
  in = cruise_frame(0.02);
  in.aircraft.calibrated_airspeed_mps = std::numeric_limits<double>::quiet_NaN();
  const AfcsOutputs& out = afcs.step(in);
  EXPECT_FALSE(out.autopilot_engaged);
  EXPECT_TRUE(out.fma.alerts & kAlertInputInvalid);
  EXPECT_TRUE(out.fma.alerts & kAlertAutopilotDisconnect);
  EXPECT_EQ(afcs.last_input_problem(), "aircraft.calibrated_airspeed_mps");
  EXPECT_EQ(out.elevator, elevator);  // held, never NaN
  ASSERT_FALSE(log.empty());
  EXPECT_EQ(log.back().to, "OFF");
  // A flagged ILS signal's numbers are not checked (they are not used).
  in = cruise_frame(0.04);
  in.ils.localizer_valid = false;
  in.ils.localizer_deviation = std::numeric_limits<double>::quiet_NaN();
  afcs.step(in);
  EXPECT_TRUE(afcs.last_input_problem().empty());
  in.ils.localizer_valid = true;
  afcs.step(in);
  EXPECT_EQ(afcs.last_input_problem(), "ils.localizer_deviation");
}

TEST(Afcs, VorInputsAreCheckedOnlyWhenValidAndNamed) {
  Afcs afcs(AfcsParameters{}, 0.02);
  AfcsInputs in = cruise_frame(0.0);
  in.ils.vor.tuned = true;
  in.ils.vor.valid = false;  // flagged: its numbers are not used, nor checked
  in.ils.vor.deviation = std::numeric_limits<double>::quiet_NaN();
  afcs.step(in);
  EXPECT_TRUE(afcs.last_input_problem().empty());
  const auto problem = [&](auto&& spoil) {
    AfcsInputs bad = cruise_frame(0.02);
    bad.ils.vor.tuned = bad.ils.vor.valid = true;
    bad.ils.vor.to_from = VorToFrom::kFrom;
    spoil(bad.ils.vor);
    afcs.step(bad);
    return std::string(afcs.last_input_problem());
  };
  EXPECT_EQ(problem([](AfcsVorSignals&) {}), "");
  EXPECT_EQ(problem([](AfcsVorSignals& v) { v.deviation = 1.5; }), "ils.vor.deviation");
  EXPECT_EQ(problem([](AfcsVorSignals& v) { v.full_scale_rad = 0.0; }), "ils.vor.full_scale_rad");
  EXPECT_EQ(problem([](AfcsVorSignals& v) { v.course_true_rad = INFINITY; }), "ils.vor.course_true_rad");
  EXPECT_EQ(problem([](AfcsVorSignals& v) { v.tuned = false; }), "ils.vor.tuned");
  EXPECT_EQ(problem([](AfcsVorSignals& v) { v.to_from = static_cast<VorToFrom>(7); }), "ils.vor.to_from");
  EXPECT_EQ(problem([](AfcsVorSignals& v) {
              v.dme_valid = true;
              v.dme_slant_range_m = -1.0;
            }),
            "ils.vor.dme_slant_range_m");
  AfcsParameters p;
  p.vor.nominal_distance_m = 1.0;  // below the schedule's minimum
  EXPECT_THROW(Afcs(p, 0.02), std::invalid_argument);
}

TEST(Afcs, ModeChangesAreFaded) {
  // Wings level in HDG HOLD, then HDG SEL 90 deg to the right: the bank command moves at the
  // bank-rate limit, the pitch command does not step when ALT HLD replaces CWS P.
  AfcsParameters p;
  Afcs afcs(p, 0.02);
  AfcsInputs in = cruise_frame(0.0);
  in.buttons.autopilot_engage = true;
  afcs.step(in);
  in = cruise_frame(0.02);
  in.buttons.altitude_hold = true;
  in.buttons.heading_select = true;
  in.mcp.heading_true_rad = 1.0 + 90.0 * kDeg;
  in.mcp.altitude_m = 1500.0;  // ALT HLD holds the present altitude, not this
  double previous_bank = afcs.outputs().flight_director_roll_rad;
  double previous_pitch = afcs.outputs().flight_director_pitch_rad;
  for (int i = 0; i < 100; ++i) {
    const AfcsOutputs& out = afcs.step(in);
    EXPECT_LE(std::abs(out.flight_director_roll_rad - previous_bank), p.roll.bank_rate_limit_radps * 0.02 + 1e-12);
    EXPECT_LT(std::abs(out.flight_director_pitch_rad - previous_pitch), 0.05 * kDeg);
    previous_bank = out.flight_director_roll_rad;
    previous_pitch = out.flight_director_pitch_rad;
    in = cruise_frame(0.04 + 0.02 * i);
    in.mcp.heading_true_rad = 1.0 + 90.0 * kDeg;
    in.mcp.altitude_m = 1500.0;
  }
  EXPECT_EQ(afcs.modes().lateral, LateralMode::kHeadingSelect);
  EXPECT_EQ(afcs.modes().vertical, VerticalMode::kAltitudeHold);
  EXPECT_DOUBLE_EQ(afcs.hold_altitude_m(), 900.0);
  EXPECT_GT(previous_bank, 9.0 * kDeg);  // rolling right at 5 deg/s for 2 s
}

TEST(Afcs, FlightDirectorBarsWithoutTheAutopilot) {
  Afcs afcs(AfcsParameters{}, 0.02);
  AfcsInputs in = cruise_frame(0.0);
  in.mcp.flight_director_on = true;
  in.buttons.heading_select = true;
  in.mcp.heading_true_rad = 1.3;
  const AfcsOutputs& out = afcs.step(in);
  EXPECT_FALSE(out.autopilot_engaged);
  EXPECT_TRUE(out.flight_director_roll_valid);
  EXPECT_EQ(out.elevator, in.aircraft.elevator);  // servos follow the pilot
  // FD off as well: no modes, no bars.
  in.buttons = McpButtons{};
  in.mcp.flight_director_on = false;
  const AfcsOutputs& off = afcs.step(in);
  EXPECT_FALSE(off.flight_director_roll_valid);
  EXPECT_EQ(off.fma.lateral, LateralMode::kNone);
}

}  // namespace
}  // namespace fedsim::flight::afcs
