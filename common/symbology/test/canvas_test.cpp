// The drawing list without OpenGL: screen conventions (y down, clockwise compass angles),
// transforms composing, clip rectangles carried by every vertex, text laid out from the atlas.
#include "common/symbology/canvas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fedsim::symbology {
namespace {

constexpr double kQuarter = 0.5 * std::numbers::pi;

const FontAtlas& atlas() {
  static const FontAtlas a;
  return a;
}

TEST(Canvas, CompassAnglesAndRotationsTurnClockwiseOnTheScreen) {
  const Vec2 right = Transform::rotation(kQuarter).apply({1.0, 0.0});
  EXPECT_NEAR(right.x(), 0.0, 1e-12);
  EXPECT_NEAR(right.y(), 1.0, 1e-12);  // x turned a quarter clockwise points down
  const Vec2 east = polar({10.0, 10.0}, 5.0, kQuarter);
  EXPECT_NEAR(east.x(), 15.0, 1e-12);
  EXPECT_NEAR(east.y(), 10.0, 1e-12);
  const Vec2 north = polar({10.0, 10.0}, 5.0, 0.0);
  EXPECT_NEAR(north.y(), 5.0, 1e-12);  // compass 0 is up
  const Transform t = Transform::translation({100.0, 0.0}) * Transform::scaling(2.0);
  EXPECT_DOUBLE_EQ(t.scale(), 2.0);
  EXPECT_DOUBLE_EQ(t.apply({1.0, 1.0}).x(), 102.0);
}

TEST(Canvas, VerticesCarryTheIntersectedClip) {
  Canvas c(atlas());
  c.reset(200, 100);
  c.push(Transform::scaling(2.0));
  c.push_clip({10.0, 10.0, 60.0, 40.0});  // (20, 20)-(120, 80) on the screen
  c.push_clip({0.0, 0.0, 30.0, 100.0});   // within it: (20, 20)-(60, 80)
  c.fill_rect({0.0, 0.0, 1.0, 1.0}, Colour{});
  c.pop_clip();
  c.pop_clip();
  c.pop();
  ASSERT_EQ(c.vertex_count(), 6u);
  const float* v = c.vertices().data();
  EXPECT_FLOAT_EQ(v[Canvas::kFloatsPerVertex * 2 + 0], 2.0f);  // (1, 1) scaled by 2
  EXPECT_FLOAT_EQ(v[8], 20.0f);
  EXPECT_FLOAT_EQ(v[9], 20.0f);
  EXPECT_FLOAT_EQ(v[10], 60.0f);
  EXPECT_FLOAT_EQ(v[11], 80.0f);
  EXPECT_LT(v[2], 0.0f);  // solid colour, no texture
  EXPECT_THROW(c.pop(), std::logic_error);
  EXPECT_THROW(c.pop_clip(), std::logic_error);
}

TEST(Canvas, TextFromTheAtlas) {
  Canvas c(atlas());
  c.reset(400, 400);
  const double w = c.text("12 4", {100.0, 100.0}, 20.0, Align::kCentre, Face::kMono, Colour{});
  EXPECT_EQ(c.vertex_count(), 3u * 6u);  // a quad per inked glyph, none for the space
  EXPECT_NEAR(w, 2.0 * c.text_width("12", 20.0, Face::kMono), 1e-9);
  EXPECT_NEAR(c.text_width("12", 40.0, Face::kMono), 2.0 * c.text_width("12", 20.0, Face::kMono),
              1e-9);
  // Centred: the glyphs span about 100 +- w/2; capitals' middle at y = 100.
  float x0 = 1e9f, x1 = -1e9f;
  for (std::size_t i = 0; i < c.vertex_count(); ++i) {
    x0 = std::min(x0, c.vertices()[i * Canvas::kFloatsPerVertex]);
    x1 = std::max(x1, c.vertices()[i * Canvas::kFloatsPerVertex]);
  }
  EXPECT_NEAR(0.5 * (x0 + x1), 100.0, 2.0);
  EXPECT_LT(x1 - x0, w + 1e-6);
}

}  // namespace
}  // namespace fedsim::symbology
