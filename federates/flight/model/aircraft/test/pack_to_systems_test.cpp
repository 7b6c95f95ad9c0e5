// Tests that the shipped packs fill the systems models' Params and that the models built from
// them reproduce pack figures (loaded mass, static thrust, surface travel).
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"
#include "common/units/units.hpp"

#include <array>
#include <cmath>
#include <string>

#include "flight/model/aircraft/pack_to_systems.hpp"

namespace fedsim::flight {
namespace {

constexpr double kLb = 0.45359237;
constexpr double kLbf = 4.4482216152605;
constexpr double kDeg = units::kDegToRad;

AircraftPack pack(const std::string& name) {
  return load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/" + name);
}

TEST(PackToSystems, C172LoadedMassIsTheMaximumGrossWeight) {
  // c172x.xml: 1454 lb empty + 686 lb of occupants and luggage + 2 x 130 lb of fuel = 2400 lb,
  // the C172P's maximum take-off weight.
  const AircraftPack p = pack("c172.yaml");
  MassBalance mass(mass_balance_params(p.mass, p.engines));
  EXPECT_NEAR(mass.outputs().mass_kg, 2400.0 * kLb, 1e-6);
  EXPECT_NEAR(mass.outputs().fuel_kg, 260.0 * kLb, 1e-6);
  // Loaded CG station from the c172x.xml masses and stations (inches aft of its origin):
  // (1454*41 + 330*36 + 236*60 + 120*95 + 260*48) / 2400 = 45.64 in.
  const double cg_in = (1454.0 * 41 + 330.0 * 36 + 236.0 * 60 + 120.0 * 95 + 260.0 * 48) / 2400.0;
  EXPECT_NEAR(mass.outputs().cg_m.x(), -cg_in * 0.0254, 1e-9);
  EXPECT_GT(mass.outputs().inertia_kgm2(0, 0), p.mass.empty_inertia.ixx_kgm2);
}

TEST(PackToSystems, B737TurbofansGiveTheirRatedStaticThrust) {
  const AircraftPack p = pack("b737.yaml");
  ASSERT_EQ(p.engines.size(), 2u);
  for (const EngineSpec& e : p.engines) {
    Turbofan engine(turbofan_params(e));
    Turbofan::Inputs in;  // sea-level standard, static
    in.throttle = 1.0;
    for (int i = 0; i < 3000; ++i) engine.step(0.01, in);
    // MilThrust table is 1.0 at Mach 0 and density altitude 0: 20000 lbf.
    EXPECT_NEAR(engine.outputs().thrust_n, 20000.0 * kLbf, 1e-3 * 20000.0 * kLbf);
    EXPECT_NEAR(engine.outputs().n1_pct, 100.0, 0.01);
    EXPECT_GT(engine.outputs().force_body_n.x(), 0.0);
  }
}

TEST(PackToSystems, C172PowerplantAndGearBuild) {
  const AircraftPack p = pack("c172.yaml");
  const PistonPowerplant::Params prop = piston_powerplant_params(p.engines[0]);
  EXPECT_FALSE(prop.governor.constant_speed);  // 22 deg fixed pitch
  EXPECT_NEAR(prop.governor.fine_pitch_rad, 22.0 * kDeg, 1e-12);
  EXPECT_EQ(prop.propeller.thrust_coefficient.cols().size(), 1u);
  EXPECT_EQ(prop.rotation_sense, -1);
  EXPECT_NO_THROW(PistonPowerplant{prop});
  EXPECT_THROW(turbofan_params(p.engines[0]), std::invalid_argument);
  // The propeller's constant CT and CP factors reach the model unchanged.
  AircraftPack factored = p;
  factored.engines[0].propeller.thrust_coefficient_factor = 1.1;
  factored.engines[0].propeller.power_coefficient_factor = 0.9;
  const PistonPowerplant::Params with_factors = piston_powerplant_params(factored.engines[0]);
  EXPECT_EQ(with_factors.propeller.thrust_coefficient_factor, 1.1);
  EXPECT_EQ(with_factors.propeller.power_coefficient_factor, 0.9);

  const LandingGear::Params gear = landing_gear_params(p.landing_gear);
  ASSERT_EQ(gear.contacts.size(), 6u);
  EXPECT_EQ(gear.contacts[1].brake_group, LandingGear::BrakeGroup::kLeft);
  EXPECT_EQ(gear.contacts[5].type, LandingGear::ContactType::kStructure);
  EXPECT_NO_THROW(LandingGear{gear});
}

TEST(PackToSystems, SurfaceActuatorsReachThePackTravel) {
  const AircraftPack p = pack("c172.yaml");
  Actuator elevator(actuator_params(*p.flight_controls.elevator));
  for (int i = 0; i < 200; ++i) elevator.step(0.01, {1.0});
  EXPECT_NEAR(elevator.outputs().position_rad, 0.34, 1e-9);  // JSBSim clip, not 23 deg
  for (int i = 0; i < 200; ++i) elevator.step(0.01, {0.5});
  EXPECT_NEAR(elevator.outputs().position_rad, 0.5 * 23.0 * 0.01745, 1e-6);

  // Flaps: 0..30 deg in 4 s (JSBSim 2 + 1 + 1 s), one average rate.
  const Actuator::Params flap_params = kinematic_actuator_params(*p.flight_controls.flaps);
  EXPECT_NEAR(flap_params.rate_limit_radps, 30.0 * kDeg / 4.0, 1e-12);
  Actuator flaps(flap_params);
  for (int i = 0; i < 100; ++i) flaps.step(0.01, {1.0});
  EXPECT_NEAR(flaps.outputs().position_rad, 7.5 * kDeg, 1e-9);  // after 1 s
}

TEST(PackToSystems, NasaBodiesHaveOnlyMass) {
  const AircraftPack p = pack("nasa_brick.yaml");
  MassBalance mass(mass_balance_params(p.mass, p.engines));
  EXPECT_NEAR(mass.outputs().mass_kg, 0.155404754 * 14.5939029372, 1e-8);
  EXPECT_NEAR(mass.outputs().inertia_kgm2(2, 2), p.mass.empty_inertia.izz_kgm2, 1e-15);
  EXPECT_TRUE(landing_gear_params(p.landing_gear).contacts.empty());
}

}  // namespace
}  // namespace fedsim::flight
