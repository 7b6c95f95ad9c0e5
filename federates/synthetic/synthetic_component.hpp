// fedsim-synthetic's component: a configurable amount of busy work per frame and a
// navigation-state-sized sample, for benchmarks and integration tests of the runtime.
// Optionally reads the pilot controls as a lockstep input and traces every frame it saw.
//
// Reads:  fedsim/pilot_controls (lockstep input) with --input.
// Writes: fedsim/navigation_state ("state") with --publish.
#pragma once

#include "common/runtime/federate_main.hpp"

namespace fedsim::synthetic {

/// fedsim-synthetic as a program: --work-us, --publish, --input, --trace.
runtime::FederateProgram program();

}  // namespace fedsim::synthetic
