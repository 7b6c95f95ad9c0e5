// PAPI of KSFO 28R read back from rendered pictures: with the eye 2.0, 3.0 and 4.0 deg above the
// aiming point (1500 m from it, on the extended centreline) the four units show 4 red, 2 white
// and 2 red (the two nearest the runway red), 4 white (ICAO Annex 14 5.3.6: a 3 deg path, units
// set at 3d30', 3d10', 2d50', 2d30' from the runway outwards). The eye's height is computed from
// the runway record's end elevations, not from the model's runway profile.
#include "visual/model/renderer.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

enum class Seen { kRed, kWhite, kOther };

Seen classify(const picture::Rgba8& p) {
  if (p.r > 150 && p.g < 0.6 * p.r && p.b < 0.6 * p.r) return Seen::kRed;
  if (p.r > 170 && p.g > 0.8 * p.r && p.b > 0.6 * p.r) return Seen::kWhite;
  return Seen::kOther;
}

std::string pattern(const std::vector<Seen>& s) {
  std::string out;
  for (Seen x : s) out += x == Seen::kRed ? 'R' : (x == Seen::kWhite ? 'W' : '?');
  return out;
}

class PapiPicture : public ::testing::Test {
 protected:
  PapiPicture() : renderer_(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options())) {
    channel_.width_px = 320;
    channel_.height_px = 240;
    channel_.horizontal_fov_rad = 20.0 * kDegToRad;
    channel_.vertical_fov_rad = 15.0 * kDegToRad;
    day_.sun_elevation_rad = 40.0 * kDegToRad;
  }

  // The units as seen from the approach, outermost (leftmost) first.
  std::string seen_at(double angle_deg, const Environment& environment,
                      std::vector<double>* columns = nullptr) {
    const auto& end = test::ksfo_end("28R");
    const auto& opposite = test::ksfo_end("10L");
    const double aim_m = 400.0;  // Table 5-1, LDA >= 2400 m
    const double d_m = 1500.0;   // eye to the aiming point, horizontally
    // Runway surface at the aiming point, linear between the published end elevations.
    const double from_end_m = end.displaced_threshold_m + aim_m;
    const double aim_elevation_m =
        end.end.elevation_m +
        (opposite.end.elevation_m - end.end.elevation_m) * from_end_m / end.length_m;
    const double height_m =
        aim_elevation_m - end.threshold.elevation_m + d_m * std::tan(angle_deg * kDegToRad);
    const EyePose eye = test::approach_eye(end, d_m - aim_m, height_m, -angle_deg * kDegToRad);
    const RenderedFrame f = renderer_.render(channel_, eye, environment);
    const Scene& scene = renderer_.scene();
    const int index = scene.find_end("28R");
    std::vector<LightPoint> units = scene.lights_of(index, LightRole::kPapi);
    EXPECT_EQ(units.size(), 4u);
    const ChannelCamera camera = renderer_.camera(channel_, eye);
    std::vector<std::pair<double, Seen>> by_column;
    for (const auto& u : units) {
      const auto p = camera.project(u.position_scene_m.cast<double>());
      EXPECT_TRUE(p && camera.in_picture(*p));
      if (!p || !camera.in_picture(*p)) return "";
      by_column.emplace_back(p->x_px, classify(f.image.at(p->column(), p->row())));
    }
    std::sort(by_column.begin(), by_column.end(),
              [](auto& a, auto& b) { return a.first < b.first; });
    std::vector<Seen> seen;
    for (const auto& [x, s] : by_column) {
      seen.push_back(s);
      if (columns != nullptr) columns->push_back(x);
    }
    if (angle_deg == 3.0) {
      picture::write_png(f.image, (test::output_dir() / "papi_28r_3deg.png").string());
    }
    return pattern(seen);
  }

  Renderer renderer_;
  view::ChannelConfig channel_;
  Environment day_;
};

TEST_F(PapiPicture, SettingsAreThoseOfAThreeDegreePath) {
  const Scene& scene = renderer_.scene();
  const int index = scene.find_end("28R");
  ASSERT_GE(index, 0);
  EXPECT_DOUBLE_EQ(scene.runway_ends[index].aiming_point_m, 400.0);
  EXPECT_DOUBLE_EQ(scene.runway_ends[index].papi_along_m, 400.0);
  std::vector<double> settings;
  for (const auto& u : scene.lights_of(index, LightRole::kPapi)) {
    settings.push_back(u.papi_transition_rad / kDegToRad);
  }
  std::sort(settings.begin(), settings.end());
  ASSERT_EQ(settings.size(), 4u);
  EXPECT_NEAR(settings[0], 2.5, 1e-5);
  EXPECT_NEAR(settings[1], 2.0 + 50.0 / 60.0, 1e-5);
  EXPECT_NEAR(settings[2], 3.0 + 10.0 / 60.0, 1e-5);
  EXPECT_NEAR(settings[3], 3.5, 1e-5);
}

TEST_F(PapiPicture, FourRedLow) { EXPECT_EQ(seen_at(2.0, day_), "RRRR"); }

TEST_F(PapiPicture, TwoWhiteTwoRedOnThePath) {
  std::vector<double> columns;
  EXPECT_EQ(seen_at(3.0, day_, &columns), "WWRR");
  // The units are left of the runway: every one left of the picture's centre (the aiming
  // point, on the centreline, is at the centre).
  ASSERT_EQ(columns.size(), 4u);
  for (double x : columns) EXPECT_LT(x, 160.0);
}

TEST_F(PapiPicture, FourWhiteHigh) { EXPECT_EQ(seen_at(4.0, day_), "WWWW"); }

TEST_F(PapiPicture, SameAtNight) {
  Environment night = day_;
  night.sun_elevation_rad = -20.0 * kDegToRad;
  EXPECT_EQ(seen_at(2.0, night), "RRRR");
  EXPECT_EQ(seen_at(3.0, night), "WWRR");
  EXPECT_EQ(seen_at(4.0, night), "WWWW");
}

}  // namespace
}  // namespace fedsim::visual
