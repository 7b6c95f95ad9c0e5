// The federation's run state and simulation clock (pure logic, no DDS; used by fedsim-timing and
// by the in-process composition): turns instructor
// commands into the fields of successive frame ticks.
//   RUN    - sim time advances by one frame period per tick;
//   FREEZE - ticks continue (displays refresh) but sim time stands still (dt = 0);
//   RESET  - one tick in state RESET with sim time 0; then the state before the reset resumes.
#pragma once

#include <cstdint>

namespace fedsim::timing {

enum class RunState { kRun, kFreeze, kReset };

struct TickFields {
  std::uint64_t frame = 0;
  std::uint64_t sim_frame = 0;
  double sim_time_s = 0.0;
  double dt_s = 0.0;
  RunState state = RunState::kFreeze;
  std::uint32_t reset_count = 0;
};

class RunControl {
 public:
  RunControl(double frame_period_s, RunState initial);

  /// Applies an instructor request; it takes effect at the next tick.
  void request(RunState state);
  /// Fields of the next tick; advances the clocks.
  TickFields next_tick();

  RunState state() const { return state_; }
  double frame_period_s() const { return period_s_; }

 private:
  double period_s_;
  RunState state_;
  RunState state_after_reset_;
  bool reset_pending_ = false;
  std::uint64_t next_frame_ = 0;
  std::uint64_t sim_frame_ = 0;
  std::uint32_t reset_count_ = 0;
};

}  // namespace fedsim::timing
