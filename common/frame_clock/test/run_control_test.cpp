#include "common/frame_clock/run_control.hpp"

#include <gtest/gtest.h>

namespace fedsim::timing {
namespace {

TEST(RunControl, RunAdvancesSimTimeOnePeriodPerTick) {
  RunControl rc(0.02, RunState::kRun);
  for (int i = 0; i < 100; ++i) {
    const auto t = rc.next_tick();
    EXPECT_EQ(t.frame, static_cast<std::uint64_t>(i));
    EXPECT_EQ(t.sim_frame, static_cast<std::uint64_t>(i));
    EXPECT_DOUBLE_EQ(t.sim_time_s, i * 0.02);
    EXPECT_DOUBLE_EQ(t.dt_s, 0.02);
  }
}

TEST(RunControl, FreezeKeepsTickingButHoldsSimTime) {
  RunControl rc(0.01, RunState::kRun);
  rc.next_tick();
  rc.next_tick();
  rc.request(RunState::kFreeze);
  const auto a = rc.next_tick();
  const auto b = rc.next_tick();
  EXPECT_EQ(a.state, RunState::kFreeze);
  EXPECT_EQ(b.frame, a.frame + 1);
  EXPECT_EQ(a.sim_frame, b.sim_frame);
  EXPECT_DOUBLE_EQ(a.sim_time_s, 0.02);
  EXPECT_DOUBLE_EQ(b.dt_s, 0.0);
  rc.request(RunState::kRun);
  EXPECT_DOUBLE_EQ(rc.next_tick().sim_time_s, 0.02);
  EXPECT_DOUBLE_EQ(rc.next_tick().sim_time_s, 0.03);
}

TEST(RunControl, ResetIsOneTickThenThePreviousStateResumes) {
  RunControl rc(0.02, RunState::kRun);
  for (int i = 0; i < 5; ++i) rc.next_tick();
  rc.request(RunState::kReset);
  const auto r = rc.next_tick();
  EXPECT_EQ(r.state, RunState::kReset);
  EXPECT_EQ(r.reset_count, 1u);
  EXPECT_DOUBLE_EQ(r.sim_time_s, 0.0);
  const auto after = rc.next_tick();
  EXPECT_EQ(after.state, RunState::kRun);
  EXPECT_EQ(after.sim_frame, 0u);
  EXPECT_EQ(after.frame, r.frame + 1);
  EXPECT_EQ(after.reset_count, 1u);
}

TEST(RunControl, StartingFrozenHoldsTimeUntilRun) {
  RunControl rc(0.02, RunState::kFreeze);
  EXPECT_DOUBLE_EQ(rc.next_tick().dt_s, 0.0);
  rc.request(RunState::kRun);
  EXPECT_DOUBLE_EQ(rc.next_tick().dt_s, 0.02);
}

}  // namespace
}  // namespace fedsim::timing
