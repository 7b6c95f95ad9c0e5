// Fog by Koschmieder and light points by Allard's law, read back from rendered pictures of KSFO
// 28R at dusk (sun 3 deg below the horizon) in fog of visibility V = 800 m, the eye on the 3 deg
// path:
//  - at 2 V from the threshold the runway surface is invisible: its contrast against the
//    horizon sky (the fog's airlight) is below the 5 % threshold that defines V, while the
//    threshold lights there are still seen (Allard: I exp(-3 d/V) / d^2 above E_T);
//  - at 0.5 V both are seen;
//  - by day the same lights at 2 V fall below the (higher) daylight threshold: they vanish, as
//    RVR assessment has it (negative control of the light rule).
#include "visual/model/renderer.hpp"
#include "visual/model/sky_model.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

constexpr double kVisibilityM = 800.0;

class Fog : public ::testing::Test {
 protected:
  Fog() : renderer_(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options())) {
    channel_.width_px = 320;
    channel_.height_px = 240;
    channel_.horizontal_fov_rad = 30.0 * kDegToRad;
    channel_.vertical_fov_rad = 22.5 * kDegToRad;
    dusk_.sun_elevation_rad = -3.0 * kDegToRad;
    dusk_.sun_azimuth_rad = 110.0 * kDegToRad;  // behind the eye
    dusk_.visibility_m = kVisibilityM;
    dusk_.haze_top_agl_m = 500.0;
  }

  struct Sight {
    double surface_contrast;    // runway pavement against the horizon sky
    int threshold_lights_seen;  // of the threshold lights in the picture
    int threshold_lights_in_picture;
    double background_luminance;  // horizon sky
  };

  Sight look_from(double before_threshold_m, const Environment& environment, const char* png) {
    const auto& end = test::ksfo_end("28R");
    const double height = (before_threshold_m + 400.0) * std::tan(3.0 * kDegToRad);
    const EyePose eye = test::approach_eye(end, before_threshold_m, height, -3.0 * kDegToRad);
    const RenderedFrame f = renderer_.render(channel_, eye, environment);
    picture::write_png(f.image, (test::output_dir() / png).string());
    const ChannelCamera camera = renderer_.camera(channel_, eye);
    const Scene& scene = renderer_.scene();
    const int index = scene.find_end("28R");
    // Bare pavement 100 m past the threshold, 8 m right of the centreline (between the
    // designation, the centreline stripes and the touchdown-zone markings).
    const RunwayEndInfo& info = scene.runway_ends[index];
    const Eigen::Vector3d forward(std::cos(info.heading_true_rad), std::sin(info.heading_true_rad),
                                  0.0);
    const Eigen::Vector3d right(-forward.y(), forward.x(), 0.0);
    const auto p = camera.project(info.threshold_scene_m + 100.0 * forward + 8.0 * right);
    EXPECT_TRUE(p && camera.in_picture(*p));
    // The horizon sky, 2 px above the horizon (3 deg above the centre: pitch -3 deg).
    const int horizon_row = static_cast<int>(
        120.0 * (1.0 - std::tan(3.0 * kDegToRad) / std::tan(0.5 * channel_.vertical_fov_rad)));
    Sight s;
    s.background_luminance = test::mean_luminance(f.image, 150, horizon_row - 3, 20, 2);
    const double surface = f.image.at(p->column(), p->row()).luminance();
    s.surface_contrast = std::abs(surface - s.background_luminance) / s.background_luminance;
    s.threshold_lights_seen = s.threshold_lights_in_picture = 0;
    for (const auto& l : scene.lights_of(index, LightRole::kThreshold)) {
      const auto q = camera.project(l.position_scene_m.cast<double>());
      if (!q || !camera.in_picture(*q)) continue;
      ++s.threshold_lights_in_picture;
      const picture::Rgba8 px = f.image.at(q->column(), q->row());
      // Green: the light's colour stands out from the grey fog.
      if (px.g > px.r + 25 && px.luminance() > 1.05 * s.background_luminance)
        ++s.threshold_lights_seen;
    }
    return s;
  }

  Renderer renderer_;
  view::ChannelConfig channel_;
  Environment dusk_;
};

TEST_F(Fog, KoschmiederAttenuationOfTheModel) {
  // The extinction coefficient makes the transmittance 5 % over the visibility.
  EXPECT_NEAR(std::exp(-extinction_per_m(kVisibilityM) * kVisibilityM), 0.05, 1e-12);
  EXPECT_THROW(extinction_per_m(std::nan("")), std::invalid_argument);
}

TEST_F(Fog, AtTwiceTheVisibilityTheRunwayIsGoneButItsLightsAreSeen) {
  const Sight far = look_from(2.0 * kVisibilityM, dusk_, "fog_dusk_2v.png");
  EXPECT_LT(far.surface_contrast, 0.05);
  EXPECT_GT(far.threshold_lights_in_picture, 10);
  EXPECT_GT(far.threshold_lights_seen, far.threshold_lights_in_picture / 2);
  std::printf("2V: surface contrast %.4f, threshold lights seen %d of %d\n", far.surface_contrast,
              far.threshold_lights_seen, far.threshold_lights_in_picture);
}

TEST_F(Fog, AtHalfTheVisibilityBothAreSeen) {
  const Sight near = look_from(0.5 * kVisibilityM, dusk_, "fog_dusk_half_v.png");
  EXPECT_GT(near.surface_contrast, 0.05);
  EXPECT_GT(near.threshold_lights_in_picture, 10);
  EXPECT_EQ(near.threshold_lights_seen, near.threshold_lights_in_picture);
  std::printf("0.5V: surface contrast %.4f, threshold lights seen %d of %d\n",
              near.surface_contrast, near.threshold_lights_seen, near.threshold_lights_in_picture);
}

TEST_F(Fog, ByDayTheLightsAtTwiceTheVisibilityAreBelowThreshold) {
  Environment day = dusk_;
  day.sun_elevation_rad = 30.0 * kDegToRad;
  const Sight far = look_from(2.0 * kVisibilityM, day, "fog_day_2v.png");
  EXPECT_LT(far.surface_contrast, 0.05);
  EXPECT_EQ(far.threshold_lights_seen, 0);
  // The thresholds that make the difference (sky_model.hpp): dusk ~2e-6 lux, day ~2e-4 lux.
  const double dusk_threshold =
      light_threshold_lux(sky_state(dusk_.sun_elevation_rad).background_luminance_cd_per_m2);
  const double day_threshold =
      light_threshold_lux(sky_state(day.sun_elevation_rad).background_luminance_cd_per_m2);
  EXPECT_GT(day_threshold, 30.0 * dusk_threshold);
}

TEST_F(Fog, ClearAirShowsTheRunwayAtTheSameDistance) {
  // Negative control of the surface rule: without fog the same view has the runway in contrast.
  Environment clear = dusk_;
  clear.visibility_m = 50000.0;
  const Sight far = look_from(2.0 * kVisibilityM, clear, "clear_dusk_1600m.png");
  EXPECT_GT(far.surface_contrast, 0.05);
}

}  // namespace
}  // namespace fedsim::visual
