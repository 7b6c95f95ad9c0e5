// A frame of the control-loading loop allocates nothing (fedsim_allocation_counter) while the
// loader runs normally; only a cut-off builds its message.
#include <gtest/gtest.h>

#include "common/util/allocation_counter.hpp"
#include "control_loading/model/control_loading.hpp"

namespace fedsim::control_loading {
namespace {

TEST(NoAllocation, ActiveFramesAllocateNothing) {
  ControlLoading loader{ControlLoadingParameters{}};
  loader.engage();
  ControlLoadingInputs in;
  in.qbar_pa = 6000.0;
  in.alpha_rad = 0.3;  // shaker on
  in.axes[0].pilot_force_n = 40.0;
  in.axes[1].backdrive_active = true;
  in.axes[1].backdrive_target_norm = 0.3;
  loader.step(in, 1.0 / 60.0);
  const util::AllocationScope scope;
  for (int n = 0; n < 120; ++n) loader.step(in, 1.0 / 60.0);
  in.pilot_source = PilotSource::kSimulatedPilot;
  for (int n = 0; n < 60; ++n) loader.step(in, 1.0 / 60.0);
  EXPECT_EQ(scope.allocations(), 0u);
  EXPECT_EQ(loader.status(), LoaderStatus::kActive);
}

}  // namespace
}  // namespace fedsim::control_loading
