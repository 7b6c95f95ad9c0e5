#include "common/frame_clock/run_control.hpp"

namespace fedsim::timing {

RunControl::RunControl(double frame_period_s, RunState initial)
    : period_s_(frame_period_s),
      state_(initial == RunState::kReset ? RunState::kFreeze : initial),
      state_after_reset_(state_) {
  if (initial == RunState::kReset) reset_pending_ = true;
}

void RunControl::request(RunState state) {
  if (state == RunState::kReset) {
    reset_pending_ = true;
    state_after_reset_ = state_;
    return;
  }
  state_ = state;
  state_after_reset_ = state;
}

TickFields RunControl::next_tick() {
  TickFields tick;
  tick.frame = next_frame_++;
  if (reset_pending_) {
    reset_pending_ = false;
    ++reset_count_;
    sim_frame_ = 0;
    state_ = state_after_reset_;
    tick.state = RunState::kReset;
    tick.sim_frame = 0;
    tick.sim_time_s = 0.0;
    tick.dt_s = 0.0;
    tick.reset_count = reset_count_;
    return tick;
  }
  tick.state = state_;
  tick.sim_frame = sim_frame_;
  // Multiplying (not accumulating) keeps sim time exact to the last bit over long runs.
  tick.sim_time_s = static_cast<double>(sim_frame_) * period_s_;
  tick.reset_count = reset_count_;
  if (state_ == RunState::kRun) {
    tick.dt_s = period_s_;
    ++sim_frame_;
  }
  return tick;
}

}  // namespace fedsim::timing
