// Golden-free smoke test: KSFO from the 28R approach at 3 NM on a 3 deg path, by day, written
// to a PNG. Checks what can be checked without a golden image: the picture is the channel's
// size, the PNG reads back identically, the threshold projects onto pavement-grey pixels that
// differ from the grass beside the runway, the sky above is bluer than the ground below, and
// approach lights appear where they project.
#include "visual/model/renderer.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

TEST(Smoke, KsfoFrom28RApproachAtThreeMiles) {
  Renderer renderer(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options()));
  const auto& end = test::ksfo_end("28R");
  const double distance_m = 3.0 * units::kNmToM;
  // On a 3 deg path to the aiming point 400 m beyond the threshold.
  const EyePose eye = test::approach_eye(
      end, distance_m, (distance_m + 400.0) * std::tan(3.0 * kDegToRad), -3.0 * kDegToRad);
  view::ChannelConfig channel;
  channel.width_px = 320;
  channel.height_px = 240;
  Environment day;
  day.sun_elevation_rad = 35.0 * kDegToRad;
  day.sun_azimuth_rad = 200.0 * kDegToRad;
  day.visibility_m = 40000.0;
  const RenderedFrame frame = renderer.render(channel, eye, day);
  ASSERT_EQ(frame.image.width_px, 320);
  ASSERT_EQ(frame.image.height_px, 240);
  std::printf("render %.1f ms, %zu triangles, %zu lights; %s\n", frame.stats.render_time_ms,
              frame.stats.triangles, frame.stats.lights, renderer.description().c_str());

  const auto path = (test::output_dir() / "ksfo_28r_3nm_day.png").string();
  picture::write_png(frame.image, path);
  std::printf("wrote %s\n", path.c_str());
  const picture::Image back = picture::read_png(path);
  ASSERT_EQ(back.width_px, frame.image.width_px);
  for (int row = 0; row < back.height_px; row += 7) {
    for (int col = 0; col < back.width_px; col += 5) {
      const picture::Rgba8 a = back.at(col, row), b = frame.image.at(col, row);
      ASSERT_EQ(a.r, b.r);
      ASSERT_EQ(a.g, b.g);
      ASSERT_EQ(a.b, b.b);
    }
  }

  // Pavement is grey, the grass beside it green: 300 m past the threshold on the centreline
  // against 150 m to the right of it.
  const Scene& scene = renderer.scene();
  const RunwayEndInfo& info = scene.runway_ends[scene.find_end("28R")];
  const Eigen::Vector3d forward(std::cos(info.heading_true_rad), std::sin(info.heading_true_rad),
                                0.0);
  const Eigen::Vector3d right(-forward.y(), forward.x(), 0.0);
  const ChannelCamera camera = renderer.camera(channel, eye);
  const auto greenness = [&](const Eigen::Vector3d& p) {
    const auto px = camera.project(p);
    EXPECT_TRUE(px && camera.in_picture(*px));
    const picture::Rgba8 c = frame.image.at(px->column(), px->row());
    return c.g - 0.5 * (c.r + c.b);
  };
  const double runway = greenness(info.threshold_scene_m + 300.0 * forward + 12.0 * right);
  const double grass = greenness(info.threshold_scene_m + 300.0 * forward + 150.0 * right);
  EXPECT_GT(grass, runway + 8.0) << "grass " << grass << ", runway " << runway;
  // Sky blue at the top, ground below.
  const picture::Rgba8 sky = frame.image.at(160, 5);
  EXPECT_GT(sky.b, sky.r + 40);
  EXPECT_GT(test::mean_luminance(frame.image, 0, 0, 320, 40),
            test::mean_luminance(frame.image, 0, 200, 320, 40));
  // Most approach lights in the picture stand out from their surroundings.
  int in_picture = 0, standing_out = 0;
  for (const auto& l : scene.lights_of(scene.find_end("28R"), LightRole::kApproachCentreline)) {
    const auto p = camera.project(l.position_scene_m.cast<double>());
    if (!p || !camera.in_picture(*p)) continue;
    ++in_picture;
    const double here = test::luminance_at(frame.image, p->column(), p->row());
    const double around = test::mean_luminance(frame.image, p->column() + 3, p->row() - 1, 3, 3);
    standing_out += here > around + 0.05 ? 1 : 0;
  }
  EXPECT_GT(in_picture, 100);
  EXPECT_GT(standing_out, in_picture / 2) << standing_out << " of " << in_picture;
}

TEST(Smoke, RenderTimeFromTheLentClock) {
  Renderer renderer(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options()));
  view::ChannelConfig channel;
  const EyePose eye = test::approach_eye(test::ksfo_end("28R"), 2000.0, 130.0, -3.0 * kDegToRad);
  EXPECT_EQ(renderer.render(channel, eye, Environment{}).stats.render_time_ms, 0.0);  // no clock
  std::int64_t now_ns = 0;
  renderer.set_clock([&now_ns] { return now_ns += 1000000; });  // 1 ms a reading
  const RenderStats s = renderer.render(channel, eye, Environment{}).stats;
  EXPECT_DOUBLE_EQ(s.submit_time_ms, 1.0);  // start, draws issued, image read: three readings
  EXPECT_DOUBLE_EQ(s.render_time_ms, 2.0);
  EXPECT_EQ(s.triangles, renderer.scene().triangles.size() / 3);
  EXPECT_EQ(s.lights, renderer.scene().lights.size());
}

}  // namespace
}  // namespace fedsim::visual
