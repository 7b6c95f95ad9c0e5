// Tests of the propeller-factor identification (propeller_calibration.hpp): the premises of the
// procedure, that it reaches its targets, that the C172's recorded factors are what it
// identifies with the recorded fade band, that the pack carries them, and that it refuses what
// it cannot do.
#include "flight/model/scenario/propeller_calibration.hpp"
#include "common/util/build_paths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "common/util/config_node.hpp"
#include "flight/model/scenario/test/flight_test_support.hpp"

namespace fedsim::flight {
namespace {

using namespace testing;

/// The C172's calibration overlay (data/aircraft/c172.calibration.yaml), propeller section.
util::ConfigNode c172_overlay_propeller() {
  return util::ConfigNode::load_file(fedsim::util::data_dir() +
                                     "/aircraft/c172.calibration.yaml")
      .child("engines")
      .child("engine")
      .child("propeller");
}

/// The fade band recorded in the overlay (a stated choice: data/aircraft/README.md).
PropellerSpec::FactorFade c172_overlay_fade() {
  const util::ConfigNode prop = c172_overlay_propeller();
  return {prop.child("factor_fade_start_advance_ratio").number("value"),
          prop.child("factor_fade_end_advance_ratio").number("value")};
}

/// The C172 targets from the Cessna Model 172P Pilot's Operating Handbook (1981): static
/// full-throttle rpm 2300-2420 at sea level (the band's middle), short-field ground roll 890 ft
/// at 2400 lb, sea level, ISA, flaps 10 deg, lift-off 51 KIAS (rotation at 50 KCAS); the
/// overlay's fade band.
PropellerCalibrationTargets c172_poh_targets(const AircraftPack& pack) {
  PropellerCalibrationTargets t;
  t.static_rpm = 2360.0;
  t.ground_roll_m = 890.0 * kFt;
  t.technique.flaps_norm = 10.0 * kDeg / pack.flight_controls.flaps->full_travel_rad;
  t.technique.rotate_cas_mps = 50.0 * kKt;
  t.factor_fade = c172_overlay_fade();
  return t;
}

template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

TEST(PropellerCalibration, StaticRpmFallsWithTheCpFactorAndIgnoresTheCtFactor) {
  // The procedure's premise: at rest a fixed-pitch propeller's torque is CP rho n^2 D^5 / 2 pi,
  // so the rpm at which it takes the engine's torque falls as CP rises, and CT only scales the
  // thrust.
  AircraftPack pack = load_pack("c172.yaml");
  set_propeller_factors(pack, 1.0, 0.9);
  const StaticRunUp low_cp = static_full_throttle(pack);
  set_propeller_factors(pack, 1.0, 1.1);
  const StaticRunUp high_cp = static_full_throttle(pack);
  ASSERT_TRUE(low_cp.converged && high_cp.converged);
  EXPECT_GT(low_cp.rpm, high_cp.rpm + 100.0);
  set_propeller_factors(pack, 1.5, 1.1);
  const StaticRunUp high_ct = static_full_throttle(pack);
  EXPECT_NEAR(high_ct.rpm, high_cp.rpm, 0.5);
  EXPECT_NEAR(high_ct.thrust_n, 1.5 * high_cp.thrust_n, 0.005 * high_ct.thrust_n);
}

TEST(PropellerCalibration, C172ReachesThePohTargetsAndTheOverlayRecordsTheResult) {
  const AircraftPack pack = load_pack("c172.yaml");
  const PropellerCalibrationTargets targets = c172_poh_targets(pack);
  const PropellerCalibration cal = identify_propeller_factors(pack, targets);
  std::printf("C172 identified with the fade band %.2f-%.2f: CP x %.4f, CT x %.4f; static %.1f "
              "rpm, %.1f hp, roll %.1f ft, lift-off %.1f KCAS at J %.3f\n",
              targets.factor_fade->start_advance_ratio, targets.factor_fade->end_advance_ratio,
              cal.power_coefficient_factor, cal.thrust_coefficient_factor, cal.static_run.rpm,
              cal.static_run.power_w / 745.69987158227022, cal.roll.ground_roll_m / kFt,
              cal.roll.liftoff_cas_mps / kKt, cal.roll.liftoff_advance_ratio);
  ASSERT_TRUE(cal.static_run.converged);
  ASSERT_TRUE(cal.roll.lifted_off);
  EXPECT_NEAR(cal.static_run.rpm, 2360.0, 0.5);
  // The lift-off is detected frame by frame (100 Hz, ~0.26 m at 51 kt).
  EXPECT_NEAR(cal.roll.ground_roll_m, 890.0 * kFt, 0.5);
  // A higher static rpm than the source table's ~2200 needs a propeller that absorbs less power
  // at rest.
  EXPECT_LT(cal.power_coefficient_factor, 1.0);
  // The band starts where the take-off roll ends: the whole roll, like the run-up, is flown
  // with the factors in full, so both identify the correction where it applies in full.
  EXPECT_LE(cal.roll.liftoff_advance_ratio, targets.factor_fade->start_advance_ratio);
  EXPECT_GT(cal.roll.liftoff_advance_ratio, targets.factor_fade->start_advance_ratio - 0.05);

  // data/aircraft/c172.calibration.yaml records this result (to four decimals). If this fails,
  // the C172's aerodynamics, gear, mass or engine have changed: re-run the procedure in the
  // overlay, update its values and regenerate c172.yaml (data/aircraft/README.md).
  const util::ConfigNode prop = c172_overlay_propeller();
  EXPECT_NEAR(prop.child("power_coefficient_factor").number("value"),
              cal.power_coefficient_factor, 0.005);
  EXPECT_NEAR(prop.child("thrust_coefficient_factor").number("value"),
              cal.thrust_coefficient_factor, 0.005);
}

TEST(PropellerCalibration, C172PackCarriesTheOverlay) {
  // c172.yaml is the converter's output with the overlay merged (data/aircraft/README.md):
  // the propeller's two factors and fade band are the overlay's, to the digit.
  const util::ConfigNode prop = c172_overlay_propeller();
  const PropellerSpec& pack = load_pack("c172.yaml").engines.front().propeller;
  EXPECT_EQ(pack.power_coefficient_factor, prop.child("power_coefficient_factor").number("value"));
  EXPECT_EQ(pack.thrust_coefficient_factor,
            prop.child("thrust_coefficient_factor").number("value"));
  ASSERT_TRUE(pack.factor_fade);
  EXPECT_EQ(pack.factor_fade->start_advance_ratio, c172_overlay_fade().start_advance_ratio);
  EXPECT_EQ(pack.factor_fade->end_advance_ratio, c172_overlay_fade().end_advance_ratio);
}

TEST(PropellerCalibration, UnreachableTargetsAndBadInputsAreRefusedByName) {
  const AircraftPack c172 = load_pack("c172.yaml");
  PropellerCalibrationTargets t = c172_poh_targets(c172);
  t.static_rpm = 5000.0;  // beyond what any factor in [0.5, 2] gives
  EXPECT_NE(error_of([&] { identify_propeller_factors(c172, t); }).find("static rpm (CP factor)"),
            std::string::npos);
  t = c172_poh_targets(c172);
  t.ground_roll_m = 10.0;
  EXPECT_NE(error_of([&] { identify_propeller_factors(c172, t); }).find("ground roll (CT factor)"),
            std::string::npos);
  t = c172_poh_targets(c172);
  EXPECT_NE(error_of([&] { identify_propeller_factors(load_pack("b737.yaml"), t); })
                .find("not a piston engine"),
            std::string::npos);
  t.technique.rotate_cas_mps = 0.0;
  EXPECT_NE(error_of([&] { identify_propeller_factors(c172, t); }).find("rotate_cas_mps"),
            std::string::npos);
  t = c172_poh_targets(c172);
  t.factor_low = 0.01;  // below what Propeller accepts
  EXPECT_NE(error_of([&] { identify_propeller_factors(c172, t); }).find("factor_low"),
            std::string::npos);
  t = c172_poh_targets(c172);
  t.factor_fade = PropellerSpec::FactorFade{0.5, 0.5};  // an empty band
  EXPECT_NE(error_of([&] { identify_propeller_factors(c172, t); })
                .find("factor_fade.end_advance_ratio"),
            std::string::npos);
  t.factor_fade = PropellerSpec::FactorFade{std::nan(""), 0.5};
  EXPECT_NE(error_of([&] { identify_propeller_factors(c172, t); })
                .find("factor_fade.start_advance_ratio"),
            std::string::npos);
  t = c172_poh_targets(c172);
  t.static_rpm = std::nan("");
  EXPECT_NE(error_of([&] { identify_propeller_factors(c172, t); }).find("static_rpm"),
            std::string::npos);
}

}  // namespace
}  // namespace fedsim::flight
