#include "displays/model/pfd.hpp"

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

// Design-unit geometry (pfd.hpp): one place, so that the layout and the drawing agree.
constexpr double kDesign = 1000.0;
const Vec2 kAdiCentre{500.0, 400.0};
constexpr Rect kAdi{290.0, 165.0, 710.0, 635.0};
constexpr Rect kLadderWindow{330.0, 245.0, 670.0, 585.0};  // below the bank pointer
constexpr double kUnitsPerDeg = 10.0;
constexpr double kLadderRangeDeg = 20.0;  // rungs drawn within this of the present pitch
constexpr double kBankRadius = 190.0;
constexpr double kDotUnits = 50.0;
const Vec2 kLocCentre{500.0, 605.0};
const Vec2 kGsCentre{690.0, 400.0};
constexpr double kMaxDots = 2.25;  // a pointer beyond the scale stays pegged at its edge

constexpr Rect kSpeedTape{120.0, 165.0, 230.0, 635.0};
constexpr double kUnitsPerKt = 4.0;
constexpr Rect kSpeedReadout{100.0, 375.0, 222.0, 425.0};
constexpr Rect kAltitudeTape{770.0, 165.0, 880.0, 635.0};
constexpr double kUnitsPerFt = 0.4;
constexpr Rect kAltitudeReadout{778.0, 372.0, 908.0, 428.0};
constexpr Rect kVsi{918.0, 205.0, 985.0, 595.0};
const Vec2 kHeadingCentre{500.0, 1050.0};
constexpr double kHeadingRadius = 310.0;
constexpr Rect kHeadingWindow{250.0, 690.0, 750.0, 1000.0};
constexpr Rect kFdFlag{315.0, 235.0, 375.0, 265.0};

constexpr double kLine = 3.0;  // stroke width of scales [units]
constexpr double kSmallText = 20.0, kText = 24.0, kBigText = 30.0;  // cap heights [units]

double clamp_dots(double dots) { return std::clamp(dots, -kMaxDots, kMaxDots); }

// --- Attitude sphere --------------------------------------------------------------------

// The attitude frame: origin at the ADI centre, a along the horizon, b down across it; a pitch
// p lies at b = (theta - p) * kUnitsPerDeg. Right wing down turns the horizon counter-clockwise.
Transform attitude_frame(const PfdInputs& in) {
  return Transform::translation(kAdiCentre) * Transform::rotation(-in.roll_rad);
}

void draw_sky_and_ground(Canvas& c, const PfdInputs& in) {
  // Only what can fall in the window: the square about its circumscribed circle (rasterising
  // fragments the clip then drops is most of a software renderer's cost).
  constexpr double kReach = 330.0;
  const double horizon_b = in.pitch_rad * kRadToDeg * kUnitsPerDeg;
  const double h = std::clamp(horizon_b, -kReach, kReach);
  if (h > -kReach) c.fill_rect({-kReach, -kReach, kReach, h}, colour::kSky);
  if (h < kReach) c.fill_rect({-kReach, h, kReach, kReach}, colour::kGround);
  if (std::abs(horizon_b) < kReach) {
    c.line({-kReach, horizon_b}, {kReach, horizon_b}, kLine, colour::kWhite);
  }
}

void draw_pitch_rung(Canvas& c, double pitch_deg, double b) {
  const long quarter = std::lround(pitch_deg / 2.5);
  const bool ten = quarter % 4 == 0, five = quarter % 2 == 0;
  const double half = ten ? 70.0 : five ? 35.0 : 15.0;
  c.line({-half, b}, {half, b}, kLine, colour::kWhite);
  if (ten) {
    char label[24];
    std::snprintf(label, sizeof label, "%d", static_cast<int>(std::abs(std::lround(pitch_deg))));
    c.text(label, {-half - 8.0, b}, kSmallText, Align::kRight, Face::kMono, colour::kWhite);
    c.text(label, {half + 8.0, b}, kSmallText, Align::kLeft, Face::kMono, colour::kWhite);
  }
}

void draw_pitch_ladder(Canvas& c, const PfdInputs& in) {
  const double theta_deg = in.pitch_rad * kRadToDeg;
  const long lo = static_cast<long>(std::ceil((theta_deg - kLadderRangeDeg) / 2.5));
  const long hi = static_cast<long>(std::floor((theta_deg + kLadderRangeDeg) / 2.5));
  for (long q = std::max(lo, -36L); q <= std::min(hi, 36L); ++q) {
    if (q == 0) continue;  // the horizon line
    const double p = 2.5 * q;
    draw_pitch_rung(c, p, (theta_deg - p) * kUnitsPerDeg);
  }
}

void draw_attitude(Canvas& c, const PfdInputs& in) {
  c.push_clip(kAdi);
  c.push(attitude_frame(in));
  draw_sky_and_ground(c, in);
  c.pop();
  c.push_clip(kLadderWindow);
  c.push(attitude_frame(in));
  draw_pitch_ladder(c, in);
  c.pop();
  c.pop_clip();
  c.pop_clip();
}

// Fixed scale (ticks at 10, 20, 30, 45, 60 deg each side, a triangle at zero); the pointer and
// the slip/skid trapezoid below it turn with the sky.
void draw_bank_scale(Canvas& c, const PfdInputs& in) {
  for (double deg : {10.0, 20.0, 30.0, 45.0, 60.0}) {
    const double length = (deg == 30.0 || deg == 60.0) ? 22.0 : 12.0;
    for (double side : {-1.0, 1.0}) {
      const double a = side * deg * kDegToRad;
      c.line(polar(kAdiCentre, kBankRadius, a), polar(kAdiCentre, kBankRadius + length, a), kLine,
             colour::kWhite);
    }
  }
  const double top = kAdiCentre.y() - kBankRadius;
  c.fill_polygon({{500.0, top - 2.0}, {488.0, top - 20.0}, {512.0, top - 20.0}}, colour::kWhite);

  c.push(attitude_frame(in));
  const double r = kBankRadius - 2.0;
  c.fill_polygon({{0.0, -r}, {12.0, -r + 18.0}, {-12.0, -r + 18.0}}, colour::kWhite);
  // The ball is pushed opposite to the lateral specific force; full scale at 0.2 g.
  const double g = in.lateral_specific_force_mps2 / units::kStandardGravityMps2;
  const double slip = std::clamp(-g / 0.2 * 25.0, -30.0, 30.0);
  c.fill_polygon({{slip - 14.0, -r + 21.0},
                  {slip + 14.0, -r + 21.0},
                  {slip + 17.0, -r + 29.0},
                  {slip - 17.0, -r + 29.0}},
                 colour::kWhite);
  c.pop();
}

// Two L-shaped wings and a centre square, black outlined in white (the 737's aircraft symbol).
void draw_aircraft_symbol(Canvas& c) {
  const auto outlined = [&c](std::initializer_list<Vec2> shape, const Rect& box) {
    c.fill_rect({box.x0 - 2.0, box.y0 - 2.0, box.x1 + 2.0, box.y1 + 2.0}, colour::kWhite);
    c.fill_polygon(shape, colour::kBlack);
  };
  for (double side : {-1.0, 1.0}) {
    const double inner = 500.0 + side * 50.0, outer = 500.0 + side * 130.0;
    const Rect bar{std::min(inner, outer), 396.0, std::max(inner, outer), 406.0};
    outlined({{bar.x0, bar.y0}, {bar.x1, bar.y0}, {bar.x1, bar.y1}, {bar.x0, bar.y1}}, bar);
    const Rect drop{inner - (side > 0 ? 0.0 : 10.0), 396.0, inner + (side > 0 ? 10.0 : 0.0), 430.0};
    outlined({{drop.x0, drop.y0}, {drop.x1, drop.y0}, {drop.x1, drop.y1}, {drop.x0, drop.y1}},
             drop);
  }
  const Rect centre{494.0, 394.0, 506.0, 406.0};
  outlined({{centre.x0, centre.y0},
            {centre.x1, centre.y0},
            {centre.x1, centre.y1},
            {centre.x0, centre.y1}},
           centre);
}

void flag(Canvas& c, const char* text, const Vec2& at) {
  const double w = c.text_width(text, kText, Face::kSans) + 12.0;
  c.fill_rect({at.x() - 0.5 * w, at.y() - 18.0, at.x() + 0.5 * w, at.y() + 18.0}, colour::kBlack);
  c.rect_outline({at.x() - 0.5 * w, at.y() - 18.0, at.x() + 0.5 * w, at.y() + 18.0}, 2.0,
                 colour::kRed);
  c.text(text, at, kText, Align::kCentre, Face::kSans, colour::kRed);
}

// The bars show the command relative to the present attitude: fly the aircraft symbol onto
// their cross. Pitch 10 units/deg of error (the ladder's scale), bank 100 units per 30 deg.
void draw_flight_director(Canvas& c, const FlightDirector& fd, const PfdInputs& in) {
  if (!fd.on) return;
  // A bar whose command is not valid is removed and the flag shown (737 FCOM).
  if (!fd.pitch_valid || !fd.roll_valid) flag(c, "FD", kFdFlag.centre());
  if (fd.pitch_valid) {
    const double pitch_error_deg = (fd.pitch_command_rad - in.pitch_rad) * kRadToDeg;
    const double dy = std::clamp(-pitch_error_deg * kUnitsPerDeg, -110.0, 110.0);
    c.line({400.0, 400.0 + dy}, {600.0, 400.0 + dy}, 6.0, colour::kMagenta);
  }
  if (fd.roll_valid) {
    const double roll_error = std::remainder(fd.roll_command_rad - in.roll_rad, units::kTwoPi);
    const double dx = std::clamp(roll_error / (30.0 * kDegToRad) * 100.0, -110.0, 110.0);
    c.line({500.0 + dx, 300.0}, {500.0 + dx, 500.0}, 6.0, colour::kMagenta);
  }
}

// A deviation scale: dots at +-1 and +-2 along `axis`, a centre mark, and the pointer (a
// magenta diamond) or the flag.
void draw_deviation(Canvas& c, const Vec2& centre, const Vec2& axis, NavSignal signal, double dots,
                    const char* flag_text) {
  if (signal == NavSignal::kNotTuned) return;
  if (signal == NavSignal::kFailed) {
    flag(c, flag_text, centre);
    return;
  }
  for (int d : {-2, -1, 1, 2}) c.circle(centre + axis * (d * kDotUnits), 6.0, 2.5, colour::kWhite);
  const Vec2 across(-axis.y(), axis.x());
  c.line(centre - across * 12.0, centre + across * 12.0, kLine, colour::kWhite);
  const Vec2 p = centre + axis * (clamp_dots(dots) * kDotUnits);
  c.fill_polygon({p + axis * 15.0, p + across * 10.0, p - axis * 15.0, p - across * 10.0},
                 colour::kMagenta);
}

void draw_ils(Canvas& c, const PfdInputs& in) {
  draw_deviation(c, kLocCentre, {1.0, 0.0}, in.localizer, in.localizer_deviation_dots, "LOC");
  // Fly up (+) puts the beam, and the pointer, above the centre.
  draw_deviation(c, kGsCentre, {0.0, -1.0}, in.glideslope, in.glideslope_deviation_dots, "G/S");
}

void draw_marker(Canvas& c, MarkerBeacon marker) {
  if (marker == MarkerBeacon::kNone) return;
  const char* text = marker == MarkerBeacon::kOuter    ? "OM"
                     : marker == MarkerBeacon::kMiddle ? "MM"
                                                       : "IM";
  const Colour col = marker == MarkerBeacon::kOuter    ? colour::kCyan
                     : marker == MarkerBeacon::kMiddle ? colour::kAmber
                                                       : colour::kWhite;
  const Vec2 at{672.0, 200.0};
  c.fill_circle(at, 24.0, colour::kBlack);
  c.circle(at, 24.0, 3.0, col);
  c.text(text, at, kSmallText, Align::kCentre, Face::kSans, col);
}

void draw_radio_altitude(Canvas& c, const std::optional<double>& ra_m) {
  if (!ra_m) return;
  const double ft = *ra_m * units::kMToFt;
  if (ft > 2500.0) return;  // the 737 shows it at and below 2500 ft
  // 10-ft steps above 100 ft, 2-ft below (the 737 FCOM's radio altitude resolution).
  const double step = ft > 100.0 ? 10.0 : 2.0;
  char text[24];
  std::snprintf(text, sizeof text, "%d", static_cast<int>(std::lround(ft / step) * step));
  c.fill_rect({450.0, 545.0, 550.0, 579.0}, colour::kBlack);
  c.text(text, {500.0, 562.0}, kText, Align::kCentre, Face::kMono, colour::kWhite);
}

// --- Tapes ------------------------------------------------------------------------------

void trend_vector(Canvas& c, double x, double length_units) {
  if (std::abs(length_units) < 6.0) return;  // under about 1.5 kt / 15 ft: none, as a 737
  const double tip = 400.0 - std::clamp(length_units, -230.0, 230.0);
  const double dir = length_units > 0.0 ? -1.0 : 1.0;
  c.line({x, 400.0}, {x, tip}, kLine, colour::kGreen);
  c.polyline({{x - 8.0, tip - dir * 12.0}, {x, tip}, {x + 8.0, tip - dir * 12.0}}, kLine,
             colour::kGreen);
}

// A magenta bug on a tape's edge at `y`, pegged half-visible at the tape's ends.
void tape_bug(Canvas& c, double edge_x, double y, double inward) {
  y = std::clamp(y, 175.0, 625.0);
  c.polyline({{edge_x, y - 16.0},
              {edge_x + inward * 14.0, y - 16.0},
              {edge_x + inward * 14.0, y - 6.0},
              {edge_x + inward * 4.0, y},
              {edge_x + inward * 14.0, y + 6.0},
              {edge_x + inward * 14.0, y + 16.0},
              {edge_x, y + 16.0}},
             kLine, colour::kMagenta, true);
}

void draw_speed_tape(Canvas& c, const PfdInputs& in) {
  const double kt = in.ias_mps * units::kMpsToKt;
  c.fill_rect(kSpeedTape, colour::kTape);
  c.push_clip(kSpeedTape);
  const long first = std::max(30L, static_cast<long>(std::floor((kt - 60.0) / 10.0)) * 10);
  for (long v = first; v <= kt + 60.0; v += 10) {
    const double y = 400.0 - (v - kt) * kUnitsPerKt;
    c.line({210.0, y}, {230.0, y}, kLine, colour::kWhite);
    if (v % 20 == 0) {
      char label[24];
      std::snprintf(label, sizeof label, "%ld", v);
      c.text(label, {203.0, y}, kSmallText, Align::kRight, Face::kMono, colour::kWhite);
    }
  }
  if (in.selected_speed_mps) {
    tape_bug(c, 230.0, 400.0 - (*in.selected_speed_mps * units::kMpsToKt - kt) * kUnitsPerKt, -1.0);
  }
  c.pop_clip();
  trend_vector(c, 236.0, in.ias_trend_mps * units::kMpsToKt * kUnitsPerKt);
  const Rect& r = kSpeedReadout;
  c.fill_polygon({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}}, colour::kBlack);
  c.fill_polygon({{r.x1, 388.0}, {r.x1 + 14.0, 400.0}, {r.x1, 412.0}}, colour::kBlack);
  c.rect_outline(r, kLine, colour::kWhite);
  char text[24];
  std::snprintf(text, sizeof text, "%d", static_cast<int>(std::lround(kt)));
  c.text(text, {r.x1 - 10.0, 400.0}, kBigText, Align::kRight, Face::kMono, colour::kWhite);
  if (in.selected_speed_mps) {
    std::snprintf(text, sizeof text, "%d",
                  static_cast<int>(std::lround(*in.selected_speed_mps * units::kMpsToKt)));
    c.text(text, {175.0, 140.0}, kText, Align::kCentre, Face::kMono, colour::kMagenta);
  }
}

// Thousands large, hundreds-tens-units smaller, in 20-ft steps (the 737's drum readout).
void altitude_readout(Canvas& c, double ft) {
  const Rect& r = kAltitudeReadout;
  c.fill_polygon({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}}, colour::kBlack);
  c.fill_polygon({{r.x0, 388.0}, {r.x0 - 14.0, 400.0}, {r.x0, 412.0}}, colour::kBlack);
  c.rect_outline(r, kLine, colour::kWhite);
  const long shown = std::lround(ft / 20.0) * 20;
  const long magnitude = std::labs(shown);
  char hundreds[24], thousands[24];
  std::snprintf(hundreds, sizeof hundreds, "%03ld", magnitude % 1000);
  std::snprintf(thousands, sizeof thousands, "%s%ld", shown < 0 ? "-" : "", magnitude / 1000);
  const double x = r.x1 - 8.0;
  const double w = c.text(hundreds, {x, 403.0}, kText, Align::kRight, Face::kMono, colour::kWhite);
  if (magnitude >= 1000 || shown < 0) {
    c.text(thousands, {x - w - 2.0, 400.0}, kBigText, Align::kRight, Face::kMono, colour::kWhite);
  }
}

void draw_altitude_tape(Canvas& c, const PfdInputs& in) {
  const double ft = in.altitude_m * units::kMToFt;
  c.fill_rect(kAltitudeTape, colour::kTape);
  c.push_clip(kAltitudeTape);
  const long first = static_cast<long>(std::floor((ft - 600.0) / 100.0)) * 100;
  for (long v = first; v <= ft + 600.0; v += 100) {
    const double y = 400.0 - (v - ft) * kUnitsPerFt;
    c.line({770.0, y}, {790.0, y}, kLine, colour::kWhite);
    if (v % 200 == 0) {
      char label[24];
      std::snprintf(label, sizeof label, "%ld", v);
      c.text(label, {796.0, y}, kSmallText, Align::kLeft, Face::kMono, colour::kWhite);
    }
  }
  if (in.selected_altitude_m) {
    tape_bug(c, 770.0, 400.0 - (*in.selected_altitude_m * units::kMToFt - ft) * kUnitsPerFt, 1.0);
  }
  c.pop_clip();
  trend_vector(c, 764.0, in.altitude_trend_m * units::kMToFt * kUnitsPerFt);
  altitude_readout(c, ft);
  char text[24];
  if (in.selected_altitude_m) {
    std::snprintf(text, sizeof text, "%ld",
                  std::lround(*in.selected_altitude_m * units::kMToFt / 100.0) * 100);
    c.text(text, {825.0, 140.0}, kText, Align::kCentre, Face::kMono, colour::kMagenta);
  }
  if (in.baro_setting_pa) {
    std::snprintf(text, sizeof text, "%.2f IN", *in.baro_setting_pa / units::kInHgToPa);
  } else {
    std::snprintf(text, sizeof text, "STD");
  }
  c.text(text, {825.0, 665.0}, kText, Align::kCentre, Face::kMono, colour::kGreen);
}

// Units from the VSI's centre for a vertical speed, the 737's non-linear scale.
double vsi_units(double fpm) {
  const double v = std::min(std::abs(fpm), 6000.0);
  const double u = v <= 1000.0   ? v * 0.1
                   : v <= 2000.0 ? 100.0 + (v - 1000.0) * 0.05
                                 : 150.0 + (v - 2000.0) * 0.01;
  return fpm < 0.0 ? -u : u;
}

void draw_vsi(Canvas& c, const PfdInputs& in) {
  const Rect& r = kVsi;
  c.fill_polygon({{r.x0, r.y0}, {r.x1, r.y0 + 60.0}, {r.x1, r.y1 - 60.0}, {r.x0, r.y1}},
                 colour::kTape);
  for (double fpm : {-6000.0, -2000.0, -1000.0, -500.0, 0.0, 500.0, 1000.0, 2000.0, 6000.0}) {
    const double y = 400.0 - vsi_units(fpm);
    const bool major = std::abs(fpm) != 500.0;
    c.line({r.x0, y}, {r.x0 + (major ? 16.0 : 9.0), y}, kLine, colour::kWhite);
    if (major && fpm != 0.0) {
      char label[24];
      std::snprintf(label, sizeof label, "%d", static_cast<int>(std::abs(fpm) / 1000.0));
      c.text(label, {r.x0 + 28.0, y}, kSmallText, Align::kCentre, Face::kMono, colour::kWhite);
    }
  }
  // The needle points from a pivot right of the display at the scale.
  const double fpm = in.vertical_speed_mps * units::kMpsToFpm;
  const Vec2 tip{r.x0 + 2.0, 400.0 - vsi_units(fpm)};
  const Vec2 pivot{1060.0, 400.0};
  const Vec2 end = tip + (pivot - tip) * ((r.x1 - 5.0 - tip.x()) / (pivot.x() - tip.x()));
  c.line(tip, end, 4.0, colour::kWhite);
  if (std::abs(fpm) >= 400.0) {  // the 737 readout: above 400 ft/min, in 50 ft/min steps
    char text[24];
    std::snprintf(text, sizeof text, "%ld", std::labs(std::lround(fpm / 50.0) * 50));
    c.text(text, {952.0, fpm > 0.0 ? 180.0 : 620.0}, kSmallText, Align::kCentre, Face::kMono,
           colour::kWhite);
  }
}

// --- Heading arc and FMA -----------------------------------------------------------------

void draw_heading(Canvas& c, const PfdInputs& in) {
  const double heading = in.heading_true_reference ? in.heading_true_rad : in.heading_magnetic_rad;
  c.push_clip(kHeadingWindow);
  c.fill_circle(kHeadingCentre, kHeadingRadius, colour::kTape);
  c.push(Transform::translation(kHeadingCentre) * Transform::rotation(-heading));
  for (int deg = 0; deg < 360; deg += 5) {
    const double a = deg * kDegToRad;
    const bool ten = deg % 10 == 0;
    c.line(polar({0.0, 0.0}, kHeadingRadius, a),
           polar({0.0, 0.0}, kHeadingRadius - (ten ? 20.0 : 11.0), a), kLine, colour::kWhite);
    if (ten) {
      char label[24];
      std::snprintf(label, sizeof label, "%d", deg / 10);
      c.push(Transform::rotation(a));
      c.text(label, {0.0, -kHeadingRadius + 40.0}, deg % 30 == 0 ? kText : kSmallText,
             Align::kCentre, Face::kMono, colour::kWhite);
      c.pop();
    }
  }
  if (in.selected_heading_rad) {
    c.push(Transform::rotation(*in.selected_heading_rad));
    const double r = kHeadingRadius;
    c.polyline({{-14.0, -r},
                {-14.0, -r + 12.0},
                {14.0, -r + 12.0},
                {14.0, -r},
                {6.0, -r},
                {0.0, -r + 8.0},
                {-6.0, -r}},
               kLine, colour::kMagenta, true);
    c.pop();
  }
  c.pop();
  c.pop_clip();
  // The heading pointer and readout above the arc.
  const double top = kHeadingCentre.y() - kHeadingRadius;
  c.fill_polygon({{500.0, top + 2.0}, {490.0, top - 14.0}, {510.0, top - 14.0}}, colour::kWhite);
  char text[24];
  double deg = std::fmod(heading * kRadToDeg, 360.0);
  if (deg < 0.0) deg += 360.0;
  int shown = static_cast<int>(std::lround(deg)) % 360;
  if (shown == 0) shown = 360;
  std::snprintf(text, sizeof text, "%03d", shown);
  c.fill_rect({465.0, top - 52.0, 535.0, top - 16.0}, colour::kBlack);
  c.rect_outline({465.0, top - 52.0, 535.0, top - 16.0}, 2.0, colour::kWhite);
  c.text(text, {500.0, top - 34.0}, kText, Align::kCentre, Face::kMono, colour::kWhite);
  c.text(in.heading_true_reference ? "TRU" : "MAG", {545.0, top - 34.0}, kSmallText, Align::kLeft,
         Face::kSans, colour::kGreen);
  if (in.selected_heading_rad) {
    double sel = std::fmod(*in.selected_heading_rad * kRadToDeg, 360.0);
    if (sel < 0.0) sel += 360.0;
    int s = static_cast<int>(std::lround(sel)) % 360;
    std::snprintf(text, sizeof text, "%03d H", s == 0 ? 360 : s);
    c.text(text, {330.0, top - 34.0}, kSmallText, Align::kCentre, Face::kMono, colour::kMagenta);
  }
}

void draw_fma(Canvas& c, const FlightModes& m) {
  const double columns[] = {330.0, 500.0, 670.0};
  const std::string* active[] = {&m.autothrottle_active, &m.roll_active, &m.pitch_active};
  const std::string* armed[] = {&m.autothrottle_armed, &m.roll_armed, &m.pitch_armed};
  c.fill_rect({245.0, 20.0, 755.0, 112.0}, colour::kBlack);
  for (int i = 0; i < 3; ++i) {
    c.text(*active[i], {columns[i], 48.0}, kText, Align::kCentre, Face::kSans, colour::kGreen);
    c.text(*armed[i], {columns[i], 88.0}, kSmallText, Align::kCentre, Face::kSans, colour::kWhite);
  }
  for (double x : {415.0, 585.0}) c.line({x, 25.0}, {x, 105.0}, 2.0, colour::kWhite);
  c.text(m.afds_status, {500.0, 140.0}, kText, Align::kCentre, Face::kSans, colour::kGreen);
}

Rect design_rect_to_px(const PfdLayout& l, const Rect& r) {
  const Vec2 a = l.to_px(Vec2(r.x0, r.y0)), b = l.to_px(Vec2(r.x1, r.y1));
  return {a.x(), a.y(), b.x(), b.y()};
}

}  // namespace

Rect PfdLayout::to_px(const Rect& design) const { return design_rect_to_px(*this, design); }

PfdLayout pfd_layout(int width_px, int height_px) {
  PfdLayout l;
  const double side = std::min(width_px, height_px);
  l.px_per_unit = side / kDesign;
  l.origin_px = {0.5 * (width_px - side), 0.5 * (height_px - side)};
  l.adi_centre_px = l.to_px(kAdiCentre);
  l.pixels_per_degree = kUnitsPerDeg * l.px_per_unit;
  l.adi_px = l.to_px(kAdi);
  l.localizer_centre_px = l.to_px(kLocCentre);
  l.localizer_dot_px = kDotUnits * l.px_per_unit;
  l.localizer_scale_px = l.to_px(Rect{380.0, 585.0, 620.0, 625.0});
  l.glideslope_centre_px = l.to_px(kGsCentre);
  l.glideslope_dot_px = kDotUnits * l.px_per_unit;
  l.glideslope_scale_px = l.to_px(Rect{665.0, 280.0, 710.0, 520.0});
  l.speed_readout_px = l.to_px(kSpeedReadout);
  l.altitude_readout_px = l.to_px(kAltitudeReadout);
  l.flight_director_flag_px = l.to_px(kFdFlag);
  return l;
}

void draw_pfd(Canvas& c, const PfdInputs& in) {
  validate(in, "PFD inputs");
  const PfdLayout l = pfd_layout(c.width_px(), c.height_px());
  c.push(Transform::translation(l.origin_px) * Transform::scaling(l.px_per_unit));
  draw_attitude(c, in);
  draw_bank_scale(c, in);
  draw_ils(c, in);
  draw_marker(c, in.marker);
  draw_radio_altitude(c, in.radio_altitude_m);
  draw_flight_director(c, in.flight_director, in);
  draw_aircraft_symbol(c);
  draw_speed_tape(c, in);
  draw_altitude_tape(c, in);
  draw_vsi(c, in);
  draw_heading(c, in);
  draw_fma(c, in.modes);
  c.pop();
}

}  // namespace fedsim::displays
