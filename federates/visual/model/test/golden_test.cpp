// Golden image of the scene with a perceptual tolerance (image_compare.hpp): KSFO 28R from 1 NM
// out on the 3 deg path, by day, 160x120, compared with test/golden/ksfo_28r_1nm.png (mean
// absolute difference <= 2 levels, <= 0.5 % of pixels off by more than 48 levels). Negative
// control: the same eye pitched 1 deg differently (the horizon 2.4 px lower) fails the same
// comparison. FEDSIM_UPDATE_GOLDEN=1 rewrites the stored picture (review it before committing).
// Also: compare_images() itself (identical, one changed pixel, size mismatch).
#include "common/picture/image_compare.hpp"
#include "common/util/build_paths.hpp"
#include "visual/model/renderer.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

const std::string kGolden = fedsim::util::source_dir() + "/federates/visual/model/test/golden" + "/ksfo_28r_1nm.png";

picture::Image render_from(double pitch_offset_deg) {
  static Renderer renderer(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options()));
  const auto& end = test::ksfo_end("28R");
  const double distance_m = units::kNmToM;
  const EyePose eye = test::approach_eye(end, distance_m, (distance_m + 400.0) * std::tan(3.0 * kDegToRad),
                                         (-3.0 + pitch_offset_deg) * kDegToRad);
  view::ChannelConfig channel;
  channel.width_px = 160;
  channel.height_px = 120;
  Environment day;
  day.sun_elevation_rad = 35.0 * kDegToRad;
  day.sun_azimuth_rad = 200.0 * kDegToRad;
  day.visibility_m = 40000.0;
  return renderer.render(channel, eye, day).image;
}

TEST(Golden, SceneFromAKnownEyePointMatchesTheStoredPicture) {
  const picture::Image image = render_from(0.0);
  picture::write_png(image, (test::output_dir() / "golden_ksfo_28r_1nm.png").string());
  if (std::getenv("FEDSIM_UPDATE_GOLDEN") != nullptr) picture::write_png(image, kGolden);
  // The stored PNG has no alpha; read_png gives 255, as the renderer's opaque frames.
  const picture::Image golden = picture::read_png(kGolden);
  const picture::ImageDifference same = picture::compare_images(image, golden);
  std::printf("scene vs golden: %s\n", same.describe().c_str());
  EXPECT_TRUE(same.within(picture::ImageTolerance{})) << same.describe();
  // Negative control: pitched 1 deg up, the horizon and the runway move: the comparison fails.
  const picture::ImageDifference pitched = picture::compare_images(render_from(1.0), golden);
  std::printf("pitched 1 deg vs golden: %s\n", pitched.describe().c_str());
  EXPECT_FALSE(pitched.within(picture::ImageTolerance{})) << pitched.describe();
}

TEST(Golden, CompareImagesCountsWhatDiffers) {
  picture::Image a(10, 10);
  for (auto& v : a.rgba) v = 100;
  picture::Image b = a;
  EXPECT_EQ(picture::compare_images(a, b).mean_abs_diff, 0.0);
  b.set(3, 4, {255, 100, 100, 255});  // one pixel of 100 off by 155 in one channel
  const picture::ImageDifference d = picture::compare_images(a, b);
  EXPECT_DOUBLE_EQ(d.mean_abs_diff, 155.0 / 300.0);
  EXPECT_DOUBLE_EQ(d.differing_fraction, 0.01);
  b.set(3, 4, {140, 100, 100, 255});  // 40 levels: below the 48-level threshold
  EXPECT_DOUBLE_EQ(picture::compare_images(a, b).differing_fraction, 0.0);
  EXPECT_THROW(picture::compare_images(a, picture::Image(10, 11)), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::visual
