// The HUD against the image generator's own camera (visual::ChannelCamera, built from a scene
// frame and a geodetic eye pose as the visual federate builds it): HudProjection equals it for
// directions, and the drawn horizon and flight-path vector fall within 1 px of where it
// projects them; everything else is transparent. Negative control: the same measurement
// against a camera pitched 1 deg differently fails.
#include "displays/model/hud.hpp"
#include "common/units/units.hpp"
#include "displays/model/composite.hpp"
#include "displays/model/test/test_support.hpp"
#include "visual/model/channel_camera.hpp"
#include "visual/model/scene_frame.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace fedsim::displays::test {
namespace {

using units::kDegToRad;

const GeodeticPosition kOrigin{37.6 * kDegToRad, -122.4 * kDegToRad, 10.0};

view::ChannelConfig channel_400x300() {
  view::ChannelConfig c;
  c.width_px = 400;
  c.height_px = 300;
  c.horizontal_fov_rad = 40.0 * kDegToRad;
  c.vertical_fov_rad = 2.0 * std::atan(std::tan(20.0 * kDegToRad) * 300.0 / 400.0);
  return c;
}

// The visual channel's camera for an eye at the scene origin, 500 m up.
visual::ChannelCamera camera(const view::ChannelConfig& channel, double roll, double pitch,
                             double heading) {
  const visual::SceneFrame frame(kOrigin);
  visual::EyePose eye;
  eye.lat_rad = kOrigin.lat_rad;
  eye.lon_rad = kOrigin.lon_rad;
  eye.alt_msl_m = 510.0;
  eye.phi_rad = roll;
  eye.theta_rad = pitch;
  eye.psi_rad = heading;
  return visual::ChannelCamera(frame, channel, eye);
}

// Where the camera puts the direction d (NED at the eye = scene axes at the origin): a point
// 100 km along it.
Vec2 camera_pixel(const visual::ChannelCamera& cam, const Eigen::Vector3d& d_ned) {
  const auto p = cam.project(cam.eye_scene_m() + 1.0e5 * d_ned.normalized());
  EXPECT_TRUE(p);
  return {p->x_px, p->y_px};
}

// The zero-pitch line's row at column x (pixel centre x + 0.5), from two projected points.
double camera_horizon_row(const visual::ChannelCamera& cam, double heading, double x) {
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
    const visual::ChannelCamera cam = camera(channel, roll, pitch, heading);
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
  renderer().render_hud(in, channel, image);
  write_png(image, (output_dir() / "hud_horizon.png").string());
  const visual::ChannelCamera cam = camera(channel, in.roll_rad, in.pitch_rad, in.heading_true_rad);
  const view::ChannelConfig pitched = [&] {
    view::ChannelConfig c = channel;
    c.pitch_offset_rad = 1.0 * kDegToRad;
    return c;
  }();
  const visual::ChannelCamera wrong =
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
  renderer().render_hud(in, channel, image);
  write_png(image, (output_dir() / "hud_fpv.png").string());
  const visual::ChannelCamera cam = camera(channel, in.roll_rad, in.pitch_rad, in.heading_true_rad);
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

TEST(Hud, TransparentAwayFromTheSymbology) {
  const view::ChannelConfig channel = channel_400x300();
  HudInputs in;
  in.pitch_rad = 2.0 * kDegToRad;
  in.velocity_ned_mps = {70.0, 0.0, 3.0};
  in.ias_mps = 70.0;
  Image image;
  renderer().render_hud(in, channel, image);
  int clear = 0, green = 0;
  for (int row = 0; row < image.height_px; ++row) {
    for (int col = 0; col < image.width_px; ++col) {
      const Rgba8 p = image.at(col, row);
      if (p.a == 0) {
        ++clear;
        EXPECT_EQ(p.r + p.g + p.b, 0);  // premultiplied: no colour without alpha
      } else if (p.g >= p.r && p.g >= p.b) {
        ++green;
      }
    }
  }
  const int total = image.width_px * image.height_px;
  EXPECT_GT(clear, 0.9 * total);
  EXPECT_EQ(clear + green, total) << "every drawn pixel is green";
  for (int corner : {0, 1, 2, 3}) {
    EXPECT_EQ(image.at(corner % 2 ? 399 : 0, corner / 2 ? 299 : 0).a, 0);
  }
  // Negative control: the symbology is there.
  EXPECT_GT(total - clear, 1000);
}

TEST(Hud, CompositeOverBlendsPremultipliedAlpha) {
  Image channel(2, 1), hud(2, 1);
  channel.set(0, 0, {200, 100, 50, 255});
  channel.set(1, 0, {200, 100, 50, 255});
  hud.set(0, 0, {0, 128, 0, 128});  // half-covering green, premultiplied
  hud.set(1, 0, {0, 0, 0, 0});
  composite_over(channel, hud);
  const Rgba8 a = channel.at(0, 0), b = channel.at(1, 0);
  // out = hud + channel (255 - 128) / 255: 200*127/255 = 99.6, 128 + 49.8, 24.9.
  EXPECT_EQ(a.r, 100);
  EXPECT_EQ(a.g, 178);
  EXPECT_EQ(a.b, 25);
  EXPECT_EQ(a.a, 255);
  EXPECT_EQ(b.r, 200);  // transparent: the channel unchanged
  EXPECT_EQ(b.g, 100);
  EXPECT_EQ(b.b, 50);
  // Negative control: straight-alpha blending would give g = 128*0.5 + 100*0.5 = 114.
  EXPECT_NE(a.g, 114);
  Image small(1, 1);
  EXPECT_THROW(composite_over(small, hud), std::invalid_argument);
}

TEST(Hud, RenderedHudOverAPicture) {
  const view::ChannelConfig channel = channel_400x300();
  HudInputs in;
  in.velocity_ned_mps = {70.0, 0.0, 3.0};
  in.ias_mps = 70.0;
  Image hud;
  renderer().render_hud(in, channel, hud);
  Image picture(400, 300);
  for (std::size_t i = 0; i < picture.rgba.size(); i += 4) {
    picture.rgba[i] = 90, picture.rgba[i + 1] = 120, picture.rgba[i + 2] = 200,
    picture.rgba[i + 3] = 255;
  }
  const Image before = picture;
  composite_over(picture, hud);
  for (int row = 0; row < 300; ++row) {
    for (int col = 0; col < 400; ++col) {
      const Rgba8 h = hud.at(col, row), p = picture.at(col, row), o = before.at(col, row);
      if (h.a == 0) {
        ASSERT_EQ(p.r, o.r);
        ASSERT_EQ(p.g, o.g);
      } else if (h.a == 255) {
        ASSERT_EQ(p.g, h.g);
      }
    }
  }
}

TEST(Hud, BadInputsNameTheField) {
  HudInputs in;
  in.velocity_ned_mps.z() = NAN;
  Image image;
  try {
    renderer().render_hud(in, channel_400x300(), image);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("field 'velocity_ned_mps[2]'"), std::string::npos);
  }
  in.velocity_ned_mps.z() = 0.0;
  view::ChannelConfig bad = channel_400x300();
  bad.horizontal_fov_rad = -1.0;
  EXPECT_THROW(renderer().render_hud(in, bad, image), std::invalid_argument);
  EXPECT_NO_THROW(renderer().render_hud(in, channel_400x300(), image));
}

}  // namespace
}  // namespace fedsim::displays::test
