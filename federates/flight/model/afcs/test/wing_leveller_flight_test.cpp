// The C172's wing leveller (pack flight_controls.wing_leveller, JSBSim c172ap.xml "Roll wing
// leveler") flying the aircraft: from 20 deg of bank it levels the wings and holds them; off,
// the bank stays (the C172's spiral mode is slow); on the ground it does nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "flight/model/scenario/test/flight_test_support.hpp"

namespace fedsim::flight {
namespace {

using namespace flight::testing;

struct Banked {
  std::unique_ptr<AircraftModel> model;
  AircraftControls trim;
};

/// The C172 trimmed in cruise, then rolled right with the aileron to about 20 deg of bank and
/// the aileron centred again (the trim's controls), the leveller off.
Banked rolled_to_20_degrees() {
  Banked b{make_model("c172.yaml"), {}};
  const TrimResult trim = Trim(*b.model).solve(cruise("c172.yaml"));
  EXPECT_TRUE(trim.converged) << trim.reason;
  b.trim = trim.controls;
  b.model->set_wing_leveller_engaged(false);
  AircraftControls roll = trim.controls;
  roll.aileron += 0.3;
  b.model->set_controls(roll);
  for (int i = 0; i < 1000 && b.model->outputs().euler.phi_rad < 20.0 * kDeg; ++i) b.model->step(0.02);
  b.model->set_controls(trim.controls);
  EXPECT_NEAR(b.model->outputs().euler.phi_rad, 20.0 * kDeg, 2.0 * kDeg);
  return b;
}

/// Flies `seconds` at 50 Hz; returns the largest |bank| over the last `tail_s` seconds.
double fly(AircraftModel& model, double seconds, double tail_s) {
  double worst = 0.0;
  const int steps = static_cast<int>(std::lround(seconds / 0.02));
  for (int i = 0; i < steps; ++i) {
    model.step(0.02);
    if ((steps - i) * 0.02 <= tail_s) worst = std::max(worst, std::abs(model.outputs().euler.phi_rad));
  }
  return worst;
}

TEST(WingLevellerC172, LevelsTheWingsFrom20DegreesOfBankAndHoldsThem) {
  Banked b = rolled_to_20_degrees();
  b.model->set_wing_leveller_engaged(true);
  EXPECT_TRUE(b.model->wing_leveller_engaged());
  // It acts at once, with left aileron for a right bank (the surface follows at its rate limit).
  b.model->step(0.02);
  EXPECT_TRUE(b.model->outputs().wing_leveller_active);
  EXPECT_LT(b.model->outputs().wing_leveller_aileron, -0.5);
  for (int i = 0; i < 10; ++i) b.model->step(0.02);
  EXPECT_LT(b.model->outputs().aileron_rad, 0.0);
  // Within 10 s the wings are level to 1 deg, and they stay level for the next 20 s.
  double level_after_s = -1.0, overshoot_rad = 0.0;
  for (int i = 1; i <= 500; ++i) {
    b.model->step(0.02);
    const double phi = b.model->outputs().euler.phi_rad;
    if (level_after_s < 0.0 && std::abs(phi) < 1.0 * kDeg) level_after_s = 0.22 + i * 0.02;
    overshoot_rad = std::min(overshoot_rad, phi);
  }
  std::printf("C172 wing leveller from 20 deg: within 1 deg after %.2f s, overshoot %.2f deg\n", level_after_s,
              -overshoot_rad / kDeg);
  EXPECT_GT(level_after_s, 0.0);
  EXPECT_LT(level_after_s, 10.0);
  EXPECT_LT(std::abs(b.model->outputs().euler.phi_rad), 1.0 * kDeg);
  EXPECT_LT(fly(*b.model, 20.0, 20.0), 1.0 * kDeg);
  EXPECT_FALSE(b.model->outputs().numerical_fault);
}

TEST(WingLevellerC172, OffTheBankStays) {
  // Negative control for the test above: the same aircraft, leveller off.
  Banked b = rolled_to_20_degrees();
  fly(*b.model, 10.0, 0.0);
  EXPECT_GT(std::abs(b.model->outputs().euler.phi_rad), 10.0 * kDeg);
  EXPECT_FALSE(b.model->outputs().wing_leveller_active);
  EXPECT_EQ(b.model->outputs().wing_leveller_aileron, 0.0);
}

TEST(WingLevellerC172, TheSwitchDisengagesItAndAResetTurnsItOff) {
  Banked b = rolled_to_20_degrees();
  b.model->set_wing_leveller_engaged(true);
  fly(*b.model, 2.0, 0.0);
  b.model->set_wing_leveller_engaged(false);
  b.model->step(0.02);
  EXPECT_FALSE(b.model->outputs().wing_leveller_active);
  EXPECT_EQ(b.model->outputs().wing_leveller_aileron, 0.0);
  b.model->set_wing_leveller_engaged(true);
  AircraftInitialConditions ic;
  ic.position.alt_m = 1000.0;
  b.model->reset(ic);
  EXPECT_FALSE(b.model->wing_leveller_engaged());  // the pack's engaged_at_start: false
}

TEST(WingLevellerC172, OnTheGroundItCommandsNoAileron) {
  auto model = make_model("c172.yaml");
  const Runway runway{{37.6 * kDeg, -122.4 * kDeg, 4.0}, 280.0 * kDeg};
  ASSERT_TRUE(reposition_to_runway(*model, runway).converged);  // at rest on the centreline
  model->set_wing_leveller_engaged(true);
  for (int i = 0; i < 50; ++i) model->step(0.02);
  ASSERT_TRUE(model->outputs().weight_on_wheels);
  EXPECT_FALSE(model->outputs().wing_leveller_active);
  EXPECT_EQ(model->outputs().wing_leveller_aileron, 0.0);
}

TEST(WingLevellerC172, The737HasNone) {
  auto model = make_model("b737.yaml");
  model->set_wing_leveller_engaged(true);
  EXPECT_FALSE(model->wing_leveller_engaged());
}

}  // namespace
}  // namespace fedsim::flight
