// Sky and daylight in rendered pictures: day against night brightness, the sunset horizon
// warmer towards the sun, the picture inside a cloud, and the light threshold of the sky model
// against the RVR formula's published figures.
#include "visual/model/renderer.hpp"
#include "visual/model/sky_model.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

class Sky : public ::testing::Test {
 protected:
  Sky() : renderer_(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options())) {
    channel_.width_px = 320;
    channel_.height_px = 240;
    eye_ = test::approach_eye(test::ksfo_end("28R"), 3000.0, 180.0, 5.0 * kDegToRad);
  }

  picture::Image render(const Environment& e) { return renderer_.render(channel_, eye_, e).image; }

  Renderer renderer_;
  view::ChannelConfig channel_;
  EyePose eye_;
};

TEST_F(Sky, DayIsBrighterThanNight) {
  Environment day, night, twilight;
  day.sun_elevation_rad = 40.0 * kDegToRad;
  twilight.sun_elevation_rad = -5.0 * kDegToRad;
  night.sun_elevation_rad = -25.0 * kDegToRad;
  const picture::Image d = render(day), t = render(twilight), n = render(night);
  picture::write_png(d, (test::output_dir() / "sky_day.png").string());
  picture::write_png(n, (test::output_dir() / "sky_night.png").string());
  // The upper fifth of the picture is sky.
  const double sky_day = test::mean_luminance(d, 0, 0, 320, 48);
  const double sky_twilight = test::mean_luminance(t, 0, 0, 320, 48);
  const double sky_night = test::mean_luminance(n, 0, 0, 320, 48);
  std::printf("sky luminance: day %.3f, twilight %.3f, night %.4f\n", sky_day, sky_twilight,
              sky_night);
  EXPECT_GT(sky_day, 0.4);
  EXPECT_LT(sky_night, 0.03);
  EXPECT_GT(sky_day, 20.0 * sky_night);
  EXPECT_GT(sky_twilight, sky_night);
  EXPECT_LT(sky_twilight, sky_day);
  // The ground darkens with the sky.
  EXPECT_GT(test::mean_luminance(d, 0, 200, 320, 40),
            5.0 * test::mean_luminance(n, 0, 200, 320, 40));
}

TEST_F(Sky, SunsetHorizonIsWarmerTowardsTheSun) {
  Environment sunset;
  sunset.sun_elevation_rad = 1.0 * kDegToRad;
  sunset.sun_azimuth_rad = eye_.psi_rad;  // ahead
  const picture::Image ahead = render(sunset);
  sunset.sun_azimuth_rad = eye_.psi_rad - units::kPi;  // behind
  const picture::Image behind = render(sunset);
  // The sky a few degrees above the horizon (pitch +5 deg: the horizon is below the centre).
  const picture::Rgba8 a = ahead.at(40, 100), b = behind.at(40, 100);
  const double warm_ahead = static_cast<double>(a.r) / std::max<int>(a.b, 1);
  const double warm_behind = static_cast<double>(b.r) / std::max<int>(b.b, 1);
  EXPECT_GT(warm_ahead, 1.1 * warm_behind);
}

TEST_F(Sky, InsideACloudEverythingIsCloud) {
  Environment e;
  e.cloud = CloudLayer{100.0, 800.0, 60.0};  // the eye at ~180 m is inside
  const picture::Image in_cloud = render(e);
  double lo = 1.0, hi = 0.0;
  for (int row = 0; row < 240; row += 4) {
    for (int col = 0; col < 320; col += 4) {
      const double l = test::luminance_at(in_cloud, col, row);
      lo = std::min(lo, l);
      hi = std::max(hi, l);
    }
  }
  EXPECT_LT(hi - lo, 0.03);  // uniform: no ground, no sky, no horizon
  // Below the base the ground is seen again (negative control).
  e.cloud = CloudLayer{400.0, 1200.0, 60.0};
  const picture::Image below = render(e);
  EXPECT_GT(std::abs(test::luminance_at(below, 160, 10) - test::luminance_at(below, 160, 230)),
            0.05);
}

TEST(SkyModel, LightThresholdFollowsTheRvrFormula) {
  // log10 E_T = 0.57 log10 B + 0.05 (log10 B)^2 - 6.66: B = 1e4 cd/m^2 -> 10^-3.58 lux,
  // B = 100 -> 10^-5.32, B = 1 -> 10^-6.66 (and no lower below that).
  EXPECT_NEAR(std::log10(light_threshold_lux(1.0e4)), -3.58, 1e-9);
  EXPECT_NEAR(std::log10(light_threshold_lux(100.0)), -5.32, 1e-9);
  EXPECT_NEAR(std::log10(light_threshold_lux(1.0)), -6.66, 1e-9);
  EXPECT_DOUBLE_EQ(light_threshold_lux(1.0e-3), light_threshold_lux(1.0));
  EXPECT_THROW(light_threshold_lux(std::nan("")), std::invalid_argument);
  // The day/night switch of RVR systems (2 fL = 6.85 cd/m^2) falls in civil twilight.
  EXPECT_GT(sky_state(-2.0 * kDegToRad).background_luminance_cd_per_m2, 6.85);
  EXPECT_LT(sky_state(-6.0 * kDegToRad).background_luminance_cd_per_m2, 6.85);
}

}  // namespace
}  // namespace fedsim::visual
