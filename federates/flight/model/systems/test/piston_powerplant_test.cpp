// Tests of the piston engine + propeller installation: static and in-flight operating points,
// windmilling, standstill, the constant-speed governor and the moments on the airframe.
#include "flight/model/systems/piston_powerplant.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "flight/model/systems/test/reference_data.hpp"

namespace fedsim::flight {
namespace {

using reference::kDeg;
using reference::kHp;

PistonPowerplant::Inputs at_airspeed(double tas_mps, double throttle = 1.0) {
  PistonPowerplant::Inputs in;
  in.throttle = throttle;
  in.air_velocity_body_mps = Eigen::Vector3d(tas_mps, 0.0, 0.0);
  return in;
}

void run(PistonPowerplant& pp, const PistonPowerplant::Inputs& in, double seconds, double dt_s) {
  const int steps = static_cast<int>(std::lround(seconds / dt_s));
  for (int i = 0; i < steps; ++i) pp.step(dt_s, in);
}

// Hamilton Standard 6243A-3 constant-speed propeller coefficients (JSBSim
// engine/HamiltonStd6243A-3.xml: J 0..2, blade angle 10 and 30 deg), geometrically scaled to
// an 84-inch disc (CT and CP are non-dimensional) so that the IO-320 governs within 10..30 deg.
PistonPowerplant::Params constant_speed_installation() {
  PistonPowerplant::Params p = reference::c172_powerplant();
  const std::vector<double> j = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7,
                                 0.8, 0.9, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0};
  const std::vector<double> ct10 = {0.06739, 0.06674, 0.06610, 0.06545, 0.05963, 0.01771,
                                    0.01512, 0.01176, 0.00864, 0.00480, 0.00096, 0.0,
                                    0.0,     0.0,     0.0,     0.0};
  const std::vector<double> ct30 = {0.0842, 0.0838, 0.0834, 0.0830, 0.0826, 0.0822, 0.0818, 0.0782,
                                    0.0745, 0.0705, 0.0664, 0.0567, 0.0441, 0.0324, 0.0180, 0.0036};
  const std::vector<double> cp10 = {0.01144, 0.01126, 0.01109, 0.01074, 0.01040, 0.01005,
                                    0.00953, 0.00832, 0.00658, 0.00433, 0.00173, 0.0,
                                    0.0,     0.0,     0.0,     0.0};
  const std::vector<double> cp30 = {0.05198, 0.05159, 0.05119, 0.05080, 0.05040, 0.04962,
                                    0.04883, 0.04804, 0.04725, 0.04647, 0.04568, 0.04331,
                                    0.03780, 0.02993, 0.01969, 0.00788};
  std::vector<double> ct, cp;
  for (std::size_t i = 0; i < j.size(); ++i) {
    ct.insert(ct.end(), {ct10[i], ct30[i]});
    cp.insert(cp.end(), {cp10[i], cp30[i]});
  }
  p.propeller.diameter_m = 84.0 * reference::kIn;
  p.propeller.thrust_coefficient = Table2D(j, {10.0 * kDeg, 30.0 * kDeg}, ct);
  p.propeller.power_coefficient = Table2D(j, {10.0 * kDeg, 30.0 * kDeg}, cp);
  p.propeller.thrust_tip_mach_factor = Table1D();
  p.propeller.power_tip_mach_factor = Table1D();
  p.governor.constant_speed = true;
  p.governor.fine_pitch_rad = 10.0 * kDeg;
  p.governor.coarse_pitch_rad = 30.0 * kDeg;
  p.governor.feather_pitch_rad = 85.0 * kDeg;
  p.governor.governor_max_rpm = 2700.0;
  p.governor.governor_min_rpm = 1800.0;
  return p;
}

TEST(PistonPowerplant, SeaLevelStaticFullThrottleIsPlausibleForAnIo320) {
  // C172 with a 160 hp O-320 class engine and fixed-pitch propeller: static rpm about
  // 2200-2400, well under the 2700 rpm rating; static thrust around 1.5-2 kN.
  for (double dt : {0.02, 0.0025}) {
    PistonPowerplant pp(reference::c172_powerplant());
    pp.reset(800.0);
    run(pp, at_airspeed(0.0), 20.0, dt);
    const PistonPowerplant::Outputs& out = pp.outputs();
    EXPECT_GT(out.engine_rpm, 2100.0);
    EXPECT_LT(out.engine_rpm, 2450.0);
    EXPECT_GT(out.brake_power_w / kHp, 120.0);
    EXPECT_LT(out.brake_power_w / kHp, 160.0);
    EXPECT_GT(out.thrust_n, 1300.0);
    EXPECT_LT(out.thrust_n, 2200.0);
    // Torque balance at steady state: the propeller absorbs the brake power.
    const double shaft_power_w =
        out.propeller_torque_nm * out.propeller_rpm * 2.0 * std::numbers::pi / 60.0;
    EXPECT_NEAR(shaft_power_w / out.brake_power_w, 1.0, 0.005);
    const double gallons_per_hour = out.fuel_flow_kgps * 3600.0 / 0.72 / 3.785;  // avgas
    EXPECT_GT(gallons_per_hour, 8.0);
    EXPECT_LT(gallons_per_hour, 16.0);
  }
}

TEST(PistonPowerplant, ThrustFallsOffAtHighAirspeed) {
  PistonPowerplant pp(reference::c172_powerplant());
  pp.reset(2000.0);
  run(pp, at_airspeed(0.0), 20.0, 0.02);
  const double static_thrust = pp.outputs().thrust_n;
  double previous = 1e9;
  double previous_rpm = 0.0;
  for (double v = 40.0; v <= 80.0; v += 10.0) {
    run(pp, at_airspeed(v), 20.0, 0.02);
    EXPECT_LT(pp.outputs().thrust_n, previous) << v << " m/s";
    EXPECT_GT(pp.outputs().engine_rpm, previous_rpm);  // fixed pitch: unloads with speed
    previous = pp.outputs().thrust_n;
    previous_rpm = pp.outputs().engine_rpm;
  }
  EXPECT_LT(previous, 0.95 * static_thrust);
}

TEST(PistonPowerplant, StaticPowerAndThrustLapseWithAltitude) {
  PistonPowerplant pp(reference::c172_powerplant());
  pp.reset(2000.0);
  run(pp, at_airspeed(0.0), 20.0, 0.02);
  const PistonPowerplant::Outputs sea_level = pp.outputs();
  PistonPowerplant::Inputs high = at_airspeed(0.0);
  // ISA 8000 ft: 75.26 kPa, 272.3 K, 0.9629 kg/m^3.
  high.pressure_pa = 75263.0;
  high.temperature_k = 272.30;
  high.density_kgpm3 = 0.96287;
  run(pp, high, 20.0, 0.02);
  EXPECT_LT(pp.outputs().brake_power_w, 0.85 * sea_level.brake_power_w);
  EXPECT_LT(pp.outputs().thrust_n, 0.85 * sea_level.thrust_n);
  EXPECT_LT(pp.outputs().engine_rpm, sea_level.engine_rpm);
}

TEST(PistonPowerplant, FailedEngineWindmillsToDragNotThrust) {
  for (double v : {30.0, 50.0, 70.0}) {
    PistonPowerplant pp(reference::c172_powerplant());
    pp.reset(2400.0);
    PistonPowerplant::Inputs in = at_airspeed(v);
    in.failed = true;
    run(pp, in, 60.0, 0.02);
    const PistonPowerplant::Outputs& out = pp.outputs();
    EXPECT_LT(out.thrust_n, 0.0) << v << " m/s";
    EXPECT_LT(out.force_body_n.x(), 0.0);
    EXPECT_EQ(out.fuel_flow_kgps, 0.0);
    EXPECT_TRUE(std::isfinite(out.engine_rpm));
    EXPECT_LT(out.engine_rpm, 2400.0);
  }
}

TEST(PistonPowerplant, StandstillAndStartAreFinite) {
  PistonPowerplant pp(reference::c172_powerplant());
  pp.reset(0.0);
  PistonPowerplant::Inputs off = at_airspeed(0.0, 0.0);
  off.running = false;
  run(pp, off, 5.0, 0.02);
  EXPECT_EQ(pp.outputs().engine_rpm, 0.0);  // friction holds a stopped engine
  EXPECT_EQ(pp.outputs().thrust_n, 0.0);
  EXPECT_TRUE(pp.outputs().moment_datum_body_nm.allFinite());
  // Running flag on at zero rpm: the engine picks up and settles at idle (no starter model).
  PistonPowerplant::Inputs idle = at_airspeed(0.0, 0.0);
  run(pp, idle, 30.0, 0.02);
  EXPECT_GT(pp.outputs().engine_rpm, 500.0);
  EXPECT_LT(pp.outputs().engine_rpm, 1000.0);
  EXPECT_TRUE(pp.outputs().force_body_n.allFinite());
}

TEST(PistonPowerplant, ForceActsAlongTheThrustLineAndTorqueRollsAgainstRotation) {
  PistonPowerplant::Params params = reference::c172_powerplant();
  params.thrust_line.pitch_rad = 2.0 * kDeg;
  PistonPowerplant pp(params);
  pp.reset(2000.0);
  run(pp, at_airspeed(0.0), 10.0, 0.02);
  const PistonPowerplant::Outputs& out = pp.outputs();
  const Eigen::Vector3d axis = params.thrust_line.axis_body();
  EXPECT_NEAR(out.force_body_n.dot(axis), out.thrust_n, 1e-9);
  EXPECT_NEAR(out.force_body_n.cross(axis).norm(), 0.0, 1e-9);
  EXPECT_LT(out.force_body_n.z(), 0.0);  // nose-up thrust line pushes up
  const Eigen::Vector3d reaction =
      out.moment_datum_body_nm - params.thrust_line.position_m.cross(out.force_body_n);
  // Clockwise-from-behind propeller: the air's torque rolls the aircraft left (negative).
  EXPECT_NEAR(reaction.dot(axis), -out.propeller_torque_nm, 1e-9);
  EXPECT_LT(reaction.x(), 0.0);
  EXPECT_NEAR(out.rotor_angular_momentum_body_kgm2ps.dot(axis),
              params.shaft_inertia_kgm2 * out.propeller_rpm * 2.0 * std::numbers::pi / 60.0, 1e-9);

  params.rotation_sense = -1;
  PistonPowerplant left_hand(params);
  left_hand.reset(2000.0);
  run(left_hand, at_airspeed(0.0), 10.0, 0.02);
  const Eigen::Vector3d reaction_lh =
      left_hand.outputs().moment_datum_body_nm -
      params.thrust_line.position_m.cross(left_hand.outputs().force_body_n);
  EXPECT_GT(reaction_lh.x(), 0.0);
}

TEST(PistonPowerplant, GovernorHoldsSelectedRpmAcrossAirspeedAndPower) {
  const double lever_2400 = std::sqrt(2400.0 / 2700.0);  // eq. 3.113: 2700 pl^2
  for (double dt : {0.02, 0.0025}) {
    PistonPowerplant pp(constant_speed_installation());
    pp.reset(2000.0);
    for (double throttle : {1.0, 0.9}) {
      for (double v : {0.0, 30.0, 60.0, 80.0}) {
        PistonPowerplant::Inputs in = at_airspeed(v, throttle);
        in.propeller_lever = lever_2400;
        run(pp, in, 20.0, dt);
        EXPECT_NEAR(pp.outputs().selected_rpm, 2400.0, 1e-9);
        EXPECT_NEAR(pp.outputs().engine_rpm, 2400.0, 5.0) << "v " << v << " tl " << throttle;
        EXPECT_GT(pp.outputs().blade_angle_rad, 10.0 * kDeg);
        EXPECT_LT(pp.outputs().blade_angle_rad, 30.0 * kDeg);
      }
    }
  }
}

TEST(PistonPowerplant, GovernorFollowsLeverAndRestsOnFineStopWithoutPower) {
  PistonPowerplant pp(constant_speed_installation());
  pp.reset(2400.0);
  PistonPowerplant::Inputs in = at_airspeed(50.0);
  in.propeller_lever = std::sqrt(2400.0 / 2700.0);
  run(pp, in, 20.0, 0.02);
  const double beta_2400 = pp.outputs().blade_angle_rad;
  in.propeller_lever = std::sqrt(2100.0 / 2700.0);
  run(pp, in, 10.0, 0.02);
  EXPECT_NEAR(pp.outputs().engine_rpm, 2100.0, 5.0);
  EXPECT_GT(pp.outputs().blade_angle_rad, beta_2400);  // lower rpm, coarser blades
  // Throttle closed at low speed: not enough power for 2100 rpm, blades go to the fine stop.
  PistonPowerplant::Inputs idle = at_airspeed(20.0, 0.0);
  idle.propeller_lever = in.propeller_lever;
  run(pp, idle, 20.0, 0.02);
  EXPECT_LT(pp.outputs().engine_rpm, 2000.0);
  EXPECT_NEAR(pp.outputs().blade_angle_rad, 10.0 * kDeg, 1e-12);
}

TEST(PistonPowerplant, FeatheringStopsAFailedEngine) {
  PistonPowerplant pp(constant_speed_installation());
  pp.reset(2400.0);
  PistonPowerplant::Inputs in = at_airspeed(50.0);
  in.propeller_lever = std::sqrt(2400.0 / 2700.0);
  run(pp, in, 10.0, 0.02);
  in.failed = true;
  in.feather = true;
  run(pp, in, 30.0, 0.02);
  EXPECT_NEAR(pp.outputs().blade_angle_rad, 85.0 * kDeg, 1e-12);
  EXPECT_EQ(pp.outputs().engine_rpm, 0.0);
  EXPECT_TRUE(pp.outputs().force_body_n.allFinite());
  in.feather = false;  // unfeathering returns the blades into the governed range
  run(pp, in, 10.0, 0.02);
  EXPECT_LE(pp.outputs().blade_angle_rad, 30.0 * kDeg + 1e-12);
}

TEST(PistonPowerplant, ValidatePrefixesTheSubModel) {
  PistonPowerplant::Params p = reference::c172_powerplant();
  p.engine.rated_rpm = 0.0;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("engine.rated_rpm"), std::string::npos) << e.what();
  }
  p = reference::c172_powerplant();
  p.rotation_sense = 0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = reference::c172_powerplant();
  p.shaft_inertia_kgm2 = 0.0;
  EXPECT_THROW(PistonPowerplant{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
