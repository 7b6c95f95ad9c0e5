// A step of the aircraft executive never allocates (fedsim_allocation_counter counts operator new).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "common/util/allocation_counter.hpp"
#include "flight/model/scenario/test/flight_test_support.hpp"
#include "flight/model/scenario/reposition.hpp"


namespace fedsim::flight {
namespace {

using namespace testing;

TEST(AircraftModelNoAllocation, TheCountingAllocatorCounts) {
  // Called directly: a new-expression that is deleted at once may be elided by the compiler.
  const util::AllocationScope scope;
  void* p = ::operator new(16);
  ::operator delete(p);
  EXPECT_EQ(scope.allocations(), 1u);
}

TEST(AircraftModelNoAllocation, StepsSetControlsAndOutputsDoNotAllocate) {
  // Every path a frame can take: both packs, every integrator, both earths, substeps,
  // turbulence and a microburst on, changing controls, gear moving, wheels on the ground, an
  // engine failing.
  for (const std::string pack : {"c172.yaml", "b737.yaml"}) {
    for (const IntegrationMethod method :
         {IntegrationMethod::kEuler, IntegrationMethod::kAb2, IntegrationMethod::kAb3,
          IntegrationMethod::kAb4, IntegrationMethod::kRk4}) {
      for (const EarthModelKind earth : {EarthModelKind::kFlat, EarthModelKind::kWgs84}) {
        AircraftModel::Options options;
        options.integrator = method;
        options.earth = earth;
        options.substeps = 2;
        auto model = make_model(pack, options);
        WeatherSettings weather;
        weather.turbulence = Turbulence::Severity::kSevere;
        weather.wind.altitude_m = {0.0, 3000.0};
        weather.wind.speed_mps = {5.0, 20.0};
        weather.wind.from_direction_rad = {0.5, 1.5};
        weather.microburst.max_outflow_mps = 15.0;
        weather.microburst.centre_east_m = 500.0;
        model->set_weather(weather);
        const TrimResult trim = reposition_to_runway(*model, {{0.5, 0.5, 0.0}, 0.0});
        ASSERT_TRUE(trim.converged) << trim.reason;
        AircraftControls c = trim.controls;
        c.brake_left = c.brake_right = 0.0;
        c.set_throttle(1.0);
        const util::AllocationScope scope;
        for (int i = 0; i < 400; ++i) {
          c.elevator = i % 50 < 25 ? -0.4 : 0.1;
          c.steering = i % 7 * 0.1;
          c.gear_down = i < 300;
          model->set_controls(c);
          if (i == 200) model->set_engine_failed(0, true);
          if (i == 250) model->set_runway_elevation_m(-1.0);
          model->step(0.02);
          volatile double sink = model->outputs().geodetic.alt_m + model->outputs().tas_mps;
          (void)sink;
        }
        EXPECT_EQ(scope.allocations(), 0u)
            << pack << " " << to_string(method)
            << (earth == EarthModelKind::kFlat ? " flat" : " wgs84");
        EXPECT_TRUE(std::isfinite(model->outputs().geodetic.alt_m));
        EXPECT_FALSE(model->outputs().numerical_fault);
      }
    }
  }
}

}  // namespace
}  // namespace fedsim::flight
