// The ND read back from its pixels: heading up (the lubber mark at the top whatever the
// heading; the selected-heading bug at its angle from it), a navaid at its relative bearing and
// range, navaids beyond range left out, the HSI's deviation bar replaced by the flag when the
// course signal fails. Negative controls: the mirror-image angle, an out-of-range navaid.
#include "displays/model/nd.hpp"
#include "common/units/units.hpp"
#include "displays/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace fedsim::displays::test {
namespace {

using units::kDegToRad;
constexpr int kSize = 400;

Image render(const NdInputs& in) {
  Image image;
  renderer().render_nd(in, kSize, kSize, image);
  return image;
}

Rect window(const Vec2& centre, double half) {
  return {centre.x() - half, centre.y() - half, centre.x() + half, centre.y() + half};
}

// Compass angle (clockwise from up) of p seen from the rose centre [deg].
double compass_deg(const NdLayout& l, const Vec2& p) {
  const Vec2 d = p - l.rose_centre_px;
  return std::atan2(d.x(), -d.y()) / kDegToRad;
}

TEST(Nd, HeadingUpLubberAndSelectedHeadingBug) {
  const NdLayout l = nd_layout(kSize, kSize);
  const Vec2 lubber = l.rose_centre_px - Vec2(0.0, l.rose_radius_px + 6.0);
  for (double heading_deg : {90.0, 250.0}) {
    NdInputs in;
    in.heading_rad = heading_deg * kDegToRad;
    in.track_rad = in.heading_rad;
    in.selected_heading_rad = (heading_deg + 40.0) * kDegToRad;
    const Image image = render(in);
    write_png(image,
              (output_dir() / ("nd_heading_" + std::to_string(heading_deg) + ".png")).string());
    EXPECT_GT(count(image, window(lubber, 3.0), is_white), 10) << "the lubber mark";
    // The bug 40 deg right of the lubber line, on the ring.
    const Vec2 expected = polar(l.rose_centre_px, l.rose_radius_px + 4.0, 40.0 * kDegToRad);
    const auto bug = centroid(image, window(expected, 12.0), is_magenta);
    ASSERT_TRUE(bug);
    EXPECT_NEAR(compass_deg(l, *bug), 40.0, 1.5);
    std::printf("heading %.0f: selected-heading bug at %+.2f deg from the lubber line\n",
                heading_deg, compass_deg(l, *bug));
    // Negative control: nothing magenta at the mirror image (what a heading-down rose shows).
    const Vec2 mirror = polar(l.rose_centre_px, l.rose_radius_px + 4.0, -40.0 * kDegToRad);
    EXPECT_EQ(count(image, window(mirror, 12.0), is_magenta), 0);
  }
}

TEST(Nd, NavaidAtItsRelativeBearingAndRange) {
  const NdLayout l = nd_layout(kSize, kSize);
  NdInputs in;
  in.heading_rad = 50.0 * kDegToRad;
  in.track_rad = in.heading_rad;
  in.range_nm = 40.0;
  in.navaids = {{"ABC", NavaidKind::kVor, 80.0 * kDegToRad, 24.0 * units::kNmToM},   // +30 deg
                {"FAR", NavaidKind::kVor, 20.0 * kDegToRad, 45.0 * units::kNmToM}};  // beyond
  const Image image = render(in);
  write_png(image, (output_dir() / "nd_navaid.png").string());
  // 24 NM of 40: 0.6 of the rose's radius (clear of the dashed half-range ring).
  const Vec2 expected = polar(l.rose_centre_px, 0.6 * l.rose_radius_px, 30.0 * kDegToRad);
  const auto c = centroid(image, window(expected, 7.0), is_cyan);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->x(), expected.x(), 1.0);
  EXPECT_NEAR(c->y(), expected.y(), 1.0);
  EXPECT_NEAR(compass_deg(l, *c), 30.0, 1.0);
  std::printf("navaid at +30 deg, 0.6 R: drawn at (%.2f, %.2f), expected (%.2f, %.2f) px\n", c->x(),
              c->y(), expected.x(), expected.y());
  // Negative controls: nothing at -30 deg; the navaid 45 NM out (range 40) is not drawn, at
  // the rose's edge or anywhere.
  const Vec2 mirror = polar(l.rose_centre_px, 0.6 * l.rose_radius_px, -30.0 * kDegToRad);
  EXPECT_EQ(count(image, window(mirror, 7.0), is_cyan), 0);
  const Vec2 edge = polar(l.rose_centre_px, l.rose_radius_px, -30.0 * kDegToRad);
  EXPECT_EQ(count(image, window(edge, 12.0), is_cyan), 0);
}

TEST(Nd, FailedCourseSignalShowsTheFlagNotTheBar) {
  const NdLayout l = nd_layout(kSize, kSize);
  NdInputs in;
  in.selected_course_rad = 0.0;  // course up: the bar is vertical, displaced sideways
  in.course = NavSignal::kValid;
  in.course_deviation_dots = 1.0;
  const Image valid = render(in);
  const Rect rose = window(l.rose_centre_px, l.rose_radius_px - 20.0);
  const auto bar = centroid(valid, rose, is_magenta);
  ASSERT_TRUE(bar);
  EXPECT_NEAR(bar->x(), l.rose_centre_px.x() + l.deviation_dot_px, 1.0);  // fly right: right
  EXPECT_EQ(count(valid, l.course_flag_px, is_red), 0);
  in.course = NavSignal::kFailed;
  const Image failed = render(in);
  write_png(failed, (output_dir() / "nd_course_failed.png").string());
  EXPECT_EQ(count(failed, rose, is_magenta), 0);
  EXPECT_GT(count(failed, l.course_flag_px, is_red), 30);
}

TEST(Nd, BadInputsNameTheField) {
  NdInputs in;
  in.navaids = {{"OK", NavaidKind::kNdb, 0.0, 1000.0}, {"BAD", NavaidKind::kVor, 0.0, NAN}};
  try {
    render(in);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("field 'navaids[1].distance_m'"), std::string::npos)
        << e.what();
  }
  in.navaids.clear();
  in.range_nm = 1.0;
  EXPECT_THROW(render(in), std::invalid_argument);
  in.range_nm = 40.0;
  EXPECT_NO_THROW(render(in));  // negative control
}

}  // namespace
}  // namespace fedsim::displays::test
