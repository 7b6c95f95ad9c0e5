// The replay timeline: real-time pacing, speed, pause, seek, clamping at the ends.
#include "ios/model/replay_clock.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::ios {
namespace {

std::vector<double> frames(int n, double dt = 0.02) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(100.0 + dt * i);  // a recording from sim time 100 s
  return t;
}

TEST(ReplayClock, PacesAtItsSpeedPausesAndSeeks) {
  ReplayClock c(frames(3001));  // 60 s
  EXPECT_EQ(c.due(5.0), 0u);     // starts paused at the first sample
  c.play(10.0, 1.0);
  EXPECT_EQ(c.due(10.0), 0u);
  EXPECT_EQ(c.due(11.0), 50u);   // one second later: 50 frames
  EXPECT_NEAR(c.position_s(11.0), 101.0, 1e-12);
  c.pause(11.0);
  EXPECT_EQ(c.due(20.0), 50u);   // paused: stays
  c.play(20.0, 4.0);
  EXPECT_EQ(c.due(21.0), 250u);  // 4x: 4 s of sim in 1 s of wall time
  c.seek(21.0, 130.0);
  EXPECT_EQ(c.due(21.0), 1500u);
  EXPECT_TRUE(c.playing());
  EXPECT_FALSE(c.finished(25.0));
  EXPECT_TRUE(c.finished(30.0));  // 130 + 4 * 9 > 160
  EXPECT_EQ(c.due(1000.0), 3000u);  // clamped at the last sample
  c.seek(30.0, -5.0);
  EXPECT_EQ(c.due(30.0), 0u);      // clamped at the first
}

TEST(ReplayClock, RefusesWhatCannotBeReplayed) {
  EXPECT_THROW(ReplayClock({}), std::invalid_argument);
  EXPECT_THROW(ReplayClock({1.0, 0.5}), std::invalid_argument);
  EXPECT_THROW(ReplayClock({1.0, NAN}), std::invalid_argument);
  ReplayClock c(frames(10));
  EXPECT_THROW(c.play(0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(c.play(0.0, NAN), std::invalid_argument);
  EXPECT_THROW(c.seek(0.0, INFINITY), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::ios
