#include "common/hud/hud.hpp"

#include "common/math/rotation.hpp"
#include "common/symbology/palette.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fedsim::hud {

using namespace symbology;  // the drawing (canvas, glyphs, colours) the displays share

namespace {

using units::kDegToRad;
using units::kRadToDeg;
constexpr Colour kGreen = palette::kHudGreen;
constexpr double kMinFpvSpeedMps = 2.0;

// What every drawing function needs: the projection, the picture and its size unit (1 px in a
// 600-px-high picture), the screen direction of the horizon and the "up" across it.
struct HudFrame {
  const HudProjection& projection;
  double width;
  double height;
  double unit;
  Vec2 along;  // unit vector along the horizon, to the right
  Vec2 up;     // unit vector across it, towards the sky
};

Vec2 horizon_direction(const HudProjection& p, double heading_true_rad) {
  const auto a = p.project(HudProjection::direction(heading_true_rad - 0.01, 0.0));
  const auto b = p.project(HudProjection::direction(heading_true_rad + 0.01, 0.0));
  if (!a || !b || (*b - *a).norm() < 1e-9) return {1.0, 0.0};
  return (*b - *a).normalized();
}

// The zero-pitch line: a great circle, so a straight line in the pinhole picture; through two
// horizontal directions either side of the boresight's azimuth.
void draw_horizon(Canvas& c, const HudFrame& f) {
  const Eigen::Vector3d b = f.projection.channel_from_ned().transpose() * Eigen::Vector3d::UnitX();
  if (std::hypot(b.x(), b.y()) < 0.3) return;  // looking steeply up or down: not in the picture
  const double azimuth = std::atan2(b.y(), b.x());
  const auto p0 = f.projection.project(HudProjection::direction(azimuth - 0.3, 0.0));
  const auto p1 = f.projection.project(HudProjection::direction(azimuth + 0.3, 0.0));
  if (!p0 || !p1) return;
  const Vec2 d = (*p1 - *p0).normalized() * (2.0 * (f.width + f.height));
  c.line(*p0 - d, *p1 + d, 2.0 * f.unit, kGreen);
}

void draw_rung(Canvas& c, const HudFrame& f, double pitch_deg, const Vec2& centre,
               const Vec2& along) {
  const Vec2 across(along.y(), -along.x());  // towards the sky when along points right
  const double gap = 22.0 * f.unit, half = 70.0 * f.unit, tick = 8.0 * f.unit;
  const double w = 2.0 * f.unit;
  const bool above = pitch_deg > 0.0;
  for (double side : {-1.0, 1.0}) {
    const Vec2 inner = centre + side * gap * along, outer = centre + side * half * along;
    if (above) {
      c.line(inner, outer, w, kGreen);
    } else {  // below the horizon: dashed, as HUDs draw the negative rungs
      for (int k = 0; k < 3; ++k) {
        const double t0 = k / 3.0, t1 = t0 + 0.2;
        c.line(inner + t0 * (outer - inner), inner + t1 * (outer - inner), w, kGreen);
      }
    }
    // End ticks point at the horizon.
    c.line(outer, outer + (above ? -tick : tick) * across, w, kGreen);
    char label[24];
    std::snprintf(label, sizeof label, "%d", static_cast<int>(std::lround(std::abs(pitch_deg))));
    c.text(label, outer + side * 16.0 * f.unit * along, 12.0 * f.unit, Align::kCentre, Face::kMono,
           kGreen);
  }
}

// Rungs every 5 deg, centred on the aircraft's heading, each along the local direction of
// constant elevation.
void draw_ladder(Canvas& c, const HudFrame& f, double heading_true_rad) {
  for (int p = -85; p <= 85; p += 5) {
    if (p == 0) continue;
    const auto centre =
        f.projection.project(HudProjection::direction(heading_true_rad, p * kDegToRad));
    const auto side =
        f.projection.project(HudProjection::direction(heading_true_rad + 0.01, p * kDegToRad));
    if (!centre || !side) continue;
    if (centre->x() < -0.2 * f.width || centre->x() > 1.2 * f.width ||
        centre->y() < -0.2 * f.height || centre->y() > 1.2 * f.height) {
      continue;
    }
    draw_rung(c, f, p, *centre, (*side - *centre).normalized());
  }
}

void draw_boresight(Canvas& c, const HudFrame& f, const Eigen::Vector3d& nose_ned) {
  const auto at = f.projection.project(nose_ned);
  if (!at) return;
  const double u = f.unit;
  std::vector<Vec2> w;
  for (const Vec2& p : {Vec2(-24, 0), Vec2(-12, 0), Vec2(-6, 8), Vec2(0, 0), Vec2(6, 8),
                        Vec2(12, 0), Vec2(24, 0)}) {
    w.push_back(*at + u * p);
  }
  c.polyline(w, 2.0 * u, kGreen);
}

// A circle with wings along the horizon and a fin towards the sky; returns where it is.
std::optional<Vec2> draw_fpv(Canvas& c, const HudFrame& f, const Eigen::Vector3d& v_ned) {
  if (v_ned.norm() < kMinFpvSpeedMps) return std::nullopt;
  const auto at = f.projection.project(v_ned.normalized());
  if (!at) return std::nullopt;
  const double r = 9.0 * f.unit, w = 2.0 * f.unit;
  c.circle(*at, r, w, kGreen);
  for (double side : {-1.0, 1.0})
    c.line(*at + side * r * f.along, *at + side * 3.0 * r * f.along, w, kGreen);
  c.line(*at + r * f.up, *at + 2.0 * r * f.up, w, kGreen);
  return at;
}

// The guidance cue: the FPV's place if the aircraft flew the commands (pitch error at the
// conformal scale, bank error 0.1 picture heights per 30 deg, as the PFD's roll bar).
void draw_guidance_cue(Canvas& c, const HudFrame& f, const HudInputs& in, const Vec2& fpv) {
  const FlightDirector& fd = in.flight_director;
  if (!fd.on || !fd.pitch_valid || !fd.roll_valid) return;
  const double pitch_error = fd.pitch_command_rad - in.pitch_rad;
  const double roll_error = std::remainder(fd.roll_command_rad - in.roll_rad, units::kTwoPi);
  const Vec2 at = fpv + pitch_error * f.projection.pixels_per_rad() * f.up +
                  std::clamp(roll_error / (30.0 * kDegToRad), -1.5, 1.5) * 0.1 * f.height * f.along;
  c.circle(at, 6.0 * f.unit, 2.0 * f.unit, kGreen);
}

void readout_box(Canvas& c, const Vec2& centre, double width, const char* text, double unit) {
  const Rect box{centre.x() - 0.5 * width, centre.y() - 15.0 * unit, centre.x() + 0.5 * width,
                 centre.y() + 15.0 * unit};
  c.rect_outline(box, 2.0 * unit, kGreen);
  c.text(text, centre, 15.0 * unit, Align::kCentre, Face::kMono, kGreen);
}

void draw_air_data(Canvas& c, const HudFrame& f, const HudInputs& in) {
  char text[24];
  std::snprintf(text, sizeof text, "%d",
                static_cast<int>(std::lround(in.ias_mps * units::kMpsToKt)));
  readout_box(c, {0.18 * f.width, 0.5 * f.height}, 70.0 * f.unit, text, f.unit);
  std::snprintf(text, sizeof text, "%ld", std::lround(in.altitude_m * units::kMToFt / 10.0) * 10);
  readout_box(c, {0.82 * f.width, 0.5 * f.height}, 84.0 * f.unit, text, f.unit);
  std::snprintf(text, sizeof text, "VS %ld",
                std::lround(in.vertical_speed_mps * units::kMpsToFpm / 10.0) * 10);
  c.text(text, {0.82 * f.width, 0.5 * f.height + 32.0 * f.unit}, 12.0 * f.unit, Align::kCentre,
         Face::kMono, kGreen);
}

// A magnetic heading tape along the top, 8 units per degree, +-20 deg shown.
void draw_heading_scale(Canvas& c, const HudFrame& f, double heading_magnetic_rad) {
  const double u = f.unit, ppd = 8.0 * u, y = 40.0 * u, cx = 0.5 * f.width;
  double hdg = std::fmod(heading_magnetic_rad * kRadToDeg, 360.0);
  if (hdg < 0.0) hdg += 360.0;
  c.push_clip({cx - 20.0 * ppd, 0.0, cx + 20.0 * ppd, y + 30.0 * u});
  for (int d = static_cast<int>(std::floor(hdg / 5.0)) * 5 - 25; d <= hdg + 25.0; d += 5) {
    const double x = cx + (d - hdg) * ppd;
    const bool ten = d % 10 == 0;
    c.line({x, y}, {x, y - (ten ? 10.0 : 5.0) * u}, 2.0 * u, kGreen);
    if (ten) {
      char label[24];
      std::snprintf(label, sizeof label, "%02d", ((d % 360 + 360) % 360) / 10);
      c.text(label, {x, y - 20.0 * u}, 11.0 * u, Align::kCentre, Face::kMono, kGreen);
    }
  }
  c.pop_clip();
  c.fill_polygon({{cx, y + 2.0 * u}, {cx - 6.0 * u, y + 12.0 * u}, {cx + 6.0 * u, y + 12.0 * u}},
                 kGreen);
}

}  // namespace

HudProjection::HudProjection(const view::ChannelConfig& channel, double roll_rad,
                             double pitch_rad, double heading_true_rad) {
  const Eigen::Matrix3d ned_from_body = dcm_from_euler({roll_rad, pitch_rad, heading_true_rad});
  const Eigen::Matrix3d body_from_channel = dcm_from_euler(
      {channel.roll_offset_rad, channel.pitch_offset_rad, channel.heading_offset_rad});
  channel_from_ned_ = (ned_from_body * body_from_channel).transpose();
  half_width_px_ = 0.5 * channel.width_px;
  half_height_px_ = 0.5 * channel.height_px;
  tan_half_h_ = std::tan(0.5 * channel.horizontal_fov_rad);
  tan_half_v_ = std::tan(0.5 * channel.vertical_fov_rad);
}

std::optional<Vec2> HudProjection::project(const Eigen::Vector3d& direction_ned) const {
  const Eigen::Vector3d c = channel_from_ned_ * direction_ned;
  if (c.x() < 1e-3 * direction_ned.norm()) return std::nullopt;
  return Vec2(half_width_px_ * (1.0 + c.y() / c.x() / tan_half_h_),
              half_height_px_ * (1.0 + c.z() / c.x() / tan_half_v_));
}

Eigen::Vector3d HudProjection::direction(double azimuth_rad, double elevation_rad) {
  const double ce = std::cos(elevation_rad);
  return {ce * std::cos(azimuth_rad), ce * std::sin(azimuth_rad), -std::sin(elevation_rad)};
}

double HudProjection::pixels_per_rad() const { return half_height_px_ / tan_half_v_; }

void draw_hud(Canvas& c, const HudInputs& in, const view::ChannelConfig& channel) {
  validate(in, "HUD inputs");
  const HudProjection projection(channel, in.roll_rad, in.pitch_rad, in.heading_true_rad);
  const Vec2 along = horizon_direction(projection, in.heading_true_rad);
  const HudFrame f{projection,
                   static_cast<double>(channel.width_px),
                   static_cast<double>(channel.height_px),
                   channel.height_px / 600.0,
                   along,
                   Vec2(along.y(), -along.x())};
  // The conformal symbols stay out of the heading scale's band along the top.
  c.push_clip({0.0, 62.0 * f.unit, f.width, f.height});
  draw_horizon(c, f);
  draw_ladder(c, f, in.heading_true_rad);
  c.pop_clip();
  const Eigen::Matrix3d ned_from_body =
      dcm_from_euler({in.roll_rad, in.pitch_rad, in.heading_true_rad});
  draw_boresight(c, f, ned_from_body.col(0));
  if (const auto fpv = draw_fpv(c, f, in.velocity_ned_mps)) draw_guidance_cue(c, f, in, *fpv);
  draw_air_data(c, f, in);
  draw_heading_scale(c, f, in.heading_true_rad - in.magnetic_variation_rad);
}

}  // namespace fedsim::hud
