// Tests of the aircraft-pack loader: the shipped packs load with the JSBSim/NASA figures
// converted to SI, and every deliberately broken pack fails at the right file, line and field.
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/util/config_node.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

namespace fedsim::flight {
namespace {

namespace fs = std::filesystem;

// Unit factors, written out so the test does not share the loader's constants.
constexpr double kIn = 0.0254;
constexpr double kFt = units::kFtToM;
constexpr double kLb = 0.45359237;
constexpr double kSlugFt2 = 14.5939029372 * kFt * kFt;
constexpr double kLbfPerFtToNPerM = 4.4482216152605 / kFt;
constexpr double kDeg = units::kDegToRad;

std::string data_pack(const std::string& name) {
  return fedsim::util::data_dir() + "/aircraft/" + name;
}
std::string test_data(const std::string& name) {
  return fedsim::util::test_data_dir() + "/aircraft/" + name;
}

// JSBSim structural (x aft, y right, z up), inches -> pack frame metres.
Eigen::Vector3d from_structural_in(double x, double y, double z) {
  return Eigen::Vector3d(-x * kIn, y * kIn, -z * kIn);
}

// The packs print 10 significant digits: compare relative to the expected figure.
void expect_rel(double actual, double expected, double relative = 1e-9) {
  EXPECT_NEAR(actual, expected, relative * std::abs(expected));
}

void expect_vector_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected,
                        double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
  EXPECT_NEAR(actual.z(), expected.z(), tolerance);
}

TEST(AircraftPackLoader, EveryShippedPackLoads) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fedsim::util::data_dir() + "/aircraft")) {
    if (entry.path().extension() != ".yaml") continue;
    if (entry.path().string().ends_with(".calibration.yaml")) continue;  // overlays, not packs
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(load_aircraft_pack(entry.path().string()));
    ++count;
  }
  EXPECT_GE(count, 6);  // c172, b737, two spheres, two bricks
}

TEST(AircraftPackLoader, MinimalPackHasEverySection) {
  const AircraftPack pack = load_aircraft_pack(test_data("minimal_pack.yaml"));
  EXPECT_EQ(pack.metadata.name, "test glider");
  EXPECT_EQ(pack.metadata.file, test_data("minimal_pack.yaml"));
  EXPECT_DOUBLE_EQ(pack.mass.empty_inertia.ixz_kgm2, 20.0);
  EXPECT_DOUBLE_EQ(pack.mass.empty_inertia.tensor()(0, 2), -20.0);  // products negated
  ASSERT_TRUE(pack.flight_controls.elevator);
  EXPECT_NEAR(pack.flight_controls.elevator->deflection_at_minus_one_rad, -25.0 * kDeg, 1e-12);
  EXPECT_NEAR(pack.flight_controls.elevator->demanded_deflection_rad(0.5), 10.0 * kDeg, 1e-12);
  EXPECT_NEAR(pack.flight_controls.elevator->demanded_deflection_rad(-2.0), -25.0 * kDeg, 1e-12);
  EXPECT_EQ(pack.aerodynamics.factors.size(), 1u);
  EXPECT_EQ(pack.aerodynamics.terms(AeroAxis::lift)[0].lookup.dimensions(), 2);
  EXPECT_EQ(pack.aerodynamics.terms(AeroAxis::yaw_moment)[0].lookup.dimensions(), 3);
  ASSERT_EQ(pack.engines.size(), 1u);
  EXPECT_EQ(pack.engines[0].type, EngineType::turbofan);
  EXPECT_NEAR(pack.engines[0].turbofan.tsfc_kg_per_ns, 0.07 / 3600.0, 1e-15);
  ASSERT_TRUE(pack.limits.alpha_max_rad);
  EXPECT_FALSE(pack.limits.alpha_min_rad);
}

TEST(AircraftPackLoader, C172FiguresAreTheJsbsimOnesInSi) {
  const AircraftPack p = load_aircraft_pack(data_pack("c172.yaml"));
  EXPECT_NE(p.metadata.source.find("0b688c801c52d800f75d5c41e5434ce5d7618e88"), std::string::npos);
  expect_rel(p.geometry.wing_area_m2, 174.0 * kFt * kFt);
  EXPECT_NEAR(p.geometry.wing_span_m, 36.0 * kFt, 1e-9);
  EXPECT_NEAR(p.geometry.mean_chord_m, 4.9 * kFt, 1e-9);
  expect_vector_near(p.geometry.aero_reference_point_m, from_structural_in(43.2, 0, 59.4), 1e-9);
  expect_vector_near(p.geometry.pilot_eye_point_m, from_structural_in(37.0, 0, 48.0), 1e-9);
  expect_rel(p.mass.empty_mass_kg, 1454.0 * kLb);
  expect_vector_near(p.mass.empty_cg_m, from_structural_in(41.0, 0, 36.5), 1e-9);
  expect_rel(p.mass.empty_inertia.ixx_kgm2, 948.0 * kSlugFt2);
  expect_rel(p.mass.empty_inertia.iyy_kgm2, 1346.0 * kSlugFt2);
  expect_rel(p.mass.empty_inertia.izz_kgm2, 1967.0 * kSlugFt2);
  ASSERT_EQ(p.mass.point_masses.size(), 6u);
  expect_rel(p.mass.point_masses[0].mass_kg, 190.0 * kLb);
  expect_vector_near(p.mass.point_masses[0].position_m, from_structural_in(36, -14, 24), 1e-9);
  ASSERT_EQ(p.mass.fuel_tanks.size(), 2u);
  expect_rel(p.mass.fuel_tanks[1].capacity_kg, 130.0 * kLb);
  EXPECT_NEAR(p.mass.fuel_tanks[1].radius_m, 29.4 * kIn, 1e-9);
  expect_vector_near(p.mass.fuel_tanks[1].position_m, from_structural_in(48, 112, 59.4), 1e-9);

  // Elevator: JSBSim maps -1..1 to -28..23 deg (gain 0.01745 rad/deg), lag 60/s, clip 0.34 rad.
  const auto& elevator = *p.flight_controls.elevator;
  EXPECT_NEAR(elevator.deflection_at_plus_one_rad, 23.0 * 0.01745, 1e-9);
  EXPECT_NEAR(elevator.deflection_at_minus_one_rad, -28.0 * 0.01745, 1e-9);
  EXPECT_NEAR(elevator.max_deflection_rad, 0.34, 1e-9);
  EXPECT_NEAR(elevator.min_deflection_rad, -0.34, 1e-9);
  EXPECT_NEAR(elevator.time_constant_s, 1.0 / 60.0, 1e-10);
  // Aileron: mean of left (-20..15 deg) and right (the mirror) surfaces; 1.57 rad/s each.
  EXPECT_NEAR(p.flight_controls.aileron->deflection_at_plus_one_rad, 17.5 * 0.01745, 1e-9);
  EXPECT_NEAR(p.flight_controls.aileron->rate_limit_radps, 1.57, 1e-9);
  // Rudder: fedsim +1 (right pedal) is JSBSim -1: trailing edge right, negative deflection.
  EXPECT_NEAR(p.flight_controls.rudder->deflection_at_plus_one_rad, -16.0 * 0.01745, 1e-9);
  ASSERT_TRUE(p.flight_controls.flaps);
  EXPECT_NEAR(p.flight_controls.flaps->full_travel_rad, 30.0 * kDeg, 1e-12);
  EXPECT_EQ(p.flight_controls.flaps->transit_times_s, (std::vector<double>{2.0, 1.0, 1.0}));

  ASSERT_TRUE(p.aerodynamics.stall_hysteresis);
  EXPECT_DOUBLE_EQ(p.aerodynamics.stall_hysteresis->alpha_set_rad, 0.36);
  EXPECT_DOUBLE_EQ(p.aerodynamics.stall_hysteresis->alpha_clear_rad, 0.09);
  EXPECT_EQ(p.aerodynamics.terms(AeroAxis::lift).size(), 6u);  // CLwbh ... CLalpha
  EXPECT_EQ(p.aerodynamics.terms(AeroAxis::pitch_moment).size(), 6u);

  ASSERT_EQ(p.engines.size(), 1u);
  const EngineSpec& engine = p.engines[0];
  EXPECT_EQ(engine.type, EngineType::piston_propeller);
  expect_vector_near(engine.position_m, from_structural_in(-37.7, 0, 26.6), 1e-9);
  EXPECT_EQ(engine.fuel_tanks, (std::vector<int>{0, 1}));
  expect_rel(engine.piston.max_power_w, 160.0 * 550.0 * 4.4482216152605 * kFt);
  expect_rel(engine.piston.displacement_m3, 320.0 * kIn * kIn * kIn);
  EXPECT_DOUBLE_EQ(engine.piston.max_rpm, 2700.0);
  EXPECT_NEAR(engine.propeller.diameter_m, 75.0 * kIn, 1e-12);
  expect_rel(engine.propeller.inertia_kgm2, 1.67 * kSlugFt2);
  EXPECT_EQ(engine.propeller.spin_sense, -1);
  EXPECT_NEAR(engine.propeller.thrust_coefficient(0.0), 0.073, 1e-12);
  EXPECT_NEAR(engine.propeller.power_coefficient(1.0), 0.0282, 1e-12);
  // prop_75in2f.xml states no <ct_factor>, <cp_factor> (JSBSim's default 1): the pack's factors
  // and their fade band are the calibration overlay's, merged by the converter
  // (PropellerCalibration.C172PackCarriesTheOverlay checks the values).
  EXPECT_NE(engine.propeller.thrust_coefficient_factor, 1.0);
  EXPECT_NE(engine.propeller.power_coefficient_factor, 1.0);
  EXPECT_TRUE(engine.propeller.factor_fade.has_value());

  ASSERT_EQ(p.landing_gear.contacts.size(), 6u);
  const GearContactSpec& nose = p.landing_gear.contacts[0];
  EXPECT_EQ(nose.type, ContactType::wheel);
  expect_vector_near(nose.position_m, from_structural_in(-6.8, 0, -20), 1e-9);
  expect_rel(nose.spring_n_per_m, 1800.0 * kLbfPerFtToNPerM);
  expect_rel(nose.rebound_damping_n_s_per_m, 2000.0 * kLbfPerFtToNPerM);
  EXPECT_NEAR(nose.max_steer_rad, 10.0 * kDeg, 1e-12);
  // The right main gear's strut is a JSBSim function equal to the left one's coefficients.
  expect_rel(p.landing_gear.contacts[2].spring_n_per_m, 5400.0 * kLbfPerFtToNPerM);
  expect_rel(p.landing_gear.contacts[2].rebound_damping_n_s_per_m, 320.0 * kLbfPerFtToNPerM);
  EXPECT_EQ(p.landing_gear.contacts[2].brake_group, BrakeGroup::right);
  EXPECT_EQ(p.landing_gear.contacts[3].type, ContactType::structure);
  EXPECT_DOUBLE_EQ(*p.limits.alpha_max_rad, 0.28);
}

TEST(AircraftPackLoader, B737FiguresAreTheJsbsimOnesInSi) {
  const AircraftPack p = load_aircraft_pack(data_pack("b737.yaml"));
  expect_rel(p.geometry.wing_area_m2, 1171.0 * kFt * kFt);
  expect_rel(p.mass.empty_mass_kg, 83000.0 * kLb);
  // 737.xml gives ixz = 8000 with negated_crossproduct_inertia="true": JSBSim's body tensor
  // element (1,3) is +8000, so the product of inertia (integral of x z dm) is -8000.
  expect_rel(p.mass.empty_inertia.ixz_kgm2, -8000.0 * kSlugFt2);
  expect_rel(p.mass.empty_inertia.tensor()(0, 2), 8000.0 * kSlugFt2);
  ASSERT_EQ(p.engines.size(), 2u);
  for (const auto& e : p.engines) {
    EXPECT_EQ(e.type, EngineType::turbofan);
    expect_rel(e.turbofan.max_thrust_n, 20000.0 * 4.4482216152605);
    EXPECT_NEAR(e.turbofan.max_thrust_fraction(0.0, 0.0), 1.0, 1e-12);
    EXPECT_NEAR(e.turbofan.max_thrust_fraction(0.0, 30000.0 * kFt), 0.372, 1e-12);
  }
  EXPECT_LT(p.engines[0].position_m.y(), 0.0);
  EXPECT_EQ(p.engines[0].fuel_tanks, (std::vector<int>{0, 2}));
  EXPECT_DOUBLE_EQ(p.landing_gear.transit_time_s, 5.0);
  EXPECT_TRUE(p.landing_gear.contacts[0].retractable);
  ASSERT_TRUE(p.flight_controls.speedbrake);
  ASSERT_TRUE(p.flight_controls.spoilers);
  EXPECT_FALSE(p.flight_controls.flaps->full_travel_rad > 0.0);  // aero uses flap_norm only
}

TEST(AircraftPackLoader, NasaBodiesNeedNoEngineGearOrControls) {
  const AircraftPack sphere = load_aircraft_pack(data_pack("nasa_sphere.yaml"));
  EXPECT_TRUE(sphere.engines.empty());
  EXPECT_TRUE(sphere.landing_gear.contacts.empty());
  EXPECT_FALSE(sphere.flight_controls.elevator);
  for (const auto& terms : sphere.aerodynamics.axes) EXPECT_TRUE(terms.empty());
  EXPECT_NEAR(sphere.mass.empty_mass_kg, 14.5939029372, 1e-9);

  const AircraftPack drag = load_aircraft_pack(data_pack("nasa_sphere_drag.yaml"));
  ASSERT_EQ(drag.aerodynamics.terms(AeroAxis::drag).size(), 1u);
  EXPECT_DOUBLE_EQ(drag.aerodynamics.terms(AeroAxis::drag)[0].lookup.constant_value(), 0.1);

  const AircraftPack brick = load_aircraft_pack(data_pack("nasa_brick_damped.yaml"));
  expect_rel(brick.mass.empty_mass_kg, 0.155404754 * 14.5939029372);
  // Homogeneous 8 x 4 x 2.25 in brick: I = m (a^2 + b^2) / 12 about each axis.
  const double m = 0.155404754 * 14.5939029372;
  EXPECT_NEAR(brick.mass.empty_inertia.ixx_kgm2, m * (4 * 4 + 2.25 * 2.25) * kIn * kIn / 12, 2e-8);
  EXPECT_NEAR(brick.mass.empty_inertia.iyy_kgm2, m * (8 * 8 + 2.25 * 2.25) * kIn * kIn / 12, 2e-8);
  EXPECT_NEAR(brick.mass.empty_inertia.izz_kgm2, m * (8 * 8 + 4 * 4) * kIn * kIn / 12, 2e-8);
  EXPECT_NEAR(brick.geometry.wing_area_m2, 8 * 4 * kIn * kIn, 1e-12);
  EXPECT_EQ(brick.aerodynamics.terms(AeroAxis::roll_moment).size(), 1u);
}

// --- broken packs --------------------------------------------------------------------------

struct ExpectedError {
  int line = 0;
  std::string field;
  std::string words;
};

// Finds the "# EXPECT-ERROR field | words" marker and its 1-based line.
ExpectedError read_marker(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    const auto at = text.find("# EXPECT-ERROR ");
    if (at == std::string::npos) continue;
    const std::string spec = text.substr(at + 15);
    const auto bar = spec.find(" | ");
    return {line, spec.substr(0, bar), spec.substr(bar + 3)};
  }
  return {};
}

TEST(AircraftPackLoader, BrokenPacksFailAtTheirFileLineAndField) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(test_data("broken"))) {
    const std::string path = entry.path().string();
    SCOPED_TRACE(path);
    const ExpectedError expected = read_marker(path);
    ASSERT_GT(expected.line, 0) << "no EXPECT-ERROR marker";
    try {
      load_aircraft_pack(path);
      ADD_FAILURE() << "loaded a broken pack";
    } catch (const util::ConfigError& e) {
      const std::string message = e.what();
      const std::string prefix = path + ":" + std::to_string(expected.line) + ": " +
                                 (expected.field.empty() ? "" : expected.field + ": ");
      EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
      EXPECT_NE(message.find(expected.words), std::string::npos) << message;
    }
    ++count;
  }
  EXPECT_GE(count, 22);
}

TEST(AircraftPackLoader, UnreadableFileNamesTheFile) {
  try {
    load_aircraft_pack("/nonexistent/pack.yaml");
    FAIL();
  } catch (const util::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/pack.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace fedsim::flight
