// `fedsim latency`'s pure half: onset detection against a trend, a picture's blueness (its
// horizon), its tilt (roll), the sideways shift between two pictures (yaw), the frame an arrival falls in, and the statistics. Each test has its negative
// control: the same series or picture without the change finds nothing.
#include "fedsim/latency_detect.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fedsim::latency {
namespace {

// value(frame) for frames first..last.
template <class F>
std::vector<Point> series(std::uint64_t first, std::uint64_t last, F value) {
  std::vector<Point> out;
  for (std::uint64_t f = first; f <= last; ++f) out.push_back({f, value(f)});
  return out;
}

TEST(LatencyOnset, FindsTheFirstFrameOfAStepOnAFlatOutput) {
  // Quiet up to frame 100 (S); the output moves from frame 102 on (two frames later).
  const auto s = series(80, 130, [](std::uint64_t f) { return f >= 102 ? 1e-3 * static_cast<double>(f - 101) : 0.0; });
  OnsetOptions o;
  o.min_threshold = 1e-6;
  const Onset onset = find_onset(s, 100, o);
  ASSERT_TRUE(onset.frame.has_value()) << onset.problem;
  EXPECT_EQ(*onset.frame, 102u);
  EXPECT_NEAR(onset.deviation, 1e-3, 1e-12);
  EXPECT_EQ(onset.noise, 0.0);
}

TEST(LatencyOnset, NothingMovesNothingFound) {
  const auto flat = series(80, 130, [](std::uint64_t) { return 0.25; });
  OnsetOptions o;
  o.min_threshold = 1e-9;
  const Onset onset = find_onset(flat, 100, o);
  EXPECT_FALSE(onset.frame.has_value());
  EXPECT_TRUE(onset.problem.empty()) << onset.problem;  // a verdict, not a failure to judge
}

TEST(LatencyOnset, AStepIsFoundOnTopOfADriftAndTheDriftAloneIsNot) {
  // A parabolic drift (a phugoid's arc, a washout settling) continues through the step.
  auto drift = [](std::uint64_t f) {
    const double x = static_cast<double>(f) - 100.0;
    return 0.3 + 2e-3 * x - 4e-5 * x * x;
  };
  OnsetOptions o;
  o.min_threshold = 1e-7;
  const auto quiet = series(80, 130, drift);
  EXPECT_FALSE(find_onset(quiet, 100, o).frame.has_value());
  // A straight line fitted to the same arc departs from it after the baseline: the parabola is
  // what keeps the drift from reading as a response.
  OnsetOptions line = o;
  line.trend_degree = 1;
  EXPECT_TRUE(find_onset(quiet, 100, line).frame.has_value());

  const auto stepped = series(80, 130, [&](std::uint64_t f) { return drift(f) + (f >= 101 ? 1e-4 : 0.0); });
  const Onset onset = find_onset(stepped, 100, o);
  ASSERT_TRUE(onset.frame.has_value());
  EXPECT_EQ(*onset.frame, 101u);
}

TEST(LatencyOnset, NoiseSetsTheThresholdAndAChangeWithinItIsNoResponse) {
  // Alternating +-1e-4 noise before and after; a 3e-4 change is within 5x the noise, 2e-3 is not.
  auto noisy = [](std::uint64_t f) { return f % 2 ? 1e-4 : -1e-4; };
  OnsetOptions o;
  o.trend_degree = 0;
  const auto small = series(80, 130, [&](std::uint64_t f) { return noisy(f) + (f >= 103 ? 3e-4 : 0.0); });
  const Onset none = find_onset(small, 100, o);
  EXPECT_FALSE(none.frame.has_value());
  EXPECT_NEAR(none.noise, 1e-4, 1e-12);
  const auto large = series(80, 130, [&](std::uint64_t f) { return noisy(f) + (f >= 103 ? 2e-3 : 0.0); });
  const Onset found = find_onset(large, 100, o);
  ASSERT_TRUE(found.frame.has_value());
  EXPECT_EQ(*found.frame, 103u);
  EXPECT_GT(found.threshold, 5e-4);  // 5 x noise, grown by the frames carried
}

TEST(LatencyOnset, LooksNoFurtherThanMaxFrames) {
  const auto late = series(80, 200, [](std::uint64_t f) { return f >= 140 ? 1.0 : 0.0; });
  OnsetOptions o;
  o.min_threshold = 1e-6;
  o.max_frames = 15;
  EXPECT_FALSE(find_onset(late, 100, o).frame.has_value());
  o.max_frames = 50;
  EXPECT_EQ(find_onset(late, 100, o).frame.value_or(0), 140u);
}

TEST(LatencyOnset, ARepeatedFrameKeepsItsFirstSample) {
  auto s = series(80, 110, [](std::uint64_t f) { return f >= 104 ? 1.0 : 0.0; });
  // Frame 102 seen twice (a resent sample), the second copy already different: ignored.
  s.insert(s.begin() + 23, Point{102, 5.0});
  OnsetOptions o;
  o.min_threshold = 1e-6;
  EXPECT_EQ(find_onset(s, 100, o).frame.value_or(0), 104u);
}

TEST(LatencyOnset, NamesWhatKeepsItFromJudging) {
  OnsetOptions o;
  const Onset too_few = find_onset(series(95, 110, [](std::uint64_t) { return 0.0; }), 100, o);
  EXPECT_FALSE(too_few.frame.has_value());
  EXPECT_NE(too_few.problem.find("only 6 samples before the step"), std::string::npos) << too_few.problem;

  auto nan_after = series(80, 110, [](std::uint64_t) { return 0.0; });
  nan_after[25].value = std::numeric_limits<double>::quiet_NaN();  // frame 105
  const Onset bad = find_onset(nan_after, 100, o);
  EXPECT_NE(bad.problem.find("non-finite sample after the step (frame 105)"), std::string::npos) << bad.problem;

  auto unsorted = series(80, 110, [](std::uint64_t) { return 0.0; });
  std::swap(unsorted[3], unsorted[4]);
  EXPECT_THROW(find_onset(unsorted, 100, o), std::invalid_argument);
}

TEST(LatencyOnset, RefusesOptionsOutOfRange) {
  OnsetOptions o;
  o.baseline_points = 2;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.noise_factor = std::numeric_limits<double>::infinity();
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.min_threshold = -1.0;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.trend_degree = 3;
  EXPECT_THROW(validate(o), std::invalid_argument);
  EXPECT_NO_THROW(validate(OnsetOptions{}));
}

TEST(LatencyOnset, EarliestOverChannelsIsTheFirstToMove) {
  OnsetOptions o;
  o.min_threshold = 1e-6;
  const auto a = series(80, 120, [](std::uint64_t f) { return f >= 104 ? 1.0 : 0.0; });
  const auto b = series(80, 120, [](std::uint64_t f) { return f >= 102 ? -1.0 : 0.0; });
  const auto still = series(80, 120, [](std::uint64_t) { return 0.0; });
  const ChannelOnset both = earliest_onset({a, b, still}, 100, {o, o, o});
  EXPECT_EQ(both.channel, 1u);
  EXPECT_EQ(both.onset.frame.value_or(0), 102u);
  EXPECT_FALSE(earliest_onset({still, still}, 100, {o, o}).onset.frame.has_value());
  EXPECT_THROW(earliest_onset({a}, 100, {o, o}), std::invalid_argument);
}

// A picture with sky above `horizon_row` (fractional: the edge row is blended, as a
// multisampled edge is) and ground below.
picture::Image sky_over_ground(int width, int height, double horizon_row) {
  picture::Image image(width, height);
  const picture::Rgba8 sky{60, 120, 220, 255}, ground{140, 90, 30, 255};
  for (int r = 0; r < height; ++r) {
    const double sky_part = std::clamp(horizon_row - r, 0.0, 1.0);
    auto mix = [&](std::uint8_t s, std::uint8_t g) {
      return static_cast<std::uint8_t>(std::lround(sky_part * s + (1.0 - sky_part) * g));
    };
    const picture::Rgba8 px{mix(sky.r, ground.r), mix(sky.g, ground.g), mix(sky.b, ground.b), 255};
    for (int c = 0; c < width; ++c) image.set(c, r, px);
  }
  return image;
}

TEST(LatencyBlueness, FollowsTheHorizonBySubPixelSteps) {
  const double level = blueness(sky_over_ground(200, 160, 80.0));
  const double down = blueness(sky_over_ground(200, 160, 80.25));   // nose up: more sky
  const double up = blueness(sky_over_ground(200, 160, 79.75));
  EXPECT_GT(down, level);
  EXPECT_LT(up, level);
  // The sky's (B-R) is 160, the ground's -110: a quarter row moves it by 0.25*270/255/160.
  EXPECT_NEAR(down - level, 0.25 * 270.0 / 255.0 / 160.0, 2e-5);
  // Negative control: the same picture twice, the same number.
  EXPECT_EQ(blueness(sky_over_ground(200, 160, 80.0)), level);
}

TEST(LatencyBlueness, AColumnRangeLooksOnlyThere) {
  picture::Image image = sky_over_ground(300, 100, 50.0);
  const double middle = blueness(image, 1.0 / 3.0, 2.0 / 3.0);
  for (int r = 0; r < 100; ++r) image.set(10, r, {255, 255, 255, 255});  // a tape at the left edge changes
  EXPECT_EQ(blueness(image, 1.0 / 3.0, 2.0 / 3.0), middle);
  EXPECT_NE(blueness(image), blueness(sky_over_ground(300, 100, 50.0)));
  EXPECT_THROW(blueness(image, 0.5, 0.5), std::invalid_argument);
  EXPECT_THROW(blueness(picture::Image{}), std::invalid_argument);
}

// A horizon through the picture's centre tilted by `slope` rows per column (+: its right end
// lower), the edge pixel blended by its sky part as in sky_over_ground; the ground textured
// (stripes of its red and blue, as grass and fields are), which the tilt must not see.
picture::Image tilted_horizon(int width, int height, double slope, int ground_shift = 0) {
  picture::Image image(width, height);
  const picture::Rgba8 sky{60, 120, 220, 255};
  for (int c = 0; c < width; ++c) {
    const double horizon_row = 0.5 * height + slope * (c + 0.5 - 0.5 * width);
    for (int r = 0; r < height; ++r) {
      const double sky_part = std::clamp(horizon_row - r, 0.0, 1.0);
      const bool field = ((c + ground_shift) / 7 + r / 5) % 2 == 0;
      const picture::Rgba8 ground = field ? picture::Rgba8{140, 90, 30, 255} : picture::Rgba8{70, 110, 40, 255};
      auto mix = [&](std::uint8_t sv, std::uint8_t gv) {
        return static_cast<std::uint8_t>(std::lround(sky_part * sv + (1.0 - sky_part) * gv));
      };
      image.set(c, r, {mix(sky.r, ground.r), mix(sky.g, ground.g), mix(sky.b, ground.b), 255});
    }
  }
  return image;
}

TEST(LatencyTilt, FollowsTheHorizonsTiltAndNotItsHeightOrTheGround) {
  const double level = blueness_tilt(tilted_horizon(200, 160, 0.0));
  EXPECT_NEAR(level, 0.0, 1e-3);  // the ground's stripes (red above blue) add nothing
  // Right end lower by 0.2 px (0.001 rows a column): more sky on the right, the figure falls.
  const double right_down = blueness_tilt(tilted_horizon(200, 160, 0.001));
  const double right_up = blueness_tilt(tilted_horizon(200, 160, -0.001));
  EXPECT_LT(right_down, level);
  EXPECT_GT(right_up, level);
  // Each half's mean horizon moves by 50 columns x 0.001 rows; the sky's B-R is 160. A blended
  // edge pixel counts only where its blue exceeds its red (more than 41 % sky here): a little
  // less than the whole row's share.
  const double whole_rows = 2.0 * 0.05 * 160.0 / 255.0 / 160.0;
  EXPECT_GT(level - right_down, 0.5 * whole_rows);
  EXPECT_LT(level - right_down, 1.05 * whole_rows);
  // Negative controls: the ground's texture moved sideways, a level picture the same again.
  EXPECT_EQ(blueness_tilt(tilted_horizon(200, 160, 0.0, 3)), level);
  EXPECT_EQ(blueness_tilt(tilted_horizon(200, 160, 0.0)), level);
  EXPECT_THROW(blueness_tilt(picture::Image{}), std::invalid_argument);
  EXPECT_THROW(blueness_tilt(tilted_horizon(20, 10, 0.0), Region{0.6, 0.4, 0.0, 1.0}), std::invalid_argument);
  // A region: the rows above the sky's part see no horizon, so no tilt; its own columns only.
  const picture::Image tilted = tilted_horizon(200, 160, 0.001);
  EXPECT_EQ(blueness_tilt(tilted, Region{0.0, 1.0, 0.0, 0.4}), 0.0);
  EXPECT_LT(blueness_tilt(tilted, Region{0.25, 0.75, 0.4, 0.6}), 0.0);
}

// A smooth texture (two crossed sinusoids and a slower one) displaced by (dx, dy) pixels.
Luma texture(int width, int height, double dx, double dy) {
  Luma l{width, height, std::vector<float>(static_cast<std::size_t>(width) * height)};
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const double x = c - dx, y = r - dy;
      l.value[static_cast<std::size_t>(r) * width + c] =
          static_cast<float>(120.0 + 40.0 * std::sin(0.31 * x + 0.2 * y) + 30.0 * std::cos(0.23 * y - 0.11 * x) +
                             20.0 * std::sin(0.07 * x));
    }
  }
  return l;
}

TEST(LatencyShift, RegistersSubPixelAndPixelShifts) {
  const Luma before = texture(200, 160, 0.0, 0.0);
  for (const auto& [dx, dy] : std::vector<std::pair<double, double>>{{0.3, 0.0}, {-0.05, 0.35}, {1.2, -0.4}, {0.01, 0.0}}) {
    const auto d = image_shift(before, texture(200, 160, dx, dy), Region{});
    ASSERT_TRUE(d.has_value());
    EXPECT_NEAR(d->dx_px, dx, 0.002 + 0.01 * std::abs(dx)) << dx << ", " << dy;
    EXPECT_NEAR(d->dy_px, dy, 0.002 + 0.01 * std::abs(dy)) << dx << ", " << dy;
  }
  // Negative control: the same picture again has not moved.
  const auto still = image_shift(before, texture(200, 160, 0.0, 0.0), Region{});
  ASSERT_TRUE(still.has_value());
  EXPECT_EQ(still->dx_px, 0.0);
  EXPECT_EQ(still->dy_px, 0.0);
}

TEST(LatencyShift, ARegionLooksOnlyThereAndAUniformPictureHasNoAnswer) {
  const Luma before = texture(200, 160, 0.0, 0.0);
  Luma after = texture(200, 160, 0.4, 0.0);
  // The lower half moved; the upper half, put back, did not.
  for (int r = 0; r < 80; ++r) {
    for (int c = 0; c < 200; ++c) after.value[static_cast<std::size_t>(r) * 200 + c] = before.at(c, r);
  }
  EXPECT_NEAR(image_shift(before, after, Region{0.0, 1.0, 0.55, 1.0})->dx_px, 0.4, 0.01);
  EXPECT_NEAR(image_shift(before, after, Region{0.0, 1.0, 0.0, 0.45})->dx_px, 0.0, 1e-9);
  const Luma flat{200, 160, std::vector<float>(200 * 160, 90.0f)};
  EXPECT_FALSE(image_shift(flat, flat, Region{}).has_value());
  EXPECT_FALSE(image_shift(before, texture(100, 160, 0.0, 0.0), Region{}).has_value());
  EXPECT_THROW(image_shift(before, before, Region{0.5, 0.4, 0.0, 1.0}), std::invalid_argument);
}

TEST(LatencyFrames, AnArrivalBelongsToTheLastTickBeforeIt) {
  const std::vector<TickSeen> ticks = {{10, 1000}, {11, 21000}, {12, 41000}};
  EXPECT_FALSE(frame_at(ticks, 999).has_value());
  EXPECT_EQ(frame_at(ticks, 1000).value_or(0), 10u);
  EXPECT_EQ(frame_at(ticks, 20999).value_or(0), 10u);
  EXPECT_EQ(frame_at(ticks, 21000).value_or(0), 11u);
  EXPECT_EQ(frame_at(ticks, 900000).value_or(0), 12u);
}

TEST(LatencySummary, MedianAndMax) {
  const Summary odd = summarise({45.0, 41.0, 47.5});
  EXPECT_EQ(odd.count, 3u);
  EXPECT_EQ(odd.median, 45.0);
  EXPECT_EQ(odd.min, 41.0);
  EXPECT_EQ(odd.max, 47.5);
  EXPECT_EQ(summarise({1.0, 2.0, 3.0, 10.0}).median, 2.5);
  EXPECT_EQ(summarise({}).count, 0u);
}

}  // namespace
}  // namespace fedsim::latency
