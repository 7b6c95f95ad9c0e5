// The initial-condition file: every field read with its unit, and errors that point at the
// file, line and field.
#include "flight/model/aircraft/initial_conditions.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/util/config_node.hpp"

namespace fedsim::flight {
namespace {

constexpr double kDeg = units::kDegToRad;

const char* kFull = R"(fedsim_initial_conditions: 1
position: {lat_deg: 28.5, lon_deg: -80.6, alt_ft: 4000}
velocity_body_mps: [51.0, 0.5, 1.2]
attitude_deg: {phi: 5.0, theta: 2.0, psi: 270.0}
body_rates_dps: [1.0, -2.0, 3.0]
body_rates_relative_to: inertial
engines_running: false
settle_engines: false
fuel_kg: [20.0, 25.0]
controls:
  elevator: -0.1
  throttle: [0.7, 0.6]
  mixture: 0.9
  flaps: 0.5
  gear_down: false
  brakes: 0.3
  brake_right: 0.4
weather:
  temperature_offset_k: -5
  sea_level_pressure_pa: 100000
  wind:
    - {alt_m: 0, speed_mps: 5, from_deg: 270}
    - {alt_m: 1000, speed_mps: 15, from_deg: 300}
  turbulence: moderate
  turbulence_seed: 42
  microburst: {centre_north_m: 1000, centre_east_m: -200, max_outflow_mps: 12}
runway_elevation_m: 3.0
)";

TEST(InitialConditionFile, ReadsEveryFieldInSi) {
  const InitialConditionFile f = parse_initial_condition_file(kFull, "full.yaml");
  const AircraftInitialConditions& ic = f.initial;
  EXPECT_NEAR(ic.position.lat_rad, 28.5 * kDeg, 1e-15);
  EXPECT_NEAR(ic.position.lon_rad, -80.6 * kDeg, 1e-15);
  EXPECT_NEAR(ic.position.alt_m, 1219.2, 1e-9);
  EXPECT_EQ(ic.velocity_frame, AircraftInitialConditions::VelocityFrame::kBody);
  EXPECT_EQ(ic.velocity_mps, Eigen::Vector3d(51.0, 0.5, 1.2));
  EXPECT_NEAR(ic.attitude.phi_rad, 5.0 * kDeg, 1e-15);
  EXPECT_NEAR(ic.attitude.psi_rad, 270.0 * kDeg, 1e-15);
  EXPECT_NEAR(ic.omega_body_radps.y(), -2.0 * kDeg, 1e-15);
  EXPECT_FALSE(ic.omega_relative_to_earth);
  EXPECT_FALSE(ic.engines_running);
  EXPECT_FALSE(ic.settle_engines);
  EXPECT_EQ(ic.fuel_kg, (std::vector<double>{20.0, 25.0}));
  EXPECT_DOUBLE_EQ(f.controls.elevator, -0.1);
  EXPECT_DOUBLE_EQ(f.controls.throttle[0], 0.7);
  EXPECT_DOUBLE_EQ(f.controls.throttle[1], 0.6);
  EXPECT_DOUBLE_EQ(f.controls.throttle[2], 0.0);
  EXPECT_DOUBLE_EQ(f.controls.mixture[3], 0.9);
  EXPECT_FALSE(f.controls.gear_down);
  EXPECT_DOUBLE_EQ(f.controls.brake_left, 0.3);
  EXPECT_DOUBLE_EQ(f.controls.brake_right, 0.4);
  EXPECT_DOUBLE_EQ(f.weather.atmosphere.sea_level_temperature_offset_k, -5.0);
  EXPECT_DOUBLE_EQ(f.weather.atmosphere.sea_level_pressure_pa, 100000.0);
  ASSERT_EQ(f.weather.wind.altitude_m.size(), 2u);
  EXPECT_NEAR(f.weather.wind.from_direction_rad[1], 300.0 * kDeg, 1e-15);
  EXPECT_EQ(f.weather.turbulence, Turbulence::Severity::kModerate);
  EXPECT_EQ(f.weather.turbulence_seed, 42u);
  EXPECT_DOUBLE_EQ(f.weather.microburst.centre_east_m, -200.0);
  EXPECT_DOUBLE_EQ(f.weather.microburst.max_outflow_mps, 12.0);
  ASSERT_TRUE(f.runway_elevation_m);
  EXPECT_DOUBLE_EQ(*f.runway_elevation_m, 3.0);
}

TEST(InitialConditionFile, MinimalFileHasSensibleDefaults) {
  const InitialConditionFile f = parse_initial_condition_file(
      "fedsim_initial_conditions: 1\nposition: {lat_deg: 0, lon_deg: 0, alt_m: 100}\n"
      "velocity_ned_mps: [50, 0, 0]\n",
      "min.yaml");
  EXPECT_EQ(f.initial.velocity_frame, AircraftInitialConditions::VelocityFrame::kNed);
  EXPECT_TRUE(f.initial.omega_relative_to_earth);
  EXPECT_TRUE(f.initial.engines_running);
  EXPECT_EQ(f.weather.turbulence, Turbulence::Severity::kNone);
  EXPECT_FALSE(f.runway_elevation_m);
  EXPECT_EQ(f.controls, AircraftControls{});
}

/// The error message of a bad file.
std::string error_of(const std::string& text) {
  try {
    parse_initial_condition_file(text, "bad.yaml");
  } catch (const util::ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(InitialConditionFile, ErrorsNameFileLineAndField) {
  const std::string head = "fedsim_initial_conditions: 1\n";
  const std::string pos = "position: {lat_deg: 0, lon_deg: 0, alt_m: 100}\n";
  const std::string vel = "velocity_ned_mps: [50, 0, 0]\n";
  // A typo in a key.
  EXPECT_EQ(
      error_of(head + pos + vel + "attitude_deg: {phi: 0, thta: 3}\n").rfind("bad.yaml:4:", 0), 0u);
  EXPECT_NE(error_of(head + pos + vel + "attitude_deg: {phi: 0, thta: 3}\n").find("thta"),
            std::string::npos);
  // Latitude out of range, on line 2.
  const std::string lat =
      error_of(head + "position: {lat_deg: 95, lon_deg: 0, alt_m: 100}\n" + vel);
  EXPECT_EQ(lat.rfind("bad.yaml:2: position.lat_deg:", 0), 0u) << lat;
  // Both altitude keys.
  EXPECT_NE(error_of(head + "position: {lat_deg: 0, lon_deg: 0, alt_m: 1, alt_ft: 3}\n" + vel)
                .find("not both"),
            std::string::npos);
  // No velocity at all.
  EXPECT_NE(error_of(head + pos).find("velocity_ned_mps"), std::string::npos);
  // A throttle above 1, a wrong turbulence word, wind layers out of order.
  EXPECT_NE(error_of(head + pos + vel + "controls: {throttle: 1.5}\n").find("controls.throttle"),
            std::string::npos);
  EXPECT_NE(
      error_of(head + pos + vel + "weather: {turbulence: strong}\n").find("weather.turbulence"),
      std::string::npos);
  const std::string wind =
      error_of(head + pos + vel +
               "weather:\n  wind:\n    - {alt_m: 100, speed_mps: 1, from_deg: 0}\n"
               "    - {alt_m: 50, speed_mps: 1, from_deg: 0}\n");
  EXPECT_EQ(wind.rfind("bad.yaml:7: weather.wind[1].alt_m:", 0), 0u) << wind;
  // A wrong format version and a missing file.
  EXPECT_NE(error_of("fedsim_initial_conditions: 2\n" + pos + vel).find("version"),
            std::string::npos);
  EXPECT_THROW(load_initial_condition_file("/nonexistent/ic.yaml"), util::ConfigError);
}

}  // namespace
}  // namespace fedsim::flight
