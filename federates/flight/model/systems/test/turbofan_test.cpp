// Tests of the turbofan model with CFM56 figures: static thrust, lapse, idle, spool dynamics,
// fuel flow, failure and the moment of an off-centre engine.
#include "flight/model/systems/turbofan.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "flight/model/systems/test/reference_data.hpp"

namespace fedsim::flight {
namespace {

using reference::kFt;
using reference::kLbf;

// ISA density and temperature at a geopotential altitude (troposphere and lower stratosphere).
struct Air {
  double density_kgpm3, temperature_k;
};
Air isa(double altitude_m) {
  const double exponent = units::kStandardGravityMps2 / (0.0065 * 287.05287) - 1.0;  // g / (L R) - 1
  if (altitude_m <= 11000.0) {
    const double t = 288.15 - 0.0065 * altitude_m;
    return {1.225 * std::pow(t / 288.15, exponent), t};
  }
  const double rho11 = 1.225 * std::pow(216.65 / 288.15, exponent);
  return {rho11 * std::exp(-units::kStandardGravityMps2 * (altitude_m - 11000.0) / (287.05287 * 216.65)), 216.65};
}

Turbofan::Inputs flight(double throttle, double mach, double altitude_m) {
  const Air air = isa(altitude_m);
  Turbofan::Inputs in;
  in.throttle = throttle;
  in.mach = mach;
  in.density_kgpm3 = air.density_kgpm3;
  in.temperature_k = air.temperature_k;
  return in;
}

void run(Turbofan& engine, const Turbofan::Inputs& in, double seconds, double dt_s = 0.02) {
  const int steps = static_cast<int>(std::lround(seconds / dt_s));
  for (int i = 0; i < steps; ++i) engine.step(dt_s, in);
}

TEST(Turbofan, DensityAltitudeInvertsTheStandardAtmosphere) {
  for (double h : {-1000.0, 0.0, 3000.0, 9144.0, 11000.0, 15000.0, 20000.0}) {
    EXPECT_NEAR(Turbofan::density_altitude_m(isa(h).density_kgpm3), h, 1e-6) << h;
  }
}

TEST(Turbofan, SeaLevelStaticMaximumIsTheRatedThrust) {
  Turbofan engine(reference::cfm56());
  run(engine, flight(1.0, 0.0, 0.0), 30.0);
  EXPECT_NEAR(engine.outputs().n1_pct, 100.0, 1e-6);
  EXPECT_NEAR(engine.outputs().n2_pct, 100.0, 1e-6);
  EXPECT_NEAR(engine.outputs().thrust_n, 20000.0 * kLbf, 0.001 * 20000.0 * kLbf);  // 88.96 kN
}

TEST(Turbofan, IdleThrustFollowsTheIdleTable) {
  Turbofan engine(reference::cfm56());
  run(engine, flight(0.0, 0.0, 0.0), 10.0);
  EXPECT_NEAR(engine.outputs().n1_pct, 30.0, 1e-9);
  EXPECT_NEAR(engine.outputs().thrust_n, 0.0436 * 20000.0 * kLbf, 1e-6);  // 3.88 kN
  run(engine, flight(0.0, 0.8, 30000.0 * kFt), 1.0);
  EXPECT_NEAR(engine.outputs().thrust_n, 0.0174 * 20000.0 * kLbf, 1e-3);
}

TEST(Turbofan, MaximumThrustLapsesWithAltitudeAndMach) {
  Turbofan engine(reference::cfm56());
  run(engine, flight(1.0, 0.0, 0.0), 30.0);
  struct Point {
    double mach, altitude_ft, fraction;
  };
  for (const Point& pt : {Point{0.8, 30000.0, 0.417}, Point{0.4, 10000.0, 0.692},
                          Point{0.2, 0.0, 0.934}, Point{0.8, 40000.0, 0.275},
                          Point{0.7, 35000.0, 0.5 * (0.3780 + 0.4170 + 0.2480 + 0.2750) / 2.0}}) {
    run(engine, flight(1.0, pt.mach, pt.altitude_ft * kFt), 0.1);
    EXPECT_NEAR(engine.outputs().thrust_n / (20000.0 * kLbf), pt.fraction, 1e-6)
        << "M " << pt.mach << " at " << pt.altitude_ft << " ft";
    EXPECT_NEAR(engine.outputs().density_altitude_m, pt.altitude_ft * kFt, 1e-6);
  }
}

TEST(Turbofan, SpoolsFollowFirstOrderLagsWithSeparateUpAndDownRates) {
  const Turbofan::Params p = reference::cfm56();
  for (double dt : {0.02, 0.0025}) {
    Turbofan engine(p);
    run(engine, flight(1.0, 0.0, 0.0), p.n1_spool_up_time_constant_s, dt);
    EXPECT_NEAR(engine.outputs().n1_pct, 30.0 + 70.0 * (1.0 - std::exp(-1.0)), 1e-6);
    engine.reset();
    run(engine, flight(1.0, 0.0, 0.0), p.n2_spool_up_time_constant_s, dt);
    EXPECT_NEAR(engine.outputs().n2_pct, 60.0 + 40.0 * (1.0 - std::exp(-1.0)), 1e-6);
    run(engine, flight(1.0, 0.0, 0.0), 30.0, dt);
    run(engine, flight(0.0, 0.0, 0.0), p.n1_spool_down_time_constant_s, dt);
    EXPECT_NEAR(engine.outputs().n1_pct, 100.0 - 70.0 * (1.0 - std::exp(-1.0)), 1e-6);
  }
  EXPECT_LT(p.n1_spool_down_time_constant_s, p.n1_spool_up_time_constant_s);
}

TEST(Turbofan, FlightIdleToGoAroundThrustWithinFiveSeconds) {
  // 14 CFR 33.73: flight idle to 95 % of rated take-off thrust in not more than 5 s.
  Turbofan engine(reference::cfm56());
  const double target = 0.95 * 20000.0 * kLbf;
  double t = 0.0;
  while (engine.outputs().thrust_n < target && t < 20.0) {
    engine.step(0.01, flight(1.0, 0.0, 0.0));
    t += 0.01;
  }
  EXPECT_LE(t, 5.0);
  EXPECT_GT(t, 3.0);  // a turbofan takes seconds, not a moment
}

TEST(Turbofan, FuelFlowIsTsfcTimesThrust) {
  Turbofan engine(reference::cfm56());
  run(engine, flight(1.0, 0.0, 0.0), 30.0);
  const double tsfc = 0.657 * reference::kLb / (kLbf * 3600.0);
  EXPECT_NEAR(engine.outputs().fuel_flow_kgps, tsfc * engine.outputs().thrust_n, 1e-12);
  EXPECT_NEAR(engine.outputs().fuel_flow_kgps, 1.656, 0.01);  // 13 140 lb/h
  Turbofan::Params p = reference::cfm56();
  p.tsfc_per_mach = 1.0;
  Turbofan cruise(p);
  run(cruise, flight(1.0, 0.8, 35000.0 * kFt), 30.0);
  const double theta = isa(35000.0 * kFt).temperature_k / 288.15;
  EXPECT_NEAR(cruise.outputs().fuel_flow_kgps,
              tsfc * 1.8 * std::sqrt(theta) * cruise.outputs().thrust_n, 1e-12);
}

TEST(Turbofan, FailureSpoolsDownAndRemovesThrustAndFuel) {
  Turbofan engine(reference::cfm56());
  run(engine, flight(1.0, 0.0, 0.0), 30.0);
  Turbofan::Inputs in = flight(1.0, 0.0, 0.0);
  in.failed = true;
  engine.step(0.02, in);
  EXPECT_EQ(engine.outputs().fuel_flow_kgps, 0.0);
  run(engine, in, 20.0);
  EXPECT_LT(engine.outputs().n1_pct, 0.1);
  EXPECT_LT(engine.outputs().thrust_n, 1.0);
  EXPECT_GE(engine.outputs().thrust_n, 0.0);
  engine.reset(false);
  EXPECT_EQ(engine.outputs().n1_pct, 0.0);
  EXPECT_EQ(engine.outputs().thrust_n, 0.0);
}

TEST(Turbofan, ExhaustGasTemperatureFromIdleToTakeOffAndAmbientWhenStopped) {
  // CFM56 figures at sea level ISA: about 400 C at ground idle, 930 C (the CFM56-3's take-off
  // limit) at maximum N2; linear in N2 between them.
  Turbofan engine(reference::cfm56());
  run(engine, flight(0.0, 0.0, 0.0), 30.0);
  EXPECT_NEAR(engine.outputs().exhaust_gas_temperature_k - 273.15, 400.0, 0.5);
  run(engine, flight(1.0, 0.0, 0.0), 30.0);
  EXPECT_NEAR(engine.outputs().exhaust_gas_temperature_k - 273.15, 930.0, 0.5);
  // Half way in N2 (80 %), half way in EGT rise above ambient: (400 + 930) / 2 = 665 C.
  run(engine, flight(0.5, 0.0, 0.0), 30.0);
  EXPECT_NEAR(engine.outputs().n2_pct, 80.0, 0.01);
  EXPECT_NEAR(engine.outputs().exhaust_gas_temperature_k - 273.15, 665.0, 0.5);
  // At FL300 (228.7 K) the same N2 runs 59.5 K cooler: EGT rides on the ambient temperature.
  const Air fl300 = isa(30000.0 * kFt);
  run(engine, flight(0.5, 0.78, 30000.0 * kFt), 30.0);
  EXPECT_NEAR(engine.outputs().exhaust_gas_temperature_k - 273.15,
              665.0 - (288.15 - fl300.temperature_k), 0.5);
  // Shut down: ambient temperature at once (no thermal lag is modelled).
  Turbofan::Inputs off = flight(0.0, 0.0, 0.0);
  off.running = false;
  engine.step(0.02, off);
  EXPECT_EQ(engine.outputs().exhaust_gas_temperature_k, 288.15);
}

TEST(Turbofan, OffCentreEngineYawsTowardTheOtherSide) {
  Turbofan engine(reference::cfm56());  // left engine, y = -4.9 m
  run(engine, flight(1.0, 0.0, 0.0), 30.0);
  const Turbofan::Outputs& out = engine.outputs();
  const Eigen::Vector3d r = reference::cfm56().thrust_line.position_m;
  EXPECT_NEAR(out.force_body_n.x(), out.thrust_n, 1e-9);
  EXPECT_NEAR((out.moment_datum_body_nm - r.cross(out.force_body_n)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(out.moment_datum_body_nm.z(), -r.y() * out.thrust_n, 1e-6);
  EXPECT_GT(out.moment_datum_body_nm.z(), 0.0);  // left engine alone: nose right
}

TEST(Turbofan, ValidateNamesTheBadField) {
  Turbofan::Params p = reference::cfm56();
  p.n1_spool_up_time_constant_s = 0.0;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("n1_spool_up_time_constant_s"), std::string::npos);
  }
  p = reference::cfm56();
  p.max_n1_pct = 20.0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
