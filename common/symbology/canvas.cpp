#include "common/symbology/canvas.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::symbology {

double Transform::scale() const {
  return std::sqrt(std::abs(linear(0, 0) * linear(1, 1) - linear(0, 1) * linear(1, 0)));
}

Transform Transform::operator*(const Transform& inner) const {
  Transform t;
  t.linear = linear * inner.linear;
  t.offset = linear * inner.offset + offset;
  return t;
}

Transform Transform::translation(const Vec2& by) {
  Transform t;
  t.offset = by;
  return t;
}

Transform Transform::rotation(double angle_rad) {
  // With y down, the matrix of a counter-clockwise turn in y-up axes turns clockwise on screen.
  Transform t;
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  t.linear << c, -s, s, c;
  return t;
}

Transform Transform::scaling(double factor) {
  Transform t;
  t.linear *= factor;
  return t;
}

Vec2 polar(const Vec2& centre, double r, double angle_rad) {
  return centre + r * Vec2(std::sin(angle_rad), -std::cos(angle_rad));
}

Canvas::Canvas(const FontAtlas& atlas) : atlas_(&atlas) { reset(1, 1); }

void Canvas::reset(int width_px, int height_px) {
  width_ = width_px;
  height_ = height_px;
  transforms_.assign(1, Transform{});
  clips_.assign(1, Rect{0.0, 0.0, static_cast<double>(width_px), static_cast<double>(height_px)});
  vertices_.clear();
}

void Canvas::push(const Transform& t) { transforms_.push_back(transforms_.back() * t); }

void Canvas::pop() {
  if (transforms_.size() <= 1) throw std::logic_error("Canvas::pop without push");
  transforms_.pop_back();
}

void Canvas::push_clip(const Rect& r) {
  const Transform& t = transforms_.back();
  const Vec2 corners[] = {t.apply({r.x0, r.y0}), t.apply({r.x1, r.y0}), t.apply({r.x0, r.y1}),
                          t.apply({r.x1, r.y1})};
  Rect box{corners[0].x(), corners[0].y(), corners[0].x(), corners[0].y()};
  for (const Vec2& c : corners) {
    box.x0 = std::min(box.x0, c.x());
    box.y0 = std::min(box.y0, c.y());
    box.x1 = std::max(box.x1, c.x());
    box.y1 = std::max(box.y1, c.y());
  }
  const Rect& outer = clips_.back();
  clips_.push_back({std::max(box.x0, outer.x0), std::max(box.y0, outer.y0),
                    std::min(box.x1, outer.x1), std::min(box.y1, outer.y1)});
}

void Canvas::pop_clip() {
  if (clips_.size() <= 1) throw std::logic_error("Canvas::pop_clip without push_clip");
  clips_.pop_back();
}

void Canvas::vertex(const Vec2& screen, double u, double v, Colour colour) {
  const Rect& clip = clips_.back();
  vertices_.insert(
      vertices_.end(),
      {static_cast<float>(screen.x()), static_cast<float>(screen.y()), static_cast<float>(u),
       static_cast<float>(v), colour.r, colour.g, colour.b, colour.a, static_cast<float>(clip.x0),
       static_cast<float>(clip.y0), static_cast<float>(clip.x1), static_cast<float>(clip.y1)});
}

void Canvas::triangle(const Vec2& a, const Vec2& b, const Vec2& c, Colour colour) {
  const Transform& t = transforms_.back();
  vertex(t.apply(a), -1.0, -1.0, colour);
  vertex(t.apply(b), -1.0, -1.0, colour);
  vertex(t.apply(c), -1.0, -1.0, colour);
}

void Canvas::fill_rect(const Rect& r, Colour colour) {
  fill_polygon({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}}, colour);
}

void Canvas::fill_polygon(std::initializer_list<Vec2> convex, Colour colour) {
  const Vec2* p = convex.begin();
  for (std::size_t i = 1; i + 1 < convex.size(); ++i) triangle(p[0], p[i], p[i + 1], colour);
}

void Canvas::fill_polygon(const std::vector<Vec2>& convex, Colour colour) {
  for (std::size_t i = 1; i + 1 < convex.size(); ++i) {
    triangle(convex[0], convex[i], convex[i + 1], colour);
  }
}

void Canvas::line(const Vec2& a, const Vec2& b, double width, Colour colour) {
  const Vec2 d = b - a;
  const double length = d.norm();
  if (length <= 0.0) return;
  const Vec2 n = Vec2(-d.y(), d.x()) * (0.5 * width / length);
  fill_polygon({a + n, b + n, b - n, a - n}, colour);
}

void Canvas::polyline(const std::vector<Vec2>& points, double width, Colour colour, bool closed) {
  const std::size_t n = points.size();
  const std::size_t segments = closed ? n : (n == 0 ? 0 : n - 1);
  for (std::size_t i = 0; i < segments; ++i) {
    const Vec2& a = points[i];
    const Vec2& b = points[(i + 1) % n];
    const Vec2 d = b - a;
    const double length = d.norm();
    if (length <= 0.0) continue;
    const Vec2 cap = d * (0.5 * width / length);
    line(a - cap, b + cap, width, colour);
  }
}

void Canvas::rect_outline(const Rect& r, double width, Colour colour) {
  polyline({{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}}, width, colour, true);
}

int Canvas::segments_for(double radius, double sweep_rad) const {
  // About 3 screen pixels per segment: round at any size, few triangles when small.
  const double screen_radius = radius * transforms_.back().scale();
  return std::clamp(static_cast<int>(std::ceil(screen_radius * sweep_rad / 3.0)), 8, 256);
}

void Canvas::circle(const Vec2& centre, double radius, double width, Colour colour) {
  const int n = segments_for(radius, units::kTwoPi);
  std::vector<Vec2> points;
  points.reserve(n);
  for (int i = 0; i < n; ++i) points.push_back(polar(centre, radius, units::kTwoPi * i / n));
  polyline(points, width, colour, true);
}

void Canvas::fill_circle(const Vec2& centre, double radius, Colour colour) {
  const int n = segments_for(radius, units::kTwoPi);
  for (int i = 0; i < n; ++i) {
    triangle(centre, polar(centre, radius, units::kTwoPi * i / n),
             polar(centre, radius, units::kTwoPi * (i + 1) / n), colour);
  }
}

void Canvas::arc(const Vec2& centre, double radius, double from_rad, double to_rad, double width,
                 Colour colour) {
  const int n = segments_for(radius, to_rad - from_rad);
  for (int i = 0; i < n; ++i) {
    const double a0 = from_rad + (to_rad - from_rad) * i / n;
    const double a1 = from_rad + (to_rad - from_rad) * (i + 1) / n;
    // Butt ends along the arc, so that the strokes meet without overlapping.
    line(polar(centre, radius, a0), polar(centre, radius, a1), width, colour);
  }
}

double Canvas::text_width(std::string_view text, double cap_height, Face face) const {
  return atlas_->advance(face, text) * cap_height / atlas_->cap_height(face);
}

double Canvas::text(std::string_view text, const Vec2& anchor, double cap_height, Align align,
                    Face face, Colour colour) {
  const double k = cap_height / atlas_->cap_height(face);
  const double width = text_width(text, cap_height, face);
  double pen = anchor.x() - (align == Align::kLeft     ? 0.0
                             : align == Align::kCentre ? 0.5
                                                       : 1.0) *
                                width;
  const double baseline = anchor.y() + 0.5 * cap_height;
  const Transform& t = transforms_.back();
  const double aw = atlas_->width(), ah = atlas_->height();
  for (char c : text) {
    const Glyph& g = atlas_->glyph(face, c);
    if (g.width > 0 && g.height > 0) {
      const double x0 = pen + g.bearing_x * k, x1 = x0 + g.width * k;
      const double y0 = baseline - g.bearing_y * k, y1 = y0 + g.height * k;
      const double u0 = g.atlas_x / aw, u1 = (g.atlas_x + g.width) / aw;
      const double v0 = g.atlas_y / ah, v1 = (g.atlas_y + g.height) / ah;
      const Vec2 p00 = t.apply({x0, y0}), p10 = t.apply({x1, y0});
      const Vec2 p01 = t.apply({x0, y1}), p11 = t.apply({x1, y1});
      vertex(p00, u0, v0, colour);
      vertex(p10, u1, v0, colour);
      vertex(p11, u1, v1, colour);
      vertex(p00, u0, v0, colour);
      vertex(p11, u1, v1, colour);
      vertex(p01, u0, v1, colour);
    }
    pen += g.advance * k;
  }
  return width;
}

}  // namespace fedsim::symbology
