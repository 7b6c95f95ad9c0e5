// The frame tick, built once for both hosts: the frame clock's fields (common/frame_clock) as the
// fedsim/frame_tick sample fedsim-timing publishes, and a tick as the FrameContext a step sees.
// The in-process composition goes through the same two steps, so a composed run's frames are
// the ones a federation's timing federate would have ticked.
#pragma once

#include "common/frame_clock/run_control.hpp"
#include "common/runtime/component.hpp"

namespace fedsim::runtime {

/// The sample for the clock's next tick (publish_time_ns left 0: the publisher stamps it).
msg::FrameTick tick_of(const timing::TickFields& fields, double frame_period_s, msg::TimingMode mode);

/// What a step needs to know of the frame a tick starts.
FrameContext context_of(const msg::FrameTick& tick);

}  // namespace fedsim::runtime
