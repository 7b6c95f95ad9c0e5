// The C172's engine and propeller against their source data (JSBSim engine/eng_io320.xml,
// Lycoming IO-320: 160 hp at 2700 rpm, 28.5 inHg; engine/prop_75in2f.xml, 75-inch two-blade
// fixed pitch) and against the Cessna 172P handbook: the static full-throttle rpm and power,
// the take-off ground roll, and the power at the cruise trim. Every expectation is worked out
// here from the source figures (the propeller tables times the pack's constant CT and CP
// factors, the engine rating) or taken from the handbook, not from the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "common/util/config_node.hpp"
#include "flight/model/aircraft/pack_to_systems.hpp"
#include "flight/model/scenario/reposition.hpp"
#include "flight/model/scenario/test/flight_test_support.hpp"

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

/// Propeller power P = cp_factor CP rho n^3 D^5 and thrust T = ct_factor CT rho n^2 D^4 (n in
/// rev/s; the factors are JSBSim's <cp_factor>, <ct_factor>: constant multipliers on the
/// tables). The tip speed stays below Mach 0.85 here, where the tip-Mach factors are 1.
double propeller_power_w(double rpm, double airspeed_mps, double rho, double cp_factor) {
  const double n = rpm / 60.0;
  return cp_factor * linear(kCp, airspeed_mps / (n * kDiameterM)) * rho * n * n * n *
         std::pow(kDiameterM, 5);
}
double propeller_thrust_n(double rpm, double airspeed_mps, double rho, double ct_factor) {
  const double n = rpm / 60.0;
  return ct_factor * linear(kCt, airspeed_mps / (n * kDiameterM)) * rho * n * n *
         std::pow(kDiameterM, 4);
}

/// The rpm at which the rated engine and the propeller absorb the same power (bisection).
double balance_rpm(double airspeed_mps, double rho, double cp_factor) {
  double lo = 1000.0, hi = 3500.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rated_engine_power_w(mid) > propeller_power_w(mid, airspeed_mps, rho, cp_factor) ? lo : hi) =
        mid;
  }
  return 0.5 * (lo + hi);
}

/// The constant CT and CP factors of a pack's (first) propeller: data the expectations use.
struct Factors {
  double thrust = 1.0;
  double power = 1.0;
};
Factors factors_of(const AircraftPack& pack) {
  return {pack.engines.front().propeller.thrust_coefficient_factor,
          pack.engines.front().propeller.power_coefficient_factor};
}
void set_factors(AircraftPack& pack, Factors f) {
  pack.engines.front().propeller.thrust_coefficient_factor = f.thrust;
  pack.engines.front().propeller.power_coefficient_factor = f.power;
}

/// The C172's propeller factors identified from the POH (data/aircraft/c172.calibration.yaml;
/// procedure and sources in data/aircraft/README.md, "Calibration").
Factors poh_identified_factors() {
  const util::ConfigNode overlay =
      util::ConfigNode::load_file(std::string(FEDSIM_DATA_DIR) + "/aircraft/c172.calibration.yaml");
  const util::ConfigNode prop = overlay.child("engines").child("engine").child("propeller");
  return {prop.child("thrust_coefficient_factor").number("value"),
          prop.child("power_coefficient_factor").number("value")};
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

/// The static balance of `pack` against the source data with the pack's factors: rpm and
/// brake power from the rated engine and the factored CP table, thrust from the factored CT.
void expect_static_balance_follows_the_source_data(const AircraftPack& pack) {
  const Factors f = factors_of(pack);
  const double expected_rpm = balance_rpm(0.0, kSeaLevelDensity, f.power);
  const double expected_w = rated_engine_power_w(expected_rpm);
  const PistonPowerplant::Outputs out = static_run_up(pack);
  std::printf("static, SL ISA, full throttle, CT x %.4f, CP x %.4f: %.0f rpm, %.1f hp, %.0f N, "
              "MAP %.2f inHg (source data: %.0f rpm, %.1f hp)\n",
              f.thrust, f.power, out.engine_rpm, out.brake_power_w / kHp, out.thrust_n,
              out.manifold_pressure_pa / kInHg, expected_rpm, expected_w / kHp);
  // Power scales with rpm cubed along the propeller's curve, so 2.5 % in rpm is ~8 % in power.
  EXPECT_NEAR(out.engine_rpm, expected_rpm, 0.025 * expected_rpm);
  EXPECT_NEAR(out.brake_power_w, expected_w, 0.08 * expected_w);
  // At the balance the engine's power is what the factored source propeller absorbs at that
  // rpm, and the thrust is the factored source CT's.
  EXPECT_NEAR(out.brake_power_w,
              propeller_power_w(out.engine_rpm, 0.0, kSeaLevelDensity, f.power),
              0.002 * out.brake_power_w);
  EXPECT_NEAR(out.thrust_n, propeller_thrust_n(out.engine_rpm, 0.0, kSeaLevelDensity, f.thrust),
              0.002 * out.thrust_n);
  // Full-throttle manifold pressure: 28.5 inHg (maxmp) at 2700 rpm in sea-level air, the
  // intake loss growing with the engine's air flow, so at this rpm the loss of 29.92 - 28.5
  // inHg scaled by N / 2700 (to 0.02 inHg, the difference between a linear loss and JSBSim's
  // intake impedance over this range).
  EXPECT_NEAR(out.manifold_pressure_pa / kInHg,
              101325.0 / kInHg - (101325.0 / kInHg - 28.5) * out.engine_rpm / kRatedRpm, 0.02);
}

TEST(EnginePerformance, StaticFullThrottleRpmAndPowerFollowTheSourceData) {
  // Independent expectation, without factors: rated engine = propeller at J = 0, sea level ISA:
  // 160 hp x N / 2700 = 0.066 x 1.225 x (N/60)^3 x D^5 (D^5 = 25.088 m^5) gives
  // N^2 = 44.190 / 9.3910e-6, N = 2169 rpm, 128.5 hp; a CP factor f divides N^2 by f.
  ASSERT_NEAR(balance_rpm(0.0, kSeaLevelDensity, 1.0), 2169.2, 0.5);  // the bisection itself
  ASSERT_NEAR(balance_rpm(0.0, kSeaLevelDensity, 0.81), 2169.2 / 0.9, 0.5);
  expect_static_balance_follows_the_source_data(load_pack("c172.yaml"));
}

struct FlownRoll {
  double liftoff_m = 0.0;     ///< brake release to the wheels leaving the ground (0: never)
  double liftoff_kcas = 0.0;
  double predicted_m = 0.0;   ///< the same roll integrated with the source data's thrust
};

/// A take-off of `pack` from a sea-level runway, ISA, no wind (RK4, 100 Hz): flaps set and full
/// throttle held on the brakes, mixture full rich; brakes released, the elevator held at its
/// ground-trim position until `rotate_kcas`, then -0.35 (stick back) until the wheels leave
/// the ground. Alongside, the roll is integrated from the thrust the source data give at each
/// speed (rated engine and factored propeller tables balanced by bisection) and the resistance
/// (aerodynamic and gear forces) the model meets on the way.
FlownRoll fly_takeoff(const AircraftPack& pack, double flaps_norm, double rotate_kcas) {
  const Factors f = factors_of(pack);
  AircraftModel::Options options;
  options.integrator = IntegrationMethod::kRk4;  // the federate's integrator
  AircraftModel model(pack, options);
  EXPECT_NEAR(model.outputs().mass_kg, 2400.0 * kLb, 1.0);
  AircraftControls c = model.controls();
  c.flaps = flaps_norm;
  model.set_controls(c);
  const TrimResult parked = reposition_to_runway(model, kRunway, 1.0);
  EXPECT_TRUE(parked.converged) << parked.reason;
  EXPECT_GT(model.outputs().engines[0].rpm, 2000.0);  // full power on the brakes
  EXPECT_NEAR(model.outputs().flap_norm, flaps_norm, 1e-9);
  c = parked.controls;
  c.brake_left = c.brake_right = 0.0;
  const double mass_kg = model.outputs().mass_kg;

  constexpr double kRateHz = 100.0;
  const Eigen::Vector3d start(model.outputs().north_m, model.outputs().east_m, 0.0);
  FlownRoll roll;
  double previous_v = model.outputs().ground_speed_mps;
  for (int i = 0; i < 90 * kRateHz; ++i) {
    if (model.outputs().cas_mps >= rotate_kcas * kKt) c.elevator = -0.35;  // rotate
    model.set_controls(c);
    model.step(1.0 / kRateHz);
    const AircraftOutputs& now = model.outputs();
    const double v = now.ground_speed_mps;
    if (!now.weight_on_wheels) {
      roll.liftoff_m = std::hypot(now.north_m - start.x(), now.east_m - start.y());
      roll.liftoff_kcas = now.cas_mps / kKt;
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
    const double thrust_n =
        propeller_thrust_n(balance_rpm(airspeed, rho, f.power), airspeed, rho, f.thrust) *
        std::cos(now.euler.theta_rad);
    const double accel = (thrust_n - resistance_n) / mass_kg;
    EXPECT_GT(accel, 0.0);
    if (!(accel > 0.0)) break;
    roll.predicted_m += 0.5 * (v + previous_v) * (v - previous_v) / accel;  // ds = v dv / a
    previous_v = v;
  }
  std::printf("C172 take-off, flaps %.0f deg, CT x %.4f, CP x %.4f, rotate %.0f KCAS: lift-off at "
              "%.1f KCAS after %.0f m (%.0f ft); source engine and propeller: %.0f m (%.0f ft)\n",
              flaps_norm * pack.flight_controls.flaps->full_travel_rad / kDeg, f.thrust, f.power,
              rotate_kcas, roll.liftoff_kcas, roll.liftoff_m, roll.liftoff_m / kFt,
              roll.predicted_m, roll.predicted_m / kFt);
  return roll;
}

TEST(EnginePerformance, TakeOffGroundRollFollowsTheSourceEngineAndPropeller) {
  // Sea level ISA, 2400 lb (the pack's loading), flaps up, rotate at 55 KCAS (C172P POH normal
  // take-off): the flown roll must be the one the source engine and propeller data give with
  // the resistance the model meets (the thrust is the only thing taken from the data).
  const FlownRoll roll = fly_takeoff(load_pack("c172.yaml"), 0.0, 55.0);
  ASSERT_GT(roll.liftoff_m, 0.0) << "never left the ground";
  EXPECT_NEAR(roll.liftoff_m, roll.predicted_m, 0.06 * roll.predicted_m);
  EXPECT_GT(roll.liftoff_kcas, 50.0);
  EXPECT_LT(roll.liftoff_kcas, 65.0);
}

TEST(EnginePerformance, PohIdentifiedFactorsGiveThePohStaticRpmAndShortFieldGroundRoll) {
  // The C172's propeller factors identified from the Cessna Model 172P Pilot's Operating
  // Handbook (1981) (data/aircraft/c172.calibration.yaml) against the two handbook figures
  // they were identified from, flown here independently of the identification:
  //  - static full-throttle rpm at sea level 2300-2420 (take-off power check);
  //  - section 5, short-field take-off distance: ground roll 890 ft at 2400 lb, sea level,
  //    15 C, flaps 10 deg, full throttle before brake release, paved level dry runway, zero
  //    wind, lift-off 51 KIAS (flown as rotation at 50 KCAS: fedsim has no airspeed position
  //    error, and the model lifts off about 1 kt after rotation starts).
  const Factors poh = poh_identified_factors();
  AircraftPack pack = load_pack("c172.yaml");
  set_factors(pack, poh);

  // Static: inside the handbook's band, and the balance the factored source data give.
  const PistonPowerplant::Outputs run_up = static_run_up(pack);
  EXPECT_GE(run_up.engine_rpm, 2300.0);
  EXPECT_LE(run_up.engine_rpm, 2420.0);
  expect_static_balance_follows_the_source_data(pack);

  // Short-field ground roll: within 10 % of the handbook's 890 ft, lifting off near its 51 KIAS,
  // and the roll the factored source data give.
  ASSERT_TRUE(pack.flight_controls.flaps);
  const double flaps_10 = 10.0 * kDeg / pack.flight_controls.flaps->full_travel_rad;
  constexpr double kPohRollFt = 890.0;
  const FlownRoll roll = fly_takeoff(pack, flaps_10, 50.0);
  ASSERT_GT(roll.liftoff_m, 0.0) << "never left the ground";
  EXPECT_NEAR(roll.liftoff_m / kFt, kPohRollFt, 0.10 * kPohRollFt);
  EXPECT_NEAR(roll.liftoff_kcas, 51.0, 2.0);
  EXPECT_NEAR(roll.liftoff_m, roll.predicted_m, 0.06 * roll.predicted_m);

  // Negative control: the same take-off with the source table as it is (factors 1) misses the
  // handbook's band, so the check above is not vacuous.
  set_factors(pack, {1.0, 1.0});
  const FlownRoll unfactored = fly_takeoff(pack, flaps_10, 50.0);
  ASSERT_GT(unfactored.liftoff_m, 0.0) << "never left the ground";
  EXPECT_GT(unfactored.liftoff_m / kFt, 1.10 * kPohRollFt);
  EXPECT_LT(static_run_up(pack).engine_rpm, 2300.0);
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
  const Factors f = factors_of(model->pack());
  EXPECT_NEAR(e.power_w, propeller_power_w(e.rpm, o.tas_mps, rho, f.power), 0.002 * e.power_w);
  EXPECT_NEAR(e.thrust_n, propeller_thrust_n(e.rpm, o.tas_mps, rho, f.thrust), 0.002 * e.thrust_n);
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
