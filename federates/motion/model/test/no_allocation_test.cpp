// A frame of the motion platform allocates nothing (fedsim_allocation_counter) while engaged,
// limiting, engaging or parking; only a fault builds its message.
#include <gtest/gtest.h>

#include "common/util/allocation_counter.hpp"
#include "motion/model/motion_platform.hpp"
#include "motion/model/test/manoeuvres.hpp"

namespace fedsim::motion {
namespace {

TEST(NoAllocation, PlatformFramesAllocateNothing) {
  const double dt = 1.0 / 60.0;
  MotionPlatformParameters p;
  p.washout.translational[2].gain = 1.0;  // so that the violent doublet reaches the limits
  p.washout.rotational[1].gain = 1.0;
  MotionPlatform platform(p, dt);
  const std::vector<MotionInputs> doublet = test::pitch_doublet(dt, 20.0);
  test::ManoeuvreScale violent;
  violent.pitch_rate_radps = 0.44;
  violent.airspeed_mps = 120.0;
  const std::vector<MotionInputs> violent_doublet = test::pitch_doublet(dt, 20.0, violent);
  const util::AllocationScope scope;
  platform.engage();
  while (platform.status() == MotionStatus::kEngaging) platform.step(MotionInputs{});
  for (const MotionInputs& in : doublet) platform.step(in);
  bool limited = false;
  for (const MotionInputs& in : violent_doublet)
    limited = platform.step(in).workspace_limited || limited;
  platform.park();
  while (platform.status() == MotionStatus::kParking) platform.step(MotionInputs{});
  EXPECT_EQ(scope.allocations(), 0u);
  EXPECT_TRUE(limited);
  EXPECT_EQ(platform.status(), MotionStatus::kParked);
}

}  // namespace
}  // namespace fedsim::motion
