// Golden image of the PFD with a perceptual tolerance (common/picture/image_compare.hpp): pitch
// 2.5 deg up, roll 10 deg right, 140 kt, 2500 ft, descending 700 ft/min, heading 284, localizer
// half a dot right, glide slope a quarter dot low, FD on, FMA; 240x240 compared with
// test/golden/pfd_known_state.png (mean |diff| <= 1 level, <= 0.25 % of pixels (144) off by more
// than 48: text and thin lines make most of a PFD, so a tighter limit than the scene's). Negative
// controls: a pitch 1 deg higher (1.8 % differ here), and 150 instead of 140 kt (0.51 %: the
// speed tape and readout), each fail it.
// FEDSIM_UPDATE_GOLDEN=1 rewrites the stored picture (review it before committing).
#include "common/picture/image_compare.hpp"
#include "common/util/build_paths.hpp"
#include "displays/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

namespace fedsim::displays {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
const picture::ImageTolerance kPfdTolerance{1.0, 0.0025, 48};
const std::string kGolden = fedsim::util::source_dir() + "/federates/displays/model/test/golden" + "/pfd_known_state.png";

PfdInputs known_state() {
  PfdInputs in;
  in.pitch_rad = 2.5 * kDeg;
  in.roll_rad = 10.0 * kDeg;
  in.ias_mps = 140.0 * 1852.0 / 3600.0;
  in.altitude_m = 2500.0 * 0.3048;
  in.vertical_speed_mps = -700.0 * 0.3048 / 60.0;
  in.heading_magnetic_rad = 284.0 * kDeg;
  in.heading_true_rad = 297.0 * kDeg;
  in.baro_setting_pa = 101325.0;
  in.localizer = NavSignal::kValid;
  in.localizer_deviation_dots = 0.5;
  in.glideslope = NavSignal::kValid;
  in.glideslope_deviation_dots = -0.25;
  in.flight_director = {true, true, true, 3.0 * kDeg, 5.0 * kDeg};
  in.modes.autothrottle_active = "MCP SPD";
  in.modes.roll_active = "VOR/LOC";
  in.modes.pitch_active = "G/S";
  in.modes.afds_status = "CMD";
  return in;
}

picture::Image render(const PfdInputs& in) {
  picture::Image image;
  test::renderer().render_pfd(in, 240, 240, image);
  return image;
}

TEST(Golden, PfdAtAKnownStateMatchesTheStoredPicture) {
  const picture::Image image = render(known_state());
  picture::write_png(image, (test::output_dir() / "golden_pfd_known_state.png").string());
  if (std::getenv("FEDSIM_UPDATE_GOLDEN") != nullptr) picture::write_png(image, kGolden);
  const picture::Image golden = picture::read_png(kGolden);
  const picture::ImageDifference same = picture::compare_images(image, golden);
  std::printf("PFD vs golden: %s\n", same.describe().c_str());
  EXPECT_TRUE(same.within(kPfdTolerance)) << same.describe();

  PfdInputs pitched = known_state();
  pitched.pitch_rad += 1.0 * kDeg;
  const picture::ImageDifference p = picture::compare_images(render(pitched), golden);
  std::printf("pitch +1 deg vs golden: %s\n", p.describe().c_str());
  EXPECT_FALSE(p.within(kPfdTolerance)) << p.describe();

  PfdInputs faster = known_state();
  faster.ias_mps = 150.0 * 1852.0 / 3600.0;
  const picture::ImageDifference f = picture::compare_images(render(faster), golden);
  std::printf("150 kt vs golden: %s\n", f.describe().c_str());
  EXPECT_FALSE(f.within(kPfdTolerance)) << f.describe();
}

}  // namespace
}  // namespace fedsim::displays
