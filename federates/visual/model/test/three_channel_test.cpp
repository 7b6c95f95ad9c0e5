// Three channels L/C/R at heading offsets -hfov, 0, +hfov meet edge to edge: a point a quarter
// pixel inside the centre channel's right edge lights the centre's last column and nothing in
// the right channel; a quarter pixel beyond it lights the right channel's first column and
// nothing in the centre; and of many points across the whole 3 x hfov field each is drawn in
// exactly one channel, in the column the analytic projection of that channel gives. A layout
// whose channels overlap by a degree fails the same check (negative control).
#include "visual/model/renderer.hpp"
#include "visual/model/sky_model.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

constexpr double kHfov = 40.0 * kDegToRad;
constexpr int kWidth = 320, kHeight = 240;

struct Probe {
  double azimuth_rad;    // in body axes, right positive
  double elevation_rad;  // in body axes, up positive
};

// The analytic column of a body direction in a channel whose boresight is yawed by `offset`.
double analytic_column(const Probe& p, double offset, double hfov) {
  const Eigen::Vector3d d(std::cos(p.elevation_rad) * std::cos(p.azimuth_rad - offset),
                          std::cos(p.elevation_rad) * std::sin(p.azimuth_rad - offset),
                          -std::sin(p.elevation_rad));
  if (d.x() <= 0.0) return -1.0e9;
  return 0.5 * kWidth * (1.0 + d.y() / d.x() / std::tan(0.5 * hfov));
}

class ThreeChannels : public ::testing::Test {
 protected:
  ThreeChannels() : frame_({37.6 * kDegToRad, -122.4 * kDegToRad, 0.0}) {
    eye_.lat_rad = frame_.origin().lat_rad;
    eye_.lon_rad = frame_.origin().lon_rad;
    eye_.alt_msl_m = 300.0;
    eye_.psi_rad = 30.0 * kDegToRad;
    centre_.width_px = kWidth;
    centre_.height_px = kHeight;
    centre_.horizontal_fov_rad = kHfov;
    centre_.vertical_fov_rad = 30.0 * kDegToRad;
    night_.sun_elevation_rad = -30.0 * kDegToRad;
    night_.visibility_m = 1.0e6;
  }

  // Lit pixels of light points placed 2 km away in the given body directions, per channel.
  std::vector<picture::Image> render(const std::vector<Probe>& probes,
                            const std::vector<view::ChannelConfig>& channels) {
    Scene scene{frame_};
    const double threshold =
        light_threshold_lux(sky_state(night_.sun_elevation_rad).background_luminance_cd_per_m2);
    const ChannelCamera body(frame_, view::ChannelConfig{}, eye_);  // no offsets: the body frame
    for (const Probe& p : probes) {
      const Eigen::Vector3d dir_body(std::cos(p.elevation_rad) * std::cos(p.azimuth_rad),
                                     std::cos(p.elevation_rad) * std::sin(p.azimuth_rad),
                                     -std::sin(p.elevation_rad));
      LightPoint l;
      l.position_scene_m =
          (body.eye_scene_m() + 2000.0 * (body.scene_from_channel() * dir_body)).cast<float>();
      l.intensity_cd = static_cast<float>(20.0 * threshold * 2000.0 * 2000.0);
      scene.lights.push_back(l);
    }
    Renderer renderer(std::move(scene));
    std::vector<picture::Image> images;
    for (const auto& c : channels) images.push_back(renderer.render(c, eye_, night_).image);
    return images;
  }

  static std::vector<int> lit_columns(const picture::Image& image) {
    std::vector<int> columns;
    for (int row = 0; row < image.height_px; ++row) {
      for (int col = 0; col < image.width_px; ++col) {
        if (test::luminance_at(image, col, row) > 0.3) columns.push_back(col);
      }
    }
    return columns;
  }

  SceneFrame frame_;
  EyePose eye_;
  view::ChannelConfig centre_;
  Environment night_;
};

TEST_F(ThreeChannels, LayoutIsEdgeToEdge) {
  const auto c = view::three_channel_layout(centre_);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].name, "left");
  EXPECT_NEAR(c[0].heading_offset_rad, -kHfov, 1e-12);
  EXPECT_NEAR(c[2].heading_offset_rad, kHfov, 1e-12);
  view::ChannelConfig too_wide = centre_;
  too_wide.horizontal_fov_rad = 130.0 * kDegToRad;
  EXPECT_THROW(view::three_channel_layout(too_wide), std::invalid_argument);
}

TEST_F(ThreeChannels, APointAQuarterPixelEitherSideOfTheBoundary) {
  // The angle of a quarter pixel at the edge: tan(a) = tan(hfov/2) (1 -+ 2 * 0.25 / W).
  const double t = std::tan(0.5 * kHfov);
  const Probe inside{std::atan(t * (1.0 - 0.5 / kWidth)), 0.0};
  const Probe outside{std::atan(t * (1.0 + 0.5 / kWidth)), 0.0};
  const auto channels = view::three_channel_layout(centre_);
  const auto in_images = render({inside}, channels);
  EXPECT_EQ(lit_columns(in_images[1]), std::vector<int>{kWidth - 1});  // centre, last column
  EXPECT_TRUE(lit_columns(in_images[2]).empty());
  const auto out_images = render({outside}, channels);
  EXPECT_TRUE(lit_columns(out_images[1]).empty());
  EXPECT_EQ(lit_columns(out_images[2]), std::vector<int>{0});  // right, first column
  // Mirror image on the left boundary.
  const auto left_images =
      render({{-inside.azimuth_rad, 0.0}, {-outside.azimuth_rad, 0.05}}, channels);
  EXPECT_EQ(lit_columns(left_images[1]), std::vector<int>{0});
  EXPECT_EQ(lit_columns(left_images[0]), std::vector<int>{kWidth - 1});
}

TEST_F(ThreeChannels, EveryPointInExactlyOneChannelAtItsAnalyticColumn) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> azimuth(-1.45 * kHfov, 1.45 * kHfov);
  std::uniform_real_distribution<double> elevation(-10.0 * kDegToRad, 10.0 * kDegToRad);
  const auto channels = view::three_channel_layout(centre_);
  std::vector<Probe> probes;
  while (probes.size() < 80) {
    const Probe p{azimuth(random), elevation(random)};
    bool near_border = false;  // keep clear of pixel borders so the expected column is certain
    for (const auto& c : channels) {
      const double x = analytic_column(p, c.heading_offset_rad, kHfov);
      if (x > -1.0 && x < kWidth + 1.0 && std::abs(x - std::round(x)) < 0.05) near_border = true;
    }
    if (!near_border) probes.push_back(p);
  }
  const auto images = render(probes, channels);
  int total = 0;
  for (std::size_t k = 0; k < channels.size(); ++k) {
    std::vector<int> expected;
    for (const auto& p : probes) {
      const double x = analytic_column(p, channels[k].heading_offset_rad, kHfov);
      if (x >= 0.0 && x < kWidth) expected.push_back(static_cast<int>(std::floor(x)));
    }
    std::vector<int> lit = lit_columns(images[k]);
    std::sort(lit.begin(), lit.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(lit, expected) << channels[k].name;
    total += static_cast<int>(lit.size());
  }
  EXPECT_EQ(total, static_cast<int>(probes.size()));  // no gap, no overlap

  // Negative control: channels 1 deg closer together overlap, so some points show twice.
  std::vector<view::ChannelConfig> overlapping = channels;
  overlapping[0].heading_offset_rad += 1.0 * kDegToRad;
  overlapping[2].heading_offset_rad -= 1.0 * kDegToRad;
  const auto twice = render(probes, overlapping);
  int drawn = 0;
  for (const auto& image : twice) drawn += static_cast<int>(lit_columns(image).size());
  EXPECT_GT(drawn, static_cast<int>(probes.size()));
}

}  // namespace
}  // namespace fedsim::visual
