// The HUD (common/hud) against the image generator's own camera (ChannelCamera, built from a
// scene frame and a geodetic eye pose as this federate builds it): HudProjection equals it for
// directions, and the drawn horizon and flight-path vector fall within 1 px of where it projects
// them. Negative control: the same measurement against a camera pitched 1 deg differently fails.
// Here, where the two meet: fedsim-visual --hud draws the one over the other.
#include "common/hud/hud.hpp"
#include "common/hud/test/hud_test_support.hpp"
#include "common/symbology/test/picture_probes.hpp"
#include "common/units/units.hpp"
#include "visual/model/channel_camera.hpp"
#include "visual/model/scene_frame.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace fedsim::visual::test {
namespace {

using hud::HudInputs;
using hud::HudProjection;
using hud::test::channel_400x300;
using hud::test::renderer;
using picture::Image;
using picture::Rgba8;
using symbology::Rect;
using symbology::Vec2;
using symbology::test::centroid;
using units::kDegToRad;

const GeodeticPosition kOrigin{37.6 * kDegToRad, -122.4 * kDegToRad, 10.0};

// The visual channel's camera for an eye at the scene origin, 500 m up.
ChannelCamera camera(const view::ChannelConfig& channel, double roll, double pitch, double heading) {
  const SceneFrame frame(kOrigin);
  EyePose eye;
  eye.lat_rad = kOrigin.lat_rad;
  eye.lon_rad = kOrigin.lon_rad;
  eye.alt_msl_m = 510.0;
  eye.phi_rad = roll;
  eye.theta_rad = pitch;
  eye.psi_rad = heading;
  return ChannelCamera(frame, channel, eye);
}

// Where the camera puts the direction d (NED at the eye = scene axes at the origin): a point
// 100 km along it.
Vec2 camera_pixel(const ChannelCamera& cam, const Eigen::Vector3d& d_ned) {
  const auto p = cam.project(cam.eye_scene_m() + 1.0e5 * d_ned.normalized());
  EXPECT_TRUE(p);
  return {p->x_px, p->y_px};
}

// The zero-pitch line's row at column x (pixel centre x + 0.5), from two projected points.
double camera_horizon_row(const ChannelCamera& cam, double heading, double x) {
  const Vec2 a = camera_pixel(cam, HudProjection::direction(heading - 0.2, 0.0));
  const Vec2 b = camera_pixel(cam, HudProjection::direction(heading + 0.2, 0.0));
  return a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x());
}

double alpha(const Image& image, int col, int row) { return image.at(col, row).a / 255.0; }

TEST(Hud, ProjectionEqualsTheChannelCamera) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  for (int k = 0; k < 200; ++k) {
    view::ChannelConfig channel = channel_400x300();
    channel.heading_offset_rad = u(random) * 50.0 * kDegToRad;
    channel.pitch_offset_rad = u(random) * 10.0 * kDegToRad;
    channel.roll_offset_rad = u(random) * 5.0 * kDegToRad;
    const double roll = u(random) * 60.0 * kDegToRad, pitch = u(random) * 30.0 * kDegToRad;
    const double heading = u(random) * 180.0 * kDegToRad;
    const ChannelCamera cam = camera(channel, roll, pitch, heading);
    const HudProjection hud(channel, roll, pitch, heading);
    const Eigen::Vector3d d = cam.ray_scene(200.0 + 180.0 * u(random), 150.0 + 130.0 * u(random));
    const auto p = hud.project(d);
    ASSERT_TRUE(p);
    const Vec2 q = camera_pixel(cam, d);
    EXPECT_NEAR(p->x(), q.x(), 1e-3);
    EXPECT_NEAR(p->y(), q.y(), 1e-3);
    ++compared;
  }
  EXPECT_EQ(compared, 200);
}

TEST(Hud, HorizonWhereTheCameraProjectsIt) {
  const view::ChannelConfig channel = channel_400x300();
  HudInputs in;
  in.pitch_rad = 4.0 * kDegToRad;
  in.roll_rad = 10.0 * kDegToRad;
  in.heading_true_rad = 100.0 * kDegToRad;
  in.ias_mps = 70.0;
  in.altitude_m = 500.0;
  Image image;
  renderer().render(in, channel, image);
  write_png(image, (output_dir() / "hud_horizon.png").string());
  const ChannelCamera cam = camera(channel, in.roll_rad, in.pitch_rad, in.heading_true_rad);
  const view::ChannelConfig pitched = [&] {
    view::ChannelConfig c = channel;
    c.pitch_offset_rad = 1.0 * kDegToRad;
    return c;
  }();
  const ChannelCamera wrong =
      camera(pitched, in.roll_rad, in.pitch_rad, in.heading_true_rad);
  // Columns holding only the horizon: between the speed box and the ladder, and right of it.
  for (int col : {100, 290}) {
    double sum = 0.0, weight = 0.0;
    for (int row = 0; row < image.height_px; ++row) {
      sum += alpha(image, col, row) * (row + 0.5);
      weight += alpha(image, col, row);
    }
    ASSERT_GT(weight, 0.5) << col;  // a 1-px line: its coverage sums to about 1
    const double measured = sum / weight;
    const double expected = camera_horizon_row(cam, in.heading_true_rad, col + 0.5);
    EXPECT_NEAR(measured, expected, 1.0) << "column " << col;
    std::printf("horizon in column %d: row %.2f, the camera %.2f px\n", col, measured, expected);
    EXPECT_GT(std::abs(measured - camera_horizon_row(wrong, in.heading_true_rad, col + 0.5)), 1.0);
  }
}

TEST(Hud, FlightPathVectorWhereTheCameraProjectsTheVelocity) {
  const view::ChannelConfig channel = channel_400x300();
  HudInputs in;
  in.pitch_rad = 4.0 * kDegToRad;
  in.heading_true_rad = 100.0 * kDegToRad;
  const double gamma = -2.5 * kDegToRad, track = in.heading_true_rad + 2.0 * kDegToRad;
  in.velocity_ned_mps = 70.0 * HudProjection::direction(track, gamma);
  in.ias_mps = 70.0;
  Image image;
  renderer().render(in, channel, image);
  write_png(image, (output_dir() / "hud_fpv.png").string());
  const ChannelCamera cam = camera(channel, in.roll_rad, in.pitch_rad, in.heading_true_rad);
  const Vec2 expected = camera_pixel(cam, in.velocity_ned_mps);
  // Horizontal centre: every pixel of the symbol (circle, wings and fin are symmetric left and
  // right); vertical: the wings only (the fin sits on top of the circle).
  const Rect box{expected.x() - 16.0, expected.y() - 10.0, expected.x() + 16.0,
                 expected.y() + 10.0};
  const auto all = centroid(image, box, [](const Rgba8& p) { return p.a > 128; });
  ASSERT_TRUE(all);
  double sum = 0.0, weight = 0.0;
  for (int row = static_cast<int>(box.y0); row < static_cast<int>(box.y1); ++row) {
    for (int col = static_cast<int>(box.x0); col < static_cast<int>(box.x1); ++col) {
      if (std::abs(col + 0.5 - all->x()) < 6.5) continue;  // the circle (radius 4.5 px) and fin
      sum += alpha(image, col, row) * (row + 0.5);
      weight += alpha(image, col, row);
    }
  }
  ASSERT_GT(weight, 5.0);
  const Vec2 measured(all->x(), sum / weight);
  EXPECT_NEAR(measured.x(), expected.x(), 1.0);
  EXPECT_NEAR(measured.y(), expected.y(), 1.0);
  std::printf("FPV at (%.2f, %.2f), the camera (%.2f, %.2f) px\n", measured.x(), measured.y(),
              expected.x(), expected.y());
  view::ChannelConfig pitched = channel;
  pitched.pitch_offset_rad = 1.0 * kDegToRad;
  const Vec2 wrong =
      camera_pixel(camera(pitched, 0.0, in.pitch_rad, in.heading_true_rad), in.velocity_ned_mps);
  EXPECT_GT((measured - wrong).norm(), 1.0);  // negative control
}

}  // namespace
}  // namespace fedsim::visual::test
