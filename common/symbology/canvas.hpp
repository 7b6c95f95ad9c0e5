// A 2-D drawing list: the displays and the HUD are drawn into it as coloured and textured
// triangles (lines become quads, circles polygons, text the atlas' glyph quads), which the
// renderer (canvas_renderer.hpp) then draws in one call, in order (painter's algorithm: later on
// top). Pure C++: it knows no OpenGL, so what is drawn where can be tested without a context.
//
// Coordinates: pixels of the picture, x from the left edge, y from the top edge (as Image and
// the image generator's channel camera). Drawing goes through the current transform (a
// similarity: offset, rotation, uniform scale; push()/pop() compose), so a display is written in
// its own design units and an attitude sphere in its rotated frame; widths and text heights
// scale with it.
// Compass angles (arc(), polar()) are clockwise from up, as a heading on a heading-up display.
// Clipping: every vertex carries the screen rectangle it may colour (push_clip(); the fragment
// shader discards outside it), so a tape's labels stop at the tape's edge.
#pragma once

#include "common/symbology/font_atlas.hpp"

#include <Eigen/Core>

#include <initializer_list>
#include <string_view>
#include <vector>

namespace fedsim::symbology {

using Vec2 = Eigen::Vector2d;

struct Colour {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;
};

struct Rect {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  // left, top, right, bottom
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  Vec2 centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
  bool contains(const Vec2& p) const {
    return p.x() >= x0 && p.x() < x1 && p.y() >= y0 && p.y() < y1;
  }
};

/// p' = offset + linear p, linear a rotation times a uniform scale.
struct Transform {
  Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();
  Vec2 offset = Vec2::Zero();

  Vec2 apply(const Vec2& p) const { return linear * p + offset; }
  double scale() const;
  Transform operator*(const Transform& inner) const;  // this after inner
  static Transform translation(const Vec2& by);
  /// Turns clockwise on the screen (y down) by `angle_rad`.
  static Transform rotation(double angle_rad);
  static Transform scaling(double factor);
};

enum class Align { kLeft, kCentre, kRight };

/// The point at compass angle `angle_rad` (clockwise from up) and distance `r` from `centre`.
Vec2 polar(const Vec2& centre, double r, double angle_rad);

class Canvas {
 public:
  /// Floats per vertex: x, y [px], u, v (atlas; u < 0: solid colour), r, g, b, a, clip x0, y0,
  /// x1, y1 [px].
  static constexpr int kFloatsPerVertex = 12;

  explicit Canvas(const FontAtlas& atlas);

  /// Empties the list for a picture of this size: identity transform, clip to the picture.
  void reset(int width_px, int height_px);
  int width_px() const { return width_; }
  int height_px() const { return height_; }

  void push(const Transform& t);  // the current transform becomes current * t
  void pop();
  const Transform& transform() const { return transforms_.back(); }
  /// Clips to `r` (current coordinates; its bounding box on the screen) within the current clip.
  void push_clip(const Rect& r);
  void pop_clip();

  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, Colour colour);
  void fill_rect(const Rect& r, Colour colour);
  void fill_polygon(std::initializer_list<Vec2> convex, Colour colour);
  void fill_polygon(const std::vector<Vec2>& convex, Colour colour);
  /// A straight stroke `width` wide, ends cut square at a and b.
  void line(const Vec2& a, const Vec2& b, double width, Colour colour);
  /// Strokes with square caps (segments overlap at the joints, no notches at corners).
  void polyline(const std::vector<Vec2>& points, double width, Colour colour, bool closed = false);
  void rect_outline(const Rect& r, double width, Colour colour);
  void circle(const Vec2& centre, double radius, double width, Colour colour);
  void fill_circle(const Vec2& centre, double radius, Colour colour);
  /// Arc between compass angles from_rad < to_rad.
  void arc(const Vec2& centre, double radius, double from_rad, double to_rad, double width,
           Colour colour);
  /// Draws `text` with capitals `cap_height` high, `anchor` at the vertical middle of the
  /// capitals and at the left / centre / right of the text; returns its width.
  double text(std::string_view text, const Vec2& anchor, double cap_height, Align align, Face face,
              Colour colour);
  double text_width(std::string_view text, double cap_height, Face face) const;

  const std::vector<float>& vertices() const { return vertices_; }
  std::size_t vertex_count() const { return vertices_.size() / kFloatsPerVertex; }

 private:
  void vertex(const Vec2& screen, double u, double v, Colour colour);
  int segments_for(double radius, double sweep_rad) const;

  const FontAtlas* atlas_;
  int width_ = 0;
  int height_ = 0;
  std::vector<Transform> transforms_;
  std::vector<Rect> clips_;
  std::vector<float> vertices_;
};

}  // namespace fedsim::symbology
