// The switch with fader: on a change between two different signals the output never steps by
// more than the new signal's own change plus the fade's rate |d|/T_fade times dt, ends exactly
// on the new signal after T_fade, and stays continuous through a change back mid-fade. The
// negative control is the plain switch.
#include "common/control/fader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fedsim::control {
namespace {

constexpr double kDt = 0.01;
constexpr double kFade = 1.0;
constexpr int kAltitudeHold = 1;
constexpr int kVerticalSpeed = 2;

double source_a(double t) { return 5.0 + std::sin(2.0 * t); }
double source_b(double t) { return -3.0 + 0.5 * t; }

TEST(Fader, FadesBetweenTwoDifferentSignalsAtTheFadeRate) {
  Fader fader(kFade, kDt);
  EXPECT_EQ(fader.fade_steps(), 100);
  const int switch_step = 200;
  double previous = 0.0, offset = 0.0;
  for (int n = 0; n <= switch_step + 150; ++n) {
    const double t = n * kDt;
    const bool on_b = n >= switch_step;
    const double y = on_b ? fader.step(kVerticalSpeed, source_b(t))
                          : fader.step(kAltitudeHold, source_a(t));
    if (!on_b) {
      ASSERT_EQ(y, source_a(t)) << n;  // no fade: the selected source exactly
    } else {
      // At the switch the offset is measured against the new source's present value, so the
      // step is the fade's alone; afterwards the new source's own change comes on top.
      if (n == switch_step) offset = previous - source_b(t);
      const double own_change = n == switch_step ? 0.0 : source_b(t) - source_b(t - kDt);
      const double fade_step = std::abs(offset) * kDt / kFade;
      ASSERT_LE(std::abs((y - previous) - own_change), fade_step + 1e-12) << n;
      if (n >= switch_step + fader.fade_steps() - 1) {
        ASSERT_EQ(y, source_b(t)) << n;  // faded out after T_fade
        ASSERT_FALSE(fader.fading());
      } else {
        ASSERT_TRUE(fader.fading()) << n;
      }
    }
    previous = y;
  }
  EXPECT_GT(std::abs(offset), 6.0);  // the signals differed by 6.25 at the switch
}

TEST(Fader, StaysContinuousWhenSwitchedBackMidFade) {
  Fader fader(kFade, kDt);
  fader.reset(kAltitudeHold, source_a(0.0));
  double previous = fader.output();
  double largest_step = 0.0;
  for (int n = 1; n < 400; ++n) {
    const double t = n * kDt;
    const bool on_b = n >= 100 && n < 150;  // to B, back to A halfway through the fade
    const double y = on_b ? fader.step(kVerticalSpeed, source_b(t))
                          : fader.step(kAltitudeHold, source_a(t));
    largest_step = std::max(largest_step, std::abs(y - previous));
    previous = y;
  }
  // The offsets (8.42 to B, -3.10 back to A) fade at most 0.085 a step; the sources move at
  // most 0.02 a step.
  EXPECT_LT(largest_step, 8.6 * kDt / kFade + 0.02 + 1e-9);
  EXPECT_EQ(previous, source_a(399 * kDt));
}

TEST(Fader, APlainSwitchStepsByTheWholeDifference) {
  // Negative control: without the fade the output jumps from A to B in one step.
  const double t = 2.0;
  EXPECT_GT(std::abs(source_a(t - kDt) - source_b(t)), 6.0);
  Fader fader(kDt, kDt);  // a fade of one step is a plain switch
  fader.step(kAltitudeHold, source_a(t - kDt));
  EXPECT_EQ(fader.step(kVerticalSpeed, source_b(t)), source_b(t));
}

}  // namespace
}  // namespace fedsim::control
