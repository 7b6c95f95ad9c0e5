#include "common/runtime/frame_tick.hpp"

#include "common/runtime/sim_command_codec.hpp"

namespace fedsim::runtime {

msg::FrameTick tick_of(const timing::TickFields& fields, double frame_period_s, msg::TimingMode mode) {
  msg::FrameTick tick;
  tick.frame(fields.frame);
  tick.sim_frame(fields.sim_frame);
  tick.sim_time_s(fields.sim_time_s);
  tick.dt_s(fields.dt_s);
  tick.frame_period_s(frame_period_s);
  tick.run_state(to_msg(fields.state));
  tick.reset_count(fields.reset_count);
  tick.mode(mode);
  return tick;
}

FrameContext context_of(const msg::FrameTick& tick) {
  FrameContext ctx;
  ctx.frame = tick.frame();
  ctx.sim_frame = tick.sim_frame();
  ctx.sim_time_s = tick.sim_time_s();
  ctx.dt_s = tick.dt_s();
  ctx.frame_period_s = tick.frame_period_s();
  ctx.run_state = tick.run_state();
  ctx.reset_count = tick.reset_count();
  ctx.mode = tick.mode();
  return ctx;
}

}  // namespace fedsim::runtime
