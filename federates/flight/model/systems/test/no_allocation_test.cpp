// Checks that the per-step functions of the systems and weather models never allocate: the
// global operator new is replaced by the counting one of fedsim_allocation_counter.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "common/util/allocation_counter.hpp"
#include "flight/model/weather/turbulence.hpp"
#include "flight/model/weather/wind_profile.hpp"
#include "flight/model/weather/wind_shear.hpp"
#include "flight/model/systems/actuator.hpp"
#include "flight/model/systems/test/reference_data.hpp"


namespace fedsim::flight {
namespace {

TEST(NoAllocation, ModelStepsDoNotAllocate) {
  Actuator::Params surface;
  surface.deflection_at_plus_one_rad = 0.4;
  surface.deflection_at_minus_one_rad = -0.5;
  surface.time_constant_s = 0.05;
  surface.rate_limit_radps = 1.0;
  Actuator actuator(surface);
  PistonPowerplant piston(reference::c172_powerplant());
  Turbofan turbofan(reference::cfm56());
  MassBalance mass(reference::b737_mass());
  LandingGear gear(reference::c172_gear());
  Turbulence turbulence(Turbulence::Params::for_severity(Turbulence::Severity::kSevere, 30.0, 1));
  WindProfile::Params wind_params;
  wind_params.altitude_m = {0.0, 1000.0};
  wind_params.speed_mps = {5.0, 20.0};
  wind_params.from_direction_rad = {1.0, 2.0};
  const WindProfile wind(wind_params);
  WindShear::Params burst;
  burst.max_outflow_mps = 15.0;
  const WindShear shear(burst);

  // Inputs are prepared before counting.
  PistonPowerplant::Inputs piston_in;
  piston_in.throttle = 1.0;
  piston_in.air_velocity_body_mps = Eigen::Vector3d(40.0, 1.0, 2.0);
  Turbofan::Inputs fan_in;
  fan_in.throttle = 0.8;
  const std::array<double, 2> flows = {0.5, 0.6};
  std::vector<LandingGear::ContactKinematics> kin(3);
  for (auto& k : kin) {
    k.position_ned_m = Eigen::Vector3d(0.0, 0.0, 0.05);
    k.velocity_ned_mps = Eigen::Vector3d(10.0, 0.5, 0.1);
  }
  LandingGear::Inputs gear_in;
  gear_in.contacts = kin;
  gear_in.brake_left = 0.5;
  Turbulence::Inputs turb_in;
  turb_in.tas_mps = 60.0;

  const util::AllocationScope scope;
  double sink = 0.0;
  for (int i = 0; i < 200; ++i) {
    actuator.step(0.02, {i % 2 == 0 ? 1.0 : -1.0});
    piston.step(0.02, piston_in);
    turbofan.step(0.02, fan_in);
    mass.step(0.02, {flows});
    gear.step(0.02, gear_in);
    turb_in.height_agl_m = 10.0 * i;  // crosses the low / medium altitude blend
    turbulence.step(0.02, turb_in);
    sink += wind.at(5.0 * i).wind_ned_mps.norm() + shear.wind_ned_mps(100.0 * i, 0.0, 50.0).norm();
  }
  const std::size_t after = scope.allocations();
  EXPECT_EQ(after, 0u);
  // The counter does see allocations (the check above could fail).
  {
    const std::vector<double> probe(10, 1.0);
    sink += probe.back();
  }
  EXPECT_GT(scope.allocations(), after);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace
}  // namespace fedsim::flight
