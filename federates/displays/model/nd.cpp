#include "displays/model/nd.hpp"

#include "common/symbology/palette.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fedsim::displays {

using namespace symbology;  // the drawing (canvas, glyphs, colours) the displays share

namespace {

using units::kDegToRad;
using units::kRadToDeg;
namespace colour = symbology::palette;

constexpr double kDesign = 1000.0;
const Vec2 kCentre{500.0, 560.0};
const Vec2 kOrigin{0.0, 0.0};
constexpr double kRadius = 340.0;
constexpr double kDotUnits = 70.0;
constexpr double kMaxDots = 2.25;
constexpr Rect kCourseFlag{570.0, 610.0, 670.0, 650.0};
constexpr double kLine = 3.0;
constexpr double kSmallText = 18.0, kText = 22.0, kBigText = 28.0;

int compass_degrees(double rad) {
  double deg = std::fmod(rad * kRadToDeg, 360.0);
  if (deg < 0.0) deg += 360.0;
  const int shown = static_cast<int>(std::lround(deg)) % 360;
  return shown == 0 ? 360 : shown;
}

// Rotates the frame so that up is the compass direction `rad` on the heading-up rose.
Transform rose_frame(double relative_rad) {
  return Transform::translation(kCentre) * Transform::rotation(relative_rad);
}

void draw_rose(Canvas& c, double heading_rad) {
  c.circle(kCentre, kRadius, kLine, colour::kWhite);
  c.push(rose_frame(-heading_rad));
  for (int deg = 0; deg < 360; deg += 5) {
    const double a = deg * kDegToRad;
    const double length = deg % 10 == 0 ? 22.0 : 11.0;
    c.line(polar(kOrigin, kRadius, a), polar(kOrigin, kRadius - length, a), kLine, colour::kWhite);
    if (deg % 30 == 0) {
      char label[24];
      std::snprintf(label, sizeof label, "%d", deg / 10);
      c.push(Transform::rotation(a));
      c.text(label, {0.0, -kRadius + 45.0}, kText, Align::kCentre, Face::kMono, colour::kWhite);
      c.pop();
    }
  }
  c.pop();
}

void draw_range_ring(Canvas& c, double range_nm) {
  const double r = 0.5 * kRadius;
  for (int i = 0; i < 48; i += 2) {
    c.arc(kCentre, r, units::kTwoPi * i / 48.0, units::kTwoPi * (i + 1) / 48.0, 2.0,
          colour::kWhite);
  }
  char label[24];
  std::snprintf(label, sizeof label, "%g", 0.5 * range_nm);
  c.text(label, polar(kCentre, r + 22.0, -50.0 * kDegToRad), kSmallText, Align::kCentre,
         Face::kMono, colour::kWhite);
}

void navaid_symbol(Canvas& c, NavaidKind kind, const Vec2& p) {
  const double s = 11.0;
  const auto hexagon = [&] {
    std::vector<Vec2> h;
    for (int k = 0; k < 6; ++k) h.push_back(polar(p, s, (30.0 + 60.0 * k) * kDegToRad));
    c.polyline(h, 2.5, colour::kCyan, true);
  };
  const auto square = [&](double half) {
    c.rect_outline({p.x() - half, p.y() - half, p.x() + half, p.y() + half}, 2.5, colour::kCyan);
  };
  switch (kind) {
    case NavaidKind::kVor:
      hexagon();
      break;
    case NavaidKind::kVorDme:
      hexagon();
      square(s + 3.0);
      break;
    case NavaidKind::kDme:
      square(s);
      break;
    case NavaidKind::kNdb:
      for (int k = 0; k < 8; ++k)
        c.fill_circle(polar(p, s, k * 45.0 * kDegToRad), 2.5, colour::kCyan);
      c.fill_circle(p, 3.0, colour::kCyan);
      break;
    case NavaidKind::kAirport:
      c.circle(p, s, 2.5, colour::kCyan);
      break;
  }
}

void draw_navaids(Canvas& c, const NdInputs& in) {
  for (const Navaid& n : in.navaids) {
    const double nm = n.distance_m * units::kMToNm;
    if (nm > in.range_nm) continue;
    const Vec2 p = polar(kCentre, nm / in.range_nm * kRadius, n.bearing_rad - in.heading_rad);
    navaid_symbol(c, n.kind, p);
    c.text(n.ident, p + Vec2(24.0, 18.0), kSmallText, Align::kLeft, Face::kSans, colour::kCyan);
  }
}

void draw_bearing_pointer(Canvas& c, const BearingPointer& b, bool double_line) {
  if (!b.valid) return;  // a pointer without a station is removed, never parked
  const Colour col = b.source == BearingSource::kVor ? colour::kGreen : colour::kCyan;
  c.push(rose_frame(b.relative_bearing_rad));
  const double head = -kRadius + 8.0, tail = kRadius - 8.0;
  const std::vector<double> offsets =
      double_line ? std::vector<double>{-6.0, 6.0} : std::vector<double>{0.0};
  for (double x : offsets) {
    c.line({x, head + 30.0}, {x, head + 90.0}, kLine, col);
    c.line({x, tail - 90.0}, {x, tail}, kLine, col);
  }
  c.polyline({{-14.0, head + 26.0}, {0.0, head}, {14.0, head + 26.0}}, kLine, col);
  c.polyline({{-14.0, tail - 20.0}, {0.0, tail - 40.0}, {14.0, tail - 20.0}}, kLine, col);
  c.pop();
}

void draw_bearing_legend(Canvas& c, const BearingPointer& b, int number, const Vec2& at,
                         Align align) {
  const Colour col = b.source == BearingSource::kVor ? colour::kGreen : colour::kCyan;
  char label[24];
  std::snprintf(label, sizeof label, "%s %d", b.source == BearingSource::kVor ? "VOR" : "ADF",
                number);
  c.text(label, at, kText, align, Face::kSans, col);
  c.text(b.valid && !b.ident.empty() ? b.ident : std::string("---"), at + Vec2(0.0, 34.0), kText,
         align, Face::kSans, col);
}

// The HSI: course pointer (white; it is the crew's selection, drawn whatever the signal), and
// with a valid signal the deviation dots, the magenta deviation bar and the TO/FROM pointer.
void draw_course(Canvas& c, const NdInputs& in) {
  c.push(rose_frame(in.selected_course_rad - in.heading_rad));
  const double r = kRadius - 26.0;
  c.line({0.0, -r + 24.0}, {0.0, -130.0}, 5.0, colour::kWhite);
  c.fill_polygon({{0.0, -r}, {-14.0, -r + 26.0}, {14.0, -r + 26.0}}, colour::kWhite);
  c.line({0.0, 130.0}, {0.0, r}, 5.0, colour::kWhite);
  if (in.course == NavSignal::kValid) {
    for (int d : {-2, -1, 1, 2}) c.circle({d * kDotUnits, 0.0}, 7.0, 2.5, colour::kWhite);
    const double x = std::clamp(in.course_deviation_dots, -kMaxDots, kMaxDots) * kDotUnits;
    c.line({x, -120.0}, {x, 120.0}, 6.0, colour::kMagenta);
    if (in.to_from != ToFrom::kOff) {
      const double s = in.to_from == ToFrom::kTo ? -1.0 : 1.0;  // TO points along the course
      c.fill_polygon({{0.0, s * 95.0}, {-12.0, s * 75.0}, {12.0, s * 75.0}}, colour::kWhite);
    }
  }
  c.pop();
  if (in.course == NavSignal::kFailed) {
    const char* text = in.course_is_localizer ? "LOC" : "VOR";
    c.fill_rect(kCourseFlag, colour::kBlack);
    c.rect_outline(kCourseFlag, 2.0, colour::kRed);
    c.text(text, kCourseFlag.centre(), kText, Align::kCentre, Face::kSans, colour::kRed);
  }
}

void draw_track_and_bug(Canvas& c, const NdInputs& in) {
  c.push(rose_frame(in.track_rad - in.heading_rad));
  c.line({0.0, -40.0}, {0.0, -kRadius + 30.0}, 2.0, colour::kWhite);
  c.line({-8.0, -0.5 * kRadius}, {8.0, -0.5 * kRadius}, 2.0, colour::kWhite);
  c.pop();
  if (!in.selected_heading_rad) return;
  c.push(rose_frame(*in.selected_heading_rad - in.heading_rad));
  const double r = kRadius + 2.0;
  c.polyline({{-16.0, -r},
              {-16.0, -r - 14.0},
              {16.0, -r - 14.0},
              {16.0, -r},
              {7.0, -r},
              {0.0, -r - 9.0},
              {-7.0, -r}},
             kLine, colour::kMagenta, true);
  c.pop();
}

void draw_aircraft_and_lubber(Canvas& c) {
  c.polyline({{500.0, 530.0}, {485.0, 590.0}, {515.0, 590.0}}, kLine, colour::kWhite, true);
  c.line({470.0, 560.0}, {530.0, 560.0}, kLine, colour::kWhite);
  // The lubber line: the fixed heading mark at the top of the rose.
  const double top = kCentre.y() - kRadius;
  c.fill_polygon({{500.0, top + 4.0}, {486.0, top - 22.0}, {514.0, top - 22.0}}, colour::kWhite);
}

void draw_readouts(Canvas& c, const NdInputs& in) {
  char text[32];
  std::snprintf(text, sizeof text, "%03d", compass_degrees(in.heading_rad));
  c.fill_rect({450.0, 140.0, 550.0, 184.0}, colour::kBlack);
  c.rect_outline({450.0, 140.0, 550.0, 184.0}, 2.0, colour::kWhite);
  c.text(text, {500.0, 162.0}, kBigText, Align::kCentre, Face::kMono, colour::kWhite);
  c.text("HDG", {440.0, 162.0}, kSmallText, Align::kRight, Face::kSans, colour::kGreen);
  c.text("MAG", {560.0, 162.0}, kSmallText, Align::kLeft, Face::kSans, colour::kGreen);
  if (in.ground_speed_mps) {
    std::snprintf(text, sizeof text, "GS %d",
                  static_cast<int>(std::lround(*in.ground_speed_mps * units::kMpsToKt)));
    c.text(text, {40.0, 50.0}, kText, Align::kLeft, Face::kMono, colour::kWhite);
  }
  if (in.true_airspeed_mps) {
    std::snprintf(text, sizeof text, "TAS %d",
                  static_cast<int>(std::lround(*in.true_airspeed_mps * units::kMpsToKt)));
    c.text(text, {40.0, 90.0}, kText, Align::kLeft, Face::kMono, colour::kWhite);
  }
  if (in.course != NavSignal::kNotTuned) {
    c.text(in.course_ident, {960.0, 50.0}, kText, Align::kRight, Face::kSans, colour::kGreen);
  }
  if (in.dme_valid) {
    std::snprintf(text, sizeof text, "DME %.1f", in.dme_distance_m * units::kMToNm);
  } else {
    std::snprintf(text, sizeof text, "DME ---");
  }
  c.text(text, {960.0, 90.0}, kText, Align::kRight, Face::kMono, colour::kWhite);
}

}  // namespace

NdLayout nd_layout(int width_px, int height_px) {
  NdLayout l;
  const double side = std::min(width_px, height_px);
  l.px_per_unit = side / kDesign;
  l.origin_px = {0.5 * (width_px - side), 0.5 * (height_px - side)};
  l.rose_centre_px = l.to_px(kCentre);
  l.rose_radius_px = kRadius * l.px_per_unit;
  l.deviation_dot_px = kDotUnits * l.px_per_unit;
  const Vec2 a = l.to_px({kCourseFlag.x0, kCourseFlag.y0}),
             b = l.to_px({kCourseFlag.x1, kCourseFlag.y1});
  l.course_flag_px = {a.x(), a.y(), b.x(), b.y()};
  return l;
}

void draw_nd(Canvas& c, const NdInputs& in) {
  validate(in, "ND inputs");
  const NdLayout l = nd_layout(c.width_px(), c.height_px());
  c.push(Transform::translation(l.origin_px) * Transform::scaling(l.px_per_unit));
  draw_rose(c, in.heading_rad);
  draw_range_ring(c, in.range_nm);
  draw_navaids(c, in);
  draw_bearing_pointer(c, in.bearing1, false);
  draw_bearing_pointer(c, in.bearing2, true);
  draw_course(c, in);
  draw_track_and_bug(c, in);
  draw_aircraft_and_lubber(c);
  draw_readouts(c, in);
  draw_bearing_legend(c, in.bearing1, 1, {40.0, 900.0}, Align::kLeft);
  draw_bearing_legend(c, in.bearing2, 2, {960.0, 900.0}, Align::kRight);
  c.pop();
}

}  // namespace fedsim::displays
