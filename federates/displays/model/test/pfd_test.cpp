// The PFD read back from its pixels: horizon where the pitch puts it and tilted by the roll,
// the readouts' text, the ILS pointers at the dots commanded, the G/S and FD flags in place of
// invalid pointers, and errors naming the field. Each check has a negative control that fails
// it (a 1 deg pitch error, a 3 deg roll error, a quarter-dot deviation error).
#include "displays/model/pfd.hpp"
#include "common/units/units.hpp"
#include "displays/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fedsim::displays::test {
namespace {

using units::kDegToRad;
constexpr int kSize = 400;

PfdInputs level_flight() {
  PfdInputs in;
  in.ias_mps = 130.0 * units::kKtToMps;
  in.altitude_m = 3000.0 * units::kFtToM;
  in.heading_magnetic_rad = 90.0 * kDegToRad;
  in.heading_true_rad = 90.0 * kDegToRad;
  return in;
}

Image render(const PfdInputs& in) {
  Image image;
  renderer().render_pfd(in, kSize, kSize, image);
  return image;
}

TEST(Pfd, HorizonAtThePixelThePitchImplies) {
  const PfdLayout l = pfd_layout(kSize, kSize);
  ASSERT_DOUBLE_EQ(l.pixels_per_degree, 4.0);  // 10 units/deg, 1000 units in 400 px
  const int column = static_cast<int>(l.adi_centre_px.x());
  for (double pitch_deg : {5.0, -5.0, 12.5}) {
    PfdInputs in = level_flight();
    in.pitch_rad = pitch_deg * kDegToRad;
    const Image image = render(in);
    write_png(image, (output_dir() / ("pfd_pitch_" + std::to_string(pitch_deg) + ".png")).string());
    const auto boundary = sky_ground_boundary(image, column, static_cast<int>(l.adi_px.y0),
                                              static_cast<int>(l.adi_px.y1));
    ASSERT_TRUE(boundary) << pitch_deg;
    // Nose up puts the horizon below the aircraft symbol.
    const double expected = l.adi_centre_px.y() + pitch_deg * l.pixels_per_degree;
    EXPECT_NEAR(*boundary, expected, 0.75) << "pitch " << pitch_deg << " deg";
    std::printf("pitch %+5.1f deg: horizon at row %.2f, expected %.2f px\n", pitch_deg, *boundary,
                expected);
    // Negative control: 1 deg more or less is 4 px away and fails the same check.
    for (double error : {-1.0, 1.0}) {
      EXPECT_GT(std::abs(*boundary - (expected + error * l.pixels_per_degree)), 0.75);
    }
  }
}

TEST(Pfd, RollTiltsTheHorizonByTheRollAngle) {
  const PfdLayout l = pfd_layout(kSize, kSize);
  const int y0 = static_cast<int>(l.adi_px.y0), y1 = static_cast<int>(l.adi_px.y1);
  for (double roll_deg : {20.0, -20.0, 8.0}) {
    PfdInputs in = level_flight();
    in.roll_rad = roll_deg * kDegToRad;
    const Image image = render(in);
    // The boundary in the columns 58-75 px either side of the centre (outside the aircraft
    // symbol's wings, inside the window), fitted by least squares: a row is a whole pixel, the
    // fit over 36 columns resolves the slope to a few hundredths of a degree.
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (int side : {-1, 1}) {
      for (int dx = 58; dx < 76; ++dx) {
        const int col = static_cast<int>(l.adi_centre_px.x()) + side * dx;
        const auto y = sky_ground_boundary(image, col, y0, y1);
        ASSERT_TRUE(y) << roll_deg << " column " << col;
        const double x = col + 0.5;
        sx += x, sy += *y, sxx += x * x, sxy += x * *y, ++n;
      }
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    // Right wing down: the horizon's right end rises (rows counted downwards).
    const double measured_deg = -std::atan(slope) / kDegToRad;
    EXPECT_NEAR(measured_deg, roll_deg, 0.5) << "roll " << roll_deg;
    std::printf("roll %+5.1f deg: horizon slope %+.2f deg\n", roll_deg, measured_deg);
    EXPECT_GT(std::abs(measured_deg - (roll_deg + 2.0)), 0.5);  // negative control
    EXPECT_GT(std::abs(measured_deg - (roll_deg - 2.0)), 0.5);
  }
}

TEST(Pfd, ReadoutsShowTheAltitudeAndSpeed) {
  const PfdLayout l = pfd_layout(kSize, kSize);
  PfdInputs a = level_flight(), b = level_flight();
  b.altitude_m = 1230.0 * units::kFtToM;
  b.ias_mps = 150.0 * units::kKtToMps;
  const Image ia = render(a), ib = render(b), ia2 = render(a);
  EXPECT_GT(differing_pixels(ia, ib, l.altitude_readout_px), 40);
  EXPECT_GT(differing_pixels(ia, ib, l.speed_readout_px), 40);
  // Negative control: the same inputs draw the same pixels (what differs above is the text).
  EXPECT_EQ(differing_pixels(ia, ia2, l.altitude_readout_px), 0);
  EXPECT_EQ(differing_pixels(ia, ia2, l.speed_readout_px), 0);
  // White digits inside the black boxes (their outlines left out).
  const auto inside = [](const Rect& r) { return Rect{r.x0 + 3, r.y0 + 3, r.x1 - 3, r.y1 - 3}; };
  EXPECT_GT(count(ia, inside(l.altitude_readout_px), is_light), 40);
  EXPECT_GT(count(ia, inside(l.speed_readout_px), is_light), 40);
  PfdInputs blank = level_flight();
  blank.ias_mps = 0.0;  // negative control of the count: a narrower "0"
  EXPECT_LT(count(render(blank), inside(l.speed_readout_px), is_light),
            count(ia, inside(l.speed_readout_px), is_light));
}

TEST(Pfd, LocalizerDiamondMovesByTheDotsCommanded) {
  const PfdLayout l = pfd_layout(kSize, kSize);
  ASSERT_DOUBLE_EQ(l.localizer_dot_px, 20.0);
  for (double dots : {1.0, -1.5, 0.5, 0.0}) {
    PfdInputs in = level_flight();
    in.localizer = NavSignal::kValid;
    in.localizer_deviation_dots = dots;
    const Image image = render(in);
    const auto c = centroid(image, l.localizer_scale_px, is_magenta);
    ASSERT_TRUE(c) << dots;
    // Fly right (+): the beam, and the diamond, are right of centre.
    const double expected = l.localizer_centre_px.x() + dots * l.localizer_dot_px;
    EXPECT_NEAR(c->x(), expected, 1.0) << dots << " dots";
    std::printf("localizer %+4.1f dots: diamond at x %.2f, expected %.2f px\n", dots, c->x(),
                expected);
    EXPECT_NEAR(c->y(), l.localizer_centre_px.y(), 1.0);
    EXPECT_GT(std::abs(c->x() - (expected + 0.25 * l.localizer_dot_px)), 1.0);  // control
  }
}

TEST(Pfd, GlideSlopeDiamondMovesUpForFlyUp) {
  const PfdLayout l = pfd_layout(kSize, kSize);
  for (double dots : {1.0, -2.0}) {
    PfdInputs in = level_flight();
    in.glideslope = NavSignal::kValid;
    in.glideslope_deviation_dots = dots;
    const auto c = centroid(render(in), l.glideslope_scale_px, is_magenta);
    ASSERT_TRUE(c);
    const double expected = l.glideslope_centre_px.y() - dots * l.glideslope_dot_px;
    EXPECT_NEAR(c->y(), expected, 1.0) << dots;
    EXPECT_GT(std::abs(c->y() - (l.glideslope_centre_px.y() + dots * l.glideslope_dot_px)), 1.0);
  }
}

TEST(Pfd, InvalidGlideSlopeShowsTheFlagAndNoDiamond) {
  const PfdLayout l = pfd_layout(kSize, kSize);
  PfdInputs in = level_flight();
  in.glideslope = NavSignal::kFailed;
  in.glideslope_deviation_dots = 1.0;  // a stale value must not be drawn
  const Image failed = render(in);
  write_png(failed, (output_dir() / "pfd_gs_failed.png").string());
  EXPECT_EQ(count(failed, l.glideslope_scale_px, is_magenta), 0);
  EXPECT_GT(count(failed, l.glideslope_scale_px, is_red), 30);
  // Negative control: valid, the diamond and no flag.
  in.glideslope = NavSignal::kValid;
  const Image valid = render(in);
  EXPECT_GT(count(valid, l.glideslope_scale_px, is_magenta), 30);
  EXPECT_EQ(count(valid, l.glideslope_scale_px, is_red), 0);
  // Not tuned: neither.
  in.glideslope = NavSignal::kNotTuned;
  const Image off = render(in);
  EXPECT_EQ(count(off, l.glideslope_scale_px, is_magenta), 0);
  EXPECT_EQ(count(off, l.glideslope_scale_px, is_red), 0);
}

TEST(Pfd, FlightDirectorBarsOnlyWhenValid) {
  const PfdLayout l = pfd_layout(kSize, kSize);
  const Rect adi = l.adi_px;
  PfdInputs in = level_flight();
  in.flight_director = {true, true, true, 3.0 * kDegToRad, 10.0 * kDegToRad};
  const Image valid = render(in);
  EXPECT_GT(count(valid, adi, is_magenta), 200);
  EXPECT_EQ(count(valid, l.flight_director_flag_px, is_red), 0);
  // The pitch bar 3 deg above the centre, the roll bar right of it for a right-bank command.
  const auto pitch_bar =
      centroid(valid, {adi.x0, adi.y0, l.adi_centre_px.x() - 10.0, adi.y1}, is_magenta);
  ASSERT_TRUE(pitch_bar);
  EXPECT_NEAR(pitch_bar->y(), l.adi_centre_px.y() - 3.0 * l.pixels_per_degree, 1.0);

  in.flight_director.pitch_valid = false;
  in.flight_director.roll_valid = false;
  const Image invalid = render(in);
  EXPECT_EQ(count(invalid, adi, is_magenta), 0);
  EXPECT_GT(count(invalid, l.flight_director_flag_px, is_red), 20);

  in.flight_director.on = false;
  const Image off = render(in);
  EXPECT_EQ(count(off, adi, is_magenta), 0);
  EXPECT_EQ(count(off, l.flight_director_flag_px, is_red), 0);
}

TEST(Pfd, BadInputsNameTheField) {
  const auto message = [](const PfdInputs& in) -> std::string {
    try {
      render(in);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  PfdInputs in = level_flight();
  in.pitch_rad = std::nan("");
  EXPECT_NE(message(in).find("field 'pitch_rad': not a finite number"), std::string::npos)
      << message(in);
  in = level_flight();
  in.altitude_m = 1.0e6;
  EXPECT_NE(message(in).find("field 'altitude_m'"), std::string::npos) << message(in);
  in = level_flight();
  in.selected_speed_mps = -1.0;
  EXPECT_NE(message(in).find("field 'selected_speed_mps'"), std::string::npos);
  in = level_flight();
  in.modes.roll_active = "A VERY LONG MODE";
  EXPECT_NE(message(in).find("field 'modes.roll_active'"), std::string::npos);
  in = level_flight();
  in.flight_director.roll_command_rad = INFINITY;
  EXPECT_NE(message(in).find("flight_director.roll_command_rad"), std::string::npos);
  Image image;
  EXPECT_THROW(renderer().render_pfd(level_flight(), 8, 400, image), std::invalid_argument);
  EXPECT_EQ(message(level_flight()), "no error");  // negative control
}

TEST(Pfd, RenderTimeFromTheLentClock) {
  DisplayRenderer& r = renderer();
  std::int64_t now = 0;
  r.set_clock([&now] { return now += 2'000'000; });  // each reading 2 ms later
  Image image;
  const DisplayStats s = r.render_pfd(level_flight(), kSize, kSize, image);
  r.set_clock(nullptr);
  EXPECT_DOUBLE_EQ(s.render_time_ms, 2.0);
  EXPECT_GT(s.triangles, 500u);
  EXPECT_EQ(r.render_pfd(level_flight(), kSize, kSize, image).render_time_ms, 0.0);
}

}  // namespace
}  // namespace fedsim::displays::test
