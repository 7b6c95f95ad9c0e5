// The flight federate's translation between topics and the model.
#include "flight/federate/flight_adapter.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::flight {
namespace {

AircraftControls trimmed() {
  AircraftControls t;
  t.elevator = 0.2;
  t.aileron = -0.01;
  t.set_throttle(0.8);
  t.mixture.fill(0.9);
  t.flaps = 0.25;
  return t;
}

TEST(FlightAdapter, AbsoluteControlsAreTheInceptorPositions) {
  msg::PilotControls in;
  in.elevator(-0.3f);
  in.throttle()[0] = 0.5f;
  in.mixture()[0] = 1.0f;
  in.brake_left(0.7f);
  in.gear_down(false);
  const auto c = controls_from_message(in, ControlsMode::kAbsolute, trimmed());
  EXPECT_FLOAT_EQ(c.elevator, -0.3f);
  EXPECT_FLOAT_EQ(c.throttle[0], 0.5f);
  EXPECT_FLOAT_EQ(c.mixture[0], 1.0f);
  EXPECT_FLOAT_EQ(c.brake_left, 0.7f);
  EXPECT_FALSE(c.gear_down);
  EXPECT_DOUBLE_EQ(c.flaps, 0.0);
}

TEST(FlightAdapter, RelativeControlsAddPrimariesAndThrottleToTheTrim) {
  msg::PilotControls in;  // all zero: the trim itself
  const auto at_trim = controls_from_message(in, ControlsMode::kRelative, trimmed());
  EXPECT_DOUBLE_EQ(at_trim.elevator, 0.2);
  EXPECT_DOUBLE_EQ(at_trim.throttle[0], 0.8);
  EXPECT_DOUBLE_EQ(at_trim.mixture[0], 0.9);   // levers other than throttle keep the trim
  EXPECT_DOUBLE_EQ(at_trim.flaps, 0.25);
  in.elevator(-0.05f);
  in.throttle()[0] = 0.5f;
  const auto c = controls_from_message(in, ControlsMode::kRelative, trimmed());
  EXPECT_NEAR(c.elevator, 0.15, 1e-7);
  EXPECT_DOUBLE_EQ(c.throttle[0], 1.0);  // 0.8 + 0.5, clamped
}

TEST(FlightAdapter, WeatherCommandBuildsAWindProfileAndTurbulence) {
  msg::WeatherSettings w;
  w.wind_from_rad(units::kPi / 2);
  w.wind_speed_mps(10.0);
  w.wind_gradient_mps_per_m(0.01);
  w.turbulence_intensity(2.0);
  w.turbulence_seed(7);
  w.sea_level_pressure_pa(100000.0);
  const auto s = weather_from_command(w, 100.0);
  ASSERT_EQ(s.wind.altitude_m.size(), 2u);
  EXPECT_DOUBLE_EQ(s.wind.altitude_m[0], 100.0);
  EXPECT_DOUBLE_EQ(s.wind.speed_mps[1], 16.0);  // 10 + 0.01 * 600 m
  EXPECT_EQ(s.turbulence, Turbulence::Severity::kModerate);
  EXPECT_EQ(s.turbulence_seed.value(), 7u);
  EXPECT_DOUBLE_EQ(s.atmosphere.sea_level_pressure_pa, 100000.0);
  const auto calm = weather_from_command(msg::WeatherSettings{}, 0.0);
  EXPECT_TRUE(calm.wind.altitude_m.empty());
  EXPECT_EQ(calm.turbulence, Turbulence::Severity::kNone);
}

TEST(FlightAdapter, StateCarriesOutputsWithoutLosingPrecision) {
  AircraftOutputs out;
  out.geodetic = {0.6588123456789012, -2.1345678901234567, 1219.2};
  out.tas_mps = 51.4;
  out.contacts.resize(3);
  out.contacts[1].weight_on_wheels = true;
  out.contacts[1].normal_force_n = 4000.0;
  msg::AircraftState s;
  fill_aircraft_state(out, AircraftControls{}, s);
  EXPECT_EQ(s.latitude_rad(), out.geodetic.lat_rad);  // double precision end to end
  EXPECT_EQ(s.longitude_rad(), out.geodetic.lon_rad);
  EXPECT_DOUBLE_EQ(s.air().tas_mps(), 51.4);
  EXPECT_EQ(s.gear_count(), 3);
  EXPECT_TRUE(s.gear()[1].weight_on_wheels());
  EXPECT_FLOAT_EQ(s.gear()[1].normal_force_n(), 4000.0f);
}

}  // namespace
}  // namespace fedsim::flight
