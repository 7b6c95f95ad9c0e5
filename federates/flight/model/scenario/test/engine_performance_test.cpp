// The C172's engine and propeller against their source data (JSBSim engine/eng_io320.xml,
// Lycoming IO-320: 160 hp at 2700 rpm, 28.5 inHg; engine/prop_75in2f.xml, 75-inch two-blade
// fixed pitch), against the Cessna 172P handbook (the static full-throttle rpm and the
// short-field ground roll the pack's low-advance-ratio correction of the table was identified
// from), against momentum theory (no propeller beats an actuator disc) and the cruise the
// correction must leave as it was. Every expectation is worked out here from the source figures
// (the propeller tables with the pack's correction as data/aircraft/README.md defines it, the
// engine rating), from the handbook or from physics, not from the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "flight/model/aircraft/pack_to_systems.hpp"
#include "flight/model/scenario/reposition.hpp"
#include "flight/model/scenario/test/flight_test_support.hpp"
#include "flight/model/systems/propeller.hpp"

namespace fedsim::flight {
namespace {

using namespace testing;

constexpr double kHp = 745.69987158227022;  // W
constexpr double kInHg = 3386.389;          // Pa
constexpr double kLb = 0.45359237;          // kg

// --- Source figures, as published in the JSBSim files ---------------------------------------
constexpr double kRatedPowerW = 160.0 * kHp;  // eng_io320.xml maxhp, at maxrpm, full throttle
constexpr double kRatedRpm = 2700.0;          // eng_io320.xml maxrpm
constexpr double kDiameterM = 75.0 * 0.0254;  // prop_75in2f.xml diameter

// prop_75in2f.xml C_THRUST and C_POWER against advance ratio J (the J = 5 end rows omitted:
// the take-off roll stays below J = 0.5).
const std::vector<double> kJ = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8};
const std::vector<double> kCt = {0.073, 0.073, 0.072, 0.071, 0.069, 0.066, 0.062, 0.055, 0.045};
const std::vector<double> kCp = {0.0660, 0.0700, 0.0700, 0.0660, 0.0600,
                                 0.0530, 0.0501, 0.0469, 0.0426};

double linear(const std::vector<double>& y, double j) {
  const double x = std::clamp(j, kJ.front(), kJ.back()) / 0.1;  // breakpoints every 0.1
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(x), kJ.size() - 2);
  return y[i] + (y[i + 1] - y[i]) * (x - static_cast<double>(i));
}

/// Full-throttle engine power at `rpm` from the published rating: the rated torque, held
/// constant over the speed range (the simplest curve through the rating; an IO-320's
/// full-throttle torque varies by a few percent between 2000 and 2700 rpm).
double rated_engine_power_w(double rpm) { return kRatedPowerW * rpm / kRatedRpm; }

/// The pack's correction of the CT and CP tables (data/aircraft/README.md, propeller): factors
/// f that apply in full up to the fade band's start J_a and fade linearly to 1 at its end J_b
/// (no band: f at every J). This is the definition, written out here; the figures are data.
struct Correction {
  double thrust = 1.0;
  double power = 1.0;
  bool fades = false;
  double fade_start = 0.0;
  double fade_end = 0.0;

  /// The share of (f - 1) that applies at advance ratio j.
  double share(double j) const {
    if (!fades || j <= fade_start) return 1.0;
    if (j >= fade_end) return 0.0;
    return (fade_end - j) / (fade_end - fade_start);
  }
  double ct_factor(double j) const { return 1.0 + (thrust - 1.0) * share(j); }
  double cp_factor(double j) const { return 1.0 + (power - 1.0) * share(j); }
};

/// The source table as it is.
constexpr Correction kNoCorrection{};

Correction correction_of(const AircraftPack& pack) {
  const PropellerSpec& p = pack.engines.front().propeller;
  Correction c{p.thrust_coefficient_factor, p.power_coefficient_factor};
  if (p.factor_fade) {
    c.fades = true;
    c.fade_start = p.factor_fade->start_advance_ratio;
    c.fade_end = p.factor_fade->end_advance_ratio;
  }
  return c;
}
void set_correction(AircraftPack& pack, const Correction& c) {
  PropellerSpec& p = pack.engines.front().propeller;
  p.thrust_coefficient_factor = c.thrust;
  p.power_coefficient_factor = c.power;
  p.factor_fade.reset();
  if (c.fades) p.factor_fade = PropellerSpec::FactorFade{c.fade_start, c.fade_end};
}

/// Propeller power P = f_P(J) CP(J) rho n^3 D^5 and thrust T = f_T(J) CT(J) rho n^2 D^4 (n in
/// rev/s) with the correction's factors at J. The tip speed stays below Mach 0.85 here, where
/// the tip-Mach factors are 1.
double propeller_power_w(double rpm, double airspeed_mps, double rho, const Correction& c) {
  const double n = rpm / 60.0;
  const double j = airspeed_mps / (n * kDiameterM);
  return c.cp_factor(j) * linear(kCp, j) * rho * n * n * n * std::pow(kDiameterM, 5);
}
double propeller_thrust_n(double rpm, double airspeed_mps, double rho, const Correction& c) {
  const double n = rpm / 60.0;
  const double j = airspeed_mps / (n * kDiameterM);
  return c.ct_factor(j) * linear(kCt, j) * rho * n * n * std::pow(kDiameterM, 4);
}

/// The rpm at which the rated engine and the propeller absorb the same power (bisection).
double balance_rpm(double airspeed_mps, double rho, const Correction& c) {
  double lo = 1000.0, hi = 3500.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rated_engine_power_w(mid) > propeller_power_w(mid, airspeed_mps, rho, c) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

constexpr double kSeaLevelDensity = 1.225;  // ISA

const Runway kRunway{{34.0 * kDeg, -118.0 * kDeg, 0.0}, 69.0 * kDeg};

/// The pack's powerplant, as flown, run to steady state at full throttle, full rich, at rest,
/// sea level ISA.
PistonPowerplant::Outputs static_run_up(const AircraftPack& pack) {
  PistonPowerplant plant(piston_powerplant_params(pack.engines.front()));
  plant.reset(1000.0);
  PistonPowerplant::Inputs in;
  in.throttle = 1.0;
  in.mixture = 1.0;
  for (int i = 0; i < 3000; ++i) plant.step(0.01, in);  // 30 s, many shaft time constants
  return plant.outputs();
}

/// The static balance of `pack` against the source data with the pack's correction: rpm and
/// brake power from the rated engine and the corrected CP table (at J = 0 the factors apply in
/// full), thrust from the corrected CT.
void expect_static_balance_follows_the_source_data(const AircraftPack& pack) {
  const Correction c = correction_of(pack);
  const double expected_rpm = balance_rpm(0.0, kSeaLevelDensity, c);
  const double expected_w = rated_engine_power_w(expected_rpm);
  const PistonPowerplant::Outputs out = static_run_up(pack);
  std::printf("static, SL ISA, full throttle, CT x %.4f, CP x %.4f at J = 0: %.0f rpm, %.1f hp, "
              "%.0f N, MAP %.2f inHg (source data: %.0f rpm, %.1f hp)\n",
              c.ct_factor(0.0), c.cp_factor(0.0), out.engine_rpm, out.brake_power_w / kHp,
              out.thrust_n, out.manifold_pressure_pa / kInHg, expected_rpm, expected_w / kHp);
  // Power scales with rpm cubed along the propeller's curve, so 2.5 % in rpm is ~8 % in power.
  EXPECT_NEAR(out.engine_rpm, expected_rpm, 0.025 * expected_rpm);
  EXPECT_NEAR(out.brake_power_w, expected_w, 0.08 * expected_w);
  // At the balance the engine's power is what the corrected source propeller absorbs at that
  // rpm, and the thrust is the corrected source CT's.
  EXPECT_NEAR(out.brake_power_w, propeller_power_w(out.engine_rpm, 0.0, kSeaLevelDensity, c),
              0.002 * out.brake_power_w);
  EXPECT_NEAR(out.thrust_n, propeller_thrust_n(out.engine_rpm, 0.0, kSeaLevelDensity, c),
              0.002 * out.thrust_n);
  // Full-throttle manifold pressure: 28.5 inHg (maxmp) at 2700 rpm in sea-level air, the
  // intake loss growing with the engine's air flow, so at this rpm the loss of 29.92 - 28.5
  // inHg scaled by N / 2700 (to 0.02 inHg, the difference between a linear loss and JSBSim's
  // intake impedance over this range).
  EXPECT_NEAR(out.manifold_pressure_pa / kInHg,
              101325.0 / kInHg - (101325.0 / kInHg - 28.5) * out.engine_rpm / kRatedRpm, 0.02);
}

TEST(EnginePerformance, StaticFullThrottleRpmAndPowerFollowTheSourceData) {
  // Independent expectation for the source table as it is: rated engine = propeller at J = 0,
  // sea level ISA: 160 hp x N / 2700 = 0.066 x 1.225 x (N/60)^3 x D^5 (D^5 = 25.088 m^5) gives
  // N^2 = 44.190 / 9.3910e-6, N = 2169 rpm, 128.5 hp; a CP factor f divides N^2 by f.
  ASSERT_NEAR(balance_rpm(0.0, kSeaLevelDensity, kNoCorrection), 2169.2, 0.5);  // the bisection
  ASSERT_NEAR(balance_rpm(0.0, kSeaLevelDensity, Correction{1.0, 0.81}), 2169.2 / 0.9, 0.5);
  AircraftPack pack = load_pack("c172.yaml");
  set_correction(pack, kNoCorrection);
  expect_static_balance_follows_the_source_data(pack);
}

struct FlownRoll {
  double liftoff_m = 0.0;     ///< brake release to the wheels leaving the ground (0: never)
  double liftoff_kcas = 0.0;
  double liftoff_j = 0.0;     ///< advance ratio at lift-off
  double predicted_m = 0.0;   ///< the same roll integrated with the source data's thrust
};

/// A take-off of `pack` from a sea-level runway, ISA, no wind (RK4, 100 Hz): flaps set and full
/// throttle held on the brakes, mixture full rich; brakes released, the elevator held at its
/// ground-trim position until `rotate_kcas`, then -0.35 (stick back) until the wheels leave
/// the ground. Alongside, the roll is integrated from the thrust the source data give at each
/// speed (rated engine and corrected propeller tables balanced by bisection) and the resistance
/// (aerodynamic and gear forces) the model meets on the way.
FlownRoll fly_takeoff(const AircraftPack& pack, double flaps_norm, double rotate_kcas) {
  const Correction c = correction_of(pack);
  AircraftModel::Options options;
  options.integrator = IntegrationMethod::kRk4;  // the federate's integrator
  AircraftModel model(pack, options);
  EXPECT_NEAR(model.outputs().mass_kg, 2400.0 * kLb, 1.0);
  AircraftControls controls = model.controls();
  controls.flaps = flaps_norm;
  model.set_controls(controls);
  const TrimResult parked = reposition_to_runway(model, kRunway, 1.0);
  EXPECT_TRUE(parked.converged) << parked.reason;
  EXPECT_GT(model.outputs().engines[0].rpm, 2000.0);  // full power on the brakes
  EXPECT_NEAR(model.outputs().flap_norm, flaps_norm, 1e-9);
  controls = parked.controls;
  controls.brake_left = controls.brake_right = 0.0;
  const double mass_kg = model.outputs().mass_kg;

  constexpr double kRateHz = 100.0;
  const Eigen::Vector3d start(model.outputs().north_m, model.outputs().east_m, 0.0);
  FlownRoll roll;
  double previous_v = model.outputs().ground_speed_mps;
  for (int i = 0; i < 90 * kRateHz; ++i) {
    if (model.outputs().cas_mps >= rotate_kcas * kKt) controls.elevator = -0.35;  // rotate
    model.set_controls(controls);
    model.step(1.0 / kRateHz);
    const AircraftOutputs& now = model.outputs();
    const double v = now.ground_speed_mps;
    if (!now.weight_on_wheels) {
      roll.liftoff_m = std::hypot(now.north_m - start.x(), now.east_m - start.y());
      roll.liftoff_kcas = now.cas_mps / kKt;
      roll.liftoff_j = now.tas_mps / (now.engines[0].propeller_rpm / 60.0 * kDiameterM);
      break;
    }
    // Along the ground track: the resistance the model meets (aerodynamic and gear forces),
    // and the thrust the source data give at this airspeed (thrust axis pitched theta).
    const Eigen::Vector3d track(now.velocity_ned_mps.x(), now.velocity_ned_mps.y(), 0.0);
    if (track.norm() < 1e-3) continue;
    const Eigen::Vector3d along = track.normalized();
    const double resistance_n =
        -along.dot(now.ned_from_body * (now.aero_force_body_n + now.gear_force_body_n));
    const double airspeed = now.tas_mps;
    const double rho = now.density_kgpm3;
    const double thrust_n = propeller_thrust_n(balance_rpm(airspeed, rho, c), airspeed, rho, c) *
                            std::cos(now.euler.theta_rad);
    const double accel = (thrust_n - resistance_n) / mass_kg;
    EXPECT_GT(accel, 0.0);
    if (!(accel > 0.0)) break;
    roll.predicted_m += 0.5 * (v + previous_v) * (v - previous_v) / accel;  // ds = v dv / a
    previous_v = v;
  }
  std::printf("C172 take-off, flaps %.0f deg, CT x %.4f, CP x %.4f at J = 0, rotate %.0f KCAS: "
              "lift-off at %.1f KCAS, J %.3f, after %.0f m (%.0f ft); source engine and "
              "propeller: %.0f m (%.0f ft)\n",
              flaps_norm * pack.flight_controls.flaps->full_travel_rad / kDeg, c.ct_factor(0.0),
              c.cp_factor(0.0), rotate_kcas, roll.liftoff_kcas, roll.liftoff_j, roll.liftoff_m,
              roll.liftoff_m / kFt, roll.predicted_m, roll.predicted_m / kFt);
  return roll;
}

TEST(EnginePerformance, TakeOffGroundRollFollowsTheSourceEngineAndPropeller) {
  // Sea level ISA, 2400 lb (the pack's loading), flaps up, rotate at 55 KCAS (C172P POH normal
  // take-off): the flown roll must be the one the source engine and (corrected) propeller data
  // give with the resistance the model meets (the thrust is the only thing taken from the
  // data). The roll ends inside the pack's fade band, so the fade is flown here too.
  const FlownRoll roll = fly_takeoff(load_pack("c172.yaml"), 0.0, 55.0);
  ASSERT_GT(roll.liftoff_m, 0.0) << "never left the ground";
  EXPECT_NEAR(roll.liftoff_m, roll.predicted_m, 0.06 * roll.predicted_m);
  EXPECT_GT(roll.liftoff_kcas, 50.0);
  EXPECT_LT(roll.liftoff_kcas, 65.0);
}

TEST(EnginePerformance, CorrectedTableGivesThePohStaticRpmAndShortFieldGroundRoll) {
  // The C172 pack's propeller table, corrected at low advance ratio
  // (data/aircraft/c172.calibration.yaml merged by the converter), against the two Cessna
  // Model 172P Pilot's Operating Handbook (1981) figures the correction was identified from,
  // flown here independently of the identification:
  //  - static full-throttle rpm at sea level 2300-2420 (take-off power check);
  //  - section 5, short-field take-off distance: ground roll 890 ft at 2400 lb, sea level,
  //    15 C, flaps 10 deg, full throttle before brake release, paved level dry runway, zero
  //    wind, lift-off 51 KIAS (flown as rotation at 50 KCAS: fedsim has no airspeed position
  //    error, and the model lifts off about 1 kt after rotation starts).
  AircraftPack pack = load_pack("c172.yaml");
  const Correction corrected = correction_of(pack);
  ASSERT_TRUE(corrected.fades) << "the pack's correction has no fade band";

  // Static: inside the handbook's band, and the balance the corrected source data give.
  const PistonPowerplant::Outputs run_up = static_run_up(pack);
  EXPECT_GE(run_up.engine_rpm, 2300.0);
  EXPECT_LE(run_up.engine_rpm, 2420.0);
  expect_static_balance_follows_the_source_data(pack);

  // Short-field ground roll: within 10 % of the handbook's 890 ft, lifting off near its 51 KIAS,
  // and the roll the corrected source data give.
  ASSERT_TRUE(pack.flight_controls.flaps);
  const double flaps_10 = 10.0 * kDeg / pack.flight_controls.flaps->full_travel_rad;
  constexpr double kPohRollFt = 890.0;
  const FlownRoll roll = fly_takeoff(pack, flaps_10, 50.0);
  ASSERT_GT(roll.liftoff_m, 0.0) << "never left the ground";
  EXPECT_NEAR(roll.liftoff_m / kFt, kPohRollFt, 0.10 * kPohRollFt);
  EXPECT_NEAR(roll.liftoff_kcas, 51.0, 2.0);
  EXPECT_NEAR(roll.liftoff_m, roll.predicted_m, 0.06 * roll.predicted_m);

  // Negative control: the same take-off and run-up with the source table as it is miss the
  // handbook's figures, so the checks above are not vacuous.
  set_correction(pack, kNoCorrection);
  const FlownRoll uncorrected = fly_takeoff(pack, flaps_10, 50.0);
  ASSERT_GT(uncorrected.liftoff_m, 0.0) << "never left the ground";
  EXPECT_GT(uncorrected.liftoff_m / kFt, 1.10 * kPohRollFt);
  EXPECT_LT(static_run_up(pack).engine_rpm, 2300.0);
}

/// The smallest margin eta_ideal - eta of `pack`'s propeller, as the model evaluates it, over
/// J = 0.05 .. the end of its tables in steps of 0.005, and where it occurs. No propeller beats
/// an actuator disc (Froude's momentum theory; e.g. McCormick, Aerodynamics, Aeronautics and
/// Flight Mechanics, ch. 6): at advance ratio J and thrust coefficient CT its efficiency is at
/// most eta_i = 2 / (1 + sqrt(1 + 8 CT / (pi J^2))) (T / (q A) = 8 CT / (pi J^2)). Where CT <= 0
/// the propeller makes no thrust and its efficiency J CT / CP must not be positive.
struct DiscMargin {
  double margin = HUGE_VAL;
  double at_j = 0.0;
  double efficiency = 0.0;
  double ideal = 0.0;
  bool negative_thrust_ok = true;
};
DiscMargin actuator_disc_margin(const AircraftPack& pack) {
  const Propeller prop(piston_powerplant_params(pack.engines.front()).propeller);
  const double j_end = prop.params().power_coefficient.rows().back();
  DiscMargin worst;
  Propeller::Inputs in;
  in.blade_angle_rad = pack.engines.front().propeller.min_pitch_rad;
  in.rpm = 1200.0;  // helical tip Mach below 0.85 up to J 5: the tip-Mach factors are 1
  for (double j = 0.05; j <= j_end + 1e-9; j += 0.005) {
    in.axial_airspeed_mps = j * in.rpm / 60.0 * kDiameterM;
    const Propeller::Outputs out = prop.evaluate(in);
    EXPECT_LT(out.tip_mach, 0.85);
    const double ct = out.thrust_coefficient;
    if (ct <= 0.0) {
      worst.negative_thrust_ok = worst.negative_thrust_ok && out.efficiency <= 0.0 &&
                                 j * ct / out.power_coefficient <= 0.0;
      continue;
    }
    const double eta = j * ct / out.power_coefficient;
    EXPECT_NEAR(out.efficiency, eta, 1e-9);  // the model's own efficiency is J CT / CP
    const double ideal = 2.0 / (1.0 + std::sqrt(1.0 + 8.0 * ct / (kPi * j * j)));
    if (ideal - eta < worst.margin) worst = {ideal - eta, j, eta, ideal, worst.negative_thrust_ok};
  }
  return worst;
}

TEST(EnginePerformance, CorrectedPropellerNeverBeatsAnActuatorDisc) {
  // At every advance ratio of the corrected table the propeller stays below the momentum-theory
  // limit; a real fixed-pitch propeller stays about 10 % of it below.
  const AircraftPack pack = load_pack("c172.yaml");
  const DiscMargin corrected = actuator_disc_margin(pack);
  std::printf("corrected table: smallest margin to the actuator disc %.3f at J %.3f "
              "(efficiency %.3f, limit %.3f)\n",
              corrected.margin, corrected.at_j, corrected.efficiency, corrected.ideal);
  EXPECT_GT(corrected.margin, 0.0);
  EXPECT_TRUE(corrected.negative_thrust_ok);

  // Negative control: the same factors without the fade band (constant, as JSBSim's
  // <ct_factor>, <cp_factor>) carry the static correction into the cruise, where the propeller
  // would beat the actuator disc: the check above can fail.
  AircraftPack constant = pack;
  constant.engines.front().propeller.factor_fade.reset();
  const DiscMargin constant_factors = actuator_disc_margin(constant);
  std::printf("constant factors: smallest margin %.3f at J %.3f (efficiency %.3f, limit %.3f)\n",
              constant_factors.margin, constant_factors.at_j, constant_factors.efficiency,
              constant_factors.ideal);
  EXPECT_LT(constant_factors.margin, 0.0);
}

TEST(EnginePerformance, CruiseTrimIsUntouchedByTheLowAdvanceRatioCorrection) {
  // 4000 ft, 100 KTAS, 2400 lb, level: the cruise advance ratio lies above the correction's
  // fade band, so the trim must be the source table's: the same throttle, manifold pressure and
  // rpm to the figures reported (0.001, 0.01 inHg, 1 rpm).
  AircraftPack source = load_pack("c172.yaml");
  const Correction corrected = correction_of(source);
  set_correction(source, kNoCorrection);
  AircraftModel with_correction(load_pack("c172.yaml"), AircraftModel::Options{});
  AircraftModel without(source, AircraftModel::Options{});
  const TrimResult a = Trim(with_correction).solve(cruise("c172.yaml"));
  const TrimResult b = Trim(without).solve(cruise("c172.yaml"));
  ASSERT_TRUE(a.converged) << a.reason;
  ASSERT_TRUE(b.converged) << b.reason;
  const EngineOutputs& ea = with_correction.outputs().engines[0];
  const EngineOutputs& eb = without.outputs().engines[0];
  const double cruise_j =
      with_correction.outputs().tas_mps / (ea.propeller_rpm / 60.0 * kDiameterM);
  std::printf("cruise 4000 ft 100 KTAS: corrected throttle %.3f, %.0f rpm, %.2f inHg, J %.3f; "
              "source table throttle %.3f, %.0f rpm, %.2f inHg\n",
              a.controls.throttle[0], ea.rpm, ea.manifold_pressure_pa / kInHg, cruise_j,
              b.controls.throttle[0], eb.rpm, eb.manifold_pressure_pa / kInHg);
  EXPECT_GT(cruise_j, corrected.fade_end);  // the premise: cruise is past the band
  EXPECT_NEAR(a.controls.throttle[0], b.controls.throttle[0], 0.0005);
  EXPECT_NEAR(ea.manifold_pressure_pa / kInHg, eb.manifold_pressure_pa / kInHg, 0.005);
  EXPECT_NEAR(ea.rpm, eb.rpm, 0.5);
}

TEST(EnginePerformance, CruiseTrimPowerIsWhatThePropellerAbsorbsAndTheEngineMakes) {
  // 4000 ft, 100 KTAS, 2400 lb, level: the trimmed engine's power must equal what the source
  // propeller absorbs at the trimmed rpm and advance ratio, and must be in line with what the
  // IO-320 data predicts at the trimmed manifold pressure and rpm: the charge per cycle scales
  // with the manifold pressure and the cycles with rpm (indicated power ~ MAP x rpm, seed
  // 3.8.1 and JSBSim FGPiston's speed-density air flow), so P ~ 160 hp (MAP / 28.5 inHg)
  // (rpm / 2700) less the friction share that does not scale with MAP, i.e. somewhat below it.
  auto model = make_model("c172.yaml");
  const TrimResult t = Trim(*model).solve(cruise("c172.yaml"));
  ASSERT_TRUE(t.converged) << t.reason;
  const AircraftOutputs& o = model->outputs();
  const EngineOutputs& e = o.engines[0];
  const double rho = o.density_kgpm3;
  std::printf("cruise 4000 ft 100 KTAS: throttle %.3f, %.0f rpm, MAP %.2f inHg, %.1f hp (%.0f %% "
              "of 160), thrust %.0f N, EGT %.0f K\n",
              t.controls.throttle[0], e.rpm, e.manifold_pressure_pa / kInHg, e.power_w / kHp,
              100.0 * e.power_w / kRatedPowerW, e.thrust_n, e.egt_k);
  const Correction c = correction_of(model->pack());
  EXPECT_NEAR(e.power_w, propeller_power_w(e.rpm, o.tas_mps, rho, c), 0.002 * e.power_w);
  EXPECT_NEAR(e.thrust_n, propeller_thrust_n(e.rpm, o.tas_mps, rho, c), 0.002 * e.thrust_n);
  // No propeller beats an actuator disc (Froude's momentum theory; e.g. McCormick,
  // Aerodynamics, Aeronautics and Flight Mechanics, ch. 6): at thrust T, airspeed V and disc
  // area A its efficiency is at most 2 / (1 + sqrt(1 + T / (q A))), q = rho V^2 / 2, and real
  // fixed-pitch propellers reach about 85-90 % of that.
  const double disc_area_m2 = kPi * kDiameterM * kDiameterM / 4.0;
  const double q_pa = 0.5 * rho * o.tas_mps * o.tas_mps;
  const double ideal_efficiency = 2.0 / (1.0 + std::sqrt(1.0 + e.thrust_n / (q_pa * disc_area_m2)));
  const double efficiency = e.thrust_n * o.tas_mps / e.power_w;
  std::printf("cruise propeller efficiency %.3f, actuator-disc limit %.3f\n", efficiency,
              ideal_efficiency);
  EXPECT_LT(efficiency, ideal_efficiency);
  const double map_rpm_scaled_w =
      kRatedPowerW * (e.manifold_pressure_pa / (28.5 * kInHg)) * (e.rpm / kRatedRpm);
  EXPECT_LT(e.power_w, map_rpm_scaled_w);
  EXPECT_GT(e.power_w, 0.85 * map_rpm_scaled_w);
  // A cruise setting: about 60 % power (flight_test_support.hpp, cruise()).
  EXPECT_GT(e.power_w, 0.50 * kRatedPowerW);
  EXPECT_LT(e.power_w, 0.70 * kRatedPowerW);
  EXPECT_GT(t.controls.throttle[0], 0.0);
  EXPECT_LT(t.controls.throttle[0], 1.0);
}

}  // namespace
}  // namespace fedsim::flight

namespace fedsim::flight {
namespace {

TEST(EnginePerformance, RunningEnginesReportTheirExhaustTemperatureStoppedOnesAmbient) {
  for (const char* pack : {"c172.yaml", "b737.yaml"}) {
    auto model = testing::make_model(pack);
    const Runway runway{{34.0 * testing::kDeg, -118.0 * testing::kDeg, 0.0}, 0.0};
    ASSERT_TRUE(reposition_to_runway(*model, runway).converged) << pack;  // idle, running
    const double ambient_k = model->outputs().temperature_k;
    for (const EngineOutputs& e : model->outputs().engines) {
      EXPECT_TRUE(e.has_egt) << pack;
      EXPECT_GT(e.egt_k, ambient_k + 300.0) << pack;  // hundreds of kelvin above ambient
    }
    const double idle_k = model->outputs().engines[0].egt_k;
    AircraftControls c = model->controls();
    c.set_throttle(1.0);
    model->set_controls(c);
    for (int i = 0; i < 500; ++i) model->step(0.02);
    const double full_k = model->outputs().engines[0].egt_k;
    std::printf("%s EGT at sea level: idle %.0f K, full throttle %.0f K\n", pack, idle_k, full_k);
    for (std::size_t i = 0; i < model->engine_count(); ++i) model->set_engine_running(i, false);
    model->step(0.02);
    for (const EngineOutputs& e : model->outputs().engines) {
      EXPECT_NEAR(e.egt_k, model->outputs().temperature_k, 0.01) << pack;  // air at the CG
    }
  }
}

}  // namespace
}  // namespace fedsim::flight
