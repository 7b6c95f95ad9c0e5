// Tests of the piston engine: rated point, manifold pressure law, altitude lapse, mixture,
// failure and fuel flow, with Lycoming IO-320 figures.
#include "flight/model/systems/piston_engine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "flight/model/systems/test/reference_data.hpp"

namespace fedsim::flight {
namespace {

using reference::kHp;
using reference::kInHg;

// ISA troposphere (US Standard Atmosphere 1976), geopotential altitude.
struct Air {
  double pressure_pa, temperature_k, density_kgpm3;
};
Air isa(double altitude_m) {
  const double t = 288.15 - 0.0065 * altitude_m;
  const double p = 101325.0 * std::pow(t / 288.15, 5.255876);
  return {p, t, p / (287.05287 * t)};
}

PistonEngine::Inputs full_throttle(double rpm, const Air& air) {
  PistonEngine::Inputs in;
  in.engine_rpm = rpm;
  in.throttle = 1.0;
  in.mixture = 1.0;
  in.ambient_pressure_pa = air.pressure_pa;
  in.ambient_temperature_k = air.temperature_k;
  in.ambient_density_kgpm3 = air.density_kgpm3;
  return in;
}

// Best brake power over the mixture lever's travel (a pilot leaning for best power).
double best_power_w(const PistonEngine& engine, PistonEngine::Inputs in) {
  double best = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    in.mixture = i / 1000.0;
    best = std::max(best, engine.evaluate(in).brake_power_w);
  }
  return best;
}

TEST(PistonEngine, RatedPointGivesRatedPowerAndManifoldPressure) {
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(2700.0, isa(0.0));
  // Mixture at best power (F/A 0.080) in sea-level air: 0.088 / (2 - ml^2) = 0.080.
  in.mixture = std::sqrt(2.0 - 0.088 / 0.080);
  const PistonEngine::Outputs out = engine.evaluate(in);
  EXPECT_NEAR(out.fuel_air_ratio, 0.080, 1e-8);  // ISA sea-level density is 1.2250 kg/m^3
  EXPECT_NEAR(out.brake_power_w / kHp, 160.0, 1e-6);
  EXPECT_NEAR(out.manifold_pressure_pa / kInHg, 28.5, 1e-9);  // IO-320 maxmp
  EXPECT_NEAR(out.brake_power_w, out.brake_torque_nm * 2700.0 * 2.0 * std::numbers::pi / 60.0,
              1e-6);
  // BSFC 0.5 lb/(hp h) at the rated point: 80 lb/h.
  EXPECT_NEAR(out.fuel_flow_kgps * 3600.0 / reference::kLb, 80.0, 1e-6);
}

TEST(PistonEngine, FullThrottleManifoldPressureFollowsEq3114) {
  PistonEngine::Params p = reference::io320();
  p.intake_loss_pa_per_rpm = (0.0469 - 0.04635) * kInHg;  // book: (0.04635 tl - 0.0469) n
  const PistonEngine engine(p);
  for (double rpm : {1500.0, 2200.0, 2700.0}) {
    const Air air = isa(1000.0);
    const double book_inhg = air.pressure_pa / kInHg + (0.04635 * 1.0 - 0.0469) * rpm;
    EXPECT_NEAR(engine.evaluate(full_throttle(rpm, air)).manifold_pressure_pa / kInHg, book_inhg,
                1e-9);
  }
  // At 2700 rpm the book's intake loss is 1.485 inHg.
  EXPECT_NEAR(engine.evaluate(full_throttle(2700.0, isa(0.0))).manifold_pressure_pa / kInHg,
              101325.0 / kInHg - 1.485, 1e-9);
}

TEST(PistonEngine, ClosedThrottleManifoldPressure) {
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(550.0, isa(0.0));
  in.throttle = 0.0;
  EXPECT_NEAR(engine.evaluate(in).manifold_pressure_pa / kInHg, 10.0, 1e-9);  // minmp at idle
  in.engine_rpm = 1100.0;  // choked throttle: twice the speed, half the pressure
  EXPECT_NEAR(engine.evaluate(in).manifold_pressure_pa / kInHg, 5.0, 1e-9);
  const Air high = isa(3000.0);
  in.ambient_pressure_pa = high.pressure_pa;
  in.engine_rpm = 550.0;
  EXPECT_NEAR(engine.evaluate(in).manifold_pressure_pa, 10.0 * kInHg * high.pressure_pa / 101325.0,
              1e-6);
  // Half throttle lies half way between closed and full throttle.
  in = full_throttle(2000.0, isa(0.0));
  const double full = engine.evaluate(in).manifold_pressure_pa;
  in.throttle = 0.0;
  const double closed = engine.evaluate(in).manifold_pressure_pa;
  in.throttle = 0.5;
  EXPECT_NEAR(engine.evaluate(in).manifold_pressure_pa, 0.5 * (full + closed), 1e-9);
  // A stopped engine sees ambient pressure.
  in.engine_rpm = 0.0;
  EXPECT_NEAR(engine.evaluate(in).manifold_pressure_pa, 101325.0, 1e-9);
}

TEST(PistonEngine, PowerLapsesWithAltitudeLikeGaggFerrar) {
  // Gagg & Ferrar (1934): P / P_sl = (sigma - 0.117) / 0.883 at constant rpm, full throttle.
  const PistonEngine engine(reference::io320());
  const double sea_level = best_power_w(engine, full_throttle(2400.0, isa(0.0)));
  EXPECT_GT(sea_level / kHp, 135.0);
  EXPECT_LT(sea_level / kHp, 155.0);
  double previous = sea_level;
  for (double alt_ft : {5000.0, 10000.0}) {
    const Air air = isa(alt_ft * reference::kFt);
    const double power = best_power_w(engine, full_throttle(2400.0, air));
    const double sigma = air.density_kgpm3 / 1.225;
    const double gagg_ferrar = (sigma - 0.117) / 0.883;
    EXPECT_NEAR(power / sea_level, gagg_ferrar, 0.06) << alt_ft << " ft";
    EXPECT_LT(power, previous);
    previous = power;
  }
}

TEST(PistonEngine, HotAirGivesLessPower) {
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(2400.0, isa(0.0));
  const double standard = engine.evaluate(in).brake_power_w;
  in.ambient_temperature_k += 20.0;
  in.ambient_density_kgpm3 = in.ambient_pressure_pa / (287.05287 * in.ambient_temperature_k);
  const double hot = engine.evaluate(in).brake_power_w;
  EXPECT_LT(hot, standard);
  EXPECT_GT(hot / standard, 0.93);  // ~1 % per 6 K on indicated power, losses unchanged
}

TEST(PistonEngine, MixtureLeaningAndCutOff) {
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(2400.0, isa(10000.0 * reference::kFt));
  const PistonEngine::Outputs rich = engine.evaluate(in);
  EXPECT_GT(rich.fuel_air_ratio, 0.1);  // full rich enriches with altitude: sqrt(1/sigma)
  EXPECT_NEAR(rich.fuel_air_ratio, 0.088 / std::sqrt(in.ambient_density_kgpm3 / 1.225), 1e-12);
  EXPECT_GT(best_power_w(engine, in), 1.05 * rich.brake_power_w);  // leaning pays at 10000 ft
  in.mixture = 0.0;                                                // idle cut-off detent: no fuel
  const PistonEngine::Outputs cut = engine.evaluate(in);
  EXPECT_EQ(cut.combustion_torque_nm, 0.0);
  EXPECT_EQ(cut.fuel_flow_kgps, 0.0);
  EXPECT_LT(cut.brake_power_w, 0.0);
  // Just above the detent at sea level: 0.088 / 2 = 0.044, leaner than the misfire limit.
  in = full_throttle(2400.0, isa(0.0));
  in.mixture = 0.05;
  const PistonEngine::Outputs lean = engine.evaluate(in);
  EXPECT_NEAR(lean.fuel_air_ratio, 0.088 / (2.0 - 0.0025), 1e-6);
  EXPECT_EQ(lean.combustion_torque_nm, 0.0);
  EXPECT_GT(lean.fuel_flow_kgps, 0.0);  // fuel still flows
}

TEST(PistonEngine, FailureOrShutdownKillsCombustionButNotLosses) {
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(2000.0, isa(0.0));
  in.failed = true;
  PistonEngine::Outputs out = engine.evaluate(in);
  EXPECT_EQ(out.combustion_torque_nm, 0.0);
  EXPECT_EQ(out.fuel_flow_kgps, 0.0);
  EXPECT_GT(out.loss_torque_nm, 0.0);
  EXPECT_LT(out.brake_power_w, 0.0);  // a windmilled engine absorbs power
  in.failed = false;
  in.running = false;
  out = engine.evaluate(in);
  EXPECT_EQ(out.combustion_torque_nm, 0.0);
  EXPECT_EQ(out.fuel_flow_kgps, 0.0);
}

TEST(PistonEngine, FuelFlowScalesWithMixtureAndAirFlow) {
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(2700.0, isa(0.0));
  const PistonEngine::Outputs rich = engine.evaluate(in);
  // Full rich at the rated point: bsfc * P_rated * (0.088 / 0.080).
  const double rated_flow = 0.50 * reference::kLb / (kHp * 3600.0) * 160.0 * kHp;
  EXPECT_NEAR(rich.fuel_flow_kgps / (rated_flow * 0.088 / 0.080), 1.0, 1e-7);
  in.engine_rpm = 1350.0;  // half the air at half the speed (MAP nearly unchanged)
  const PistonEngine::Outputs half = engine.evaluate(in);
  const double map_ratio = half.manifold_pressure_pa / rich.manifold_pressure_pa;
  EXPECT_NEAR(half.fuel_flow_kgps, 0.5 * map_ratio * rich.fuel_flow_kgps, 1e-12);
}

TEST(PistonEngine, ExhaustGasTemperatureByHandAtFullRichSeaLevel) {
  // Hand calculation of the exhaust energy balance (JSBSim FGPiston figures):
  //   full rich in sea-level air: F/A = 0.088, equivalence ratio phi = 0.088 x 14.7 = 1.2936;
  //   combustion efficiency between 0.79 (phi 1.2) and 0.70 (phi 1.3): 0.70576;
  //   heat into the exhaust per kg of air: 0.088 x 47.3e6 x 0.70576 x 0.30 = 881 299 J;
  //   heat capacity per kg of air: 1005 + 1700 x 0.088 = 1154.6 J/K;
  //   rise 763.29 K, EGT = 288.15 + 763.29 = 1051.44 K (778 C, 1433 F).
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(2400.0, isa(0.0));
  const PistonEngine::Outputs full = engine.evaluate(in);
  EXPECT_NEAR(full.exhaust_gas_temperature_k, 1051.44, 0.01);
  // The balance holds per kg of air, so EGT does not depend on the power at this mixture.
  in.throttle = 0.0;
  in.engine_rpm = 800.0;
  EXPECT_NEAR(engine.evaluate(in).exhaust_gas_temperature_k, 1051.44, 0.01);

  // Leaning, the rise per kg of air F/A x eta_c(phi) is largest at phi = 1.05 (F/A 0.071429,
  // efficiency 0.95; richer, the efficiency falls faster than F/A grows, leaner, F/A falls
  // faster): 0.071429 x 47.3e6 x 0.95 x 0.30 / (1005 + 1700 x 0.071429) = 854.82 K rise,
  // 1142.97 K (1598 F: the "peak EGT" a pilot leans to, just rich of stoichiometric).
  in = full_throttle(2400.0, isa(0.0));
  double peak_k = 0.0, peak_fa = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    in.mixture = i / 2000.0;
    const PistonEngine::Outputs out = engine.evaluate(in);
    if (out.exhaust_gas_temperature_k > peak_k) {
      peak_k = out.exhaust_gas_temperature_k;
      peak_fa = out.fuel_air_ratio;
    }
  }
  EXPECT_NEAR(peak_k, 1142.97, 0.5);
  EXPECT_NEAR(peak_fa, 1.05 / 14.7, 0.0005);

  // Not burning: ambient temperature, whatever the shaft does.
  in = full_throttle(2400.0, isa(2000.0));
  in.running = false;
  EXPECT_EQ(engine.evaluate(in).exhaust_gas_temperature_k, isa(2000.0).temperature_k);
  in.running = true;
  in.mixture = 0.0;  // idle cut-off
  EXPECT_EQ(engine.evaluate(in).exhaust_gas_temperature_k, isa(2000.0).temperature_k);
  in = full_throttle(0.0, isa(0.0));  // stopped shaft: no air through the engine
  EXPECT_EQ(engine.evaluate(in).exhaust_gas_temperature_k, 288.15);
}

TEST(PistonEngine, StandstillIsFinite) {
  const PistonEngine engine(reference::io320());
  PistonEngine::Inputs in = full_throttle(0.0, isa(0.0));
  const PistonEngine::Outputs out = engine.evaluate(in);
  EXPECT_TRUE(std::isfinite(out.combustion_torque_nm));
  EXPECT_TRUE(std::isfinite(out.loss_torque_nm));
  EXPECT_EQ(out.brake_power_w, 0.0);
  EXPECT_EQ(out.fuel_flow_kgps, 0.0);
}

TEST(PistonEngine, ValidateNamesTheBadField) {
  PistonEngine::Params p = reference::io320();
  p.rated_rpm = -1.0;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rated_rpm"), std::string::npos) << e.what();
  }
  p = reference::io320();
  p.idle_manifold_pressure_pa = 200000.0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
