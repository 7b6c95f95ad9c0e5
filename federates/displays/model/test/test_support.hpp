// Shared helpers of the displays' tests: one renderer per test process, colour classes that
// find the symbols by their meaning's colour (palette.hpp, after 4x multisampling blends their
// edges), centroids and counts over rectangles, and where test pictures go.
#pragma once

#include "displays/model/canvas.hpp"
#include "displays/model/display_renderer.hpp"
#include "common/picture/image.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace fedsim::displays::test {

using picture::Image;
using picture::Rgba8;

inline DisplayRenderer& renderer() {
  static DisplayRenderer r;
  return r;
}

inline bool near(const Rgba8& p, int r, int g, int b, int tolerance) {
  return std::abs(p.r - r) <= tolerance && std::abs(p.g - g) <= tolerance &&
         std::abs(p.b - b) <= tolerance;
}
inline bool is_sky(const Rgba8& p) { return near(p, 31, 115, 217, 30); }
inline bool is_ground(const Rgba8& p) { return near(p, 140, 82, 31, 30); }
inline bool is_magenta(const Rgba8& p) { return p.r > 170 && p.b > 170 && p.g < 150; }
inline bool is_red(const Rgba8& p) { return p.r > 170 && p.g < 90 && p.b < 90; }
inline bool is_cyan(const Rgba8& p) { return p.r < 120 && p.g > 140 && p.b > 190; }
inline bool is_white(const Rgba8& p) { return p.r > 200 && p.g > 200 && p.b > 200; }
/// White text's pixels: small glyphs' strokes are thinner than a pixel, so lighter than white.
inline bool is_light(const Rgba8& p) { return p.r > 110 && p.g > 110 && p.b > 110; }

using PixelTest = std::function<bool(const Rgba8&)>;

inline int count(const Image& image, const Rect& r, const PixelTest& test) {
  int n = 0;
  for (int row = std::max(0, static_cast<int>(std::floor(r.y0)));
       row < std::min(image.height_px, static_cast<int>(std::ceil(r.y1))); ++row) {
    for (int col = std::max(0, static_cast<int>(std::floor(r.x0)));
         col < std::min(image.width_px, static_cast<int>(std::ceil(r.x1))); ++col) {
      if (test(image.at(col, row))) ++n;
    }
  }
  return n;
}

/// Centre of the pixels passing `test` in `r` (pixel centres at +0.5); nullopt when none.
inline std::optional<Vec2> centroid(const Image& image, const Rect& r, const PixelTest& test) {
  Vec2 sum = Vec2::Zero();
  int n = 0;
  for (int row = std::max(0, static_cast<int>(std::floor(r.y0)));
       row < std::min(image.height_px, static_cast<int>(std::ceil(r.y1))); ++row) {
    for (int col = std::max(0, static_cast<int>(std::floor(r.x0)));
         col < std::min(image.width_px, static_cast<int>(std::ceil(r.x1))); ++col) {
      if (test(image.at(col, row))) {
        sum += Vec2(col + 0.5, row + 0.5);
        ++n;
      }
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

/// The sky/ground boundary in `column` between rows y0 and y1: the edge between the last sky
/// row and the first ground row after it (white lines between them split the difference).
inline std::optional<double> sky_ground_boundary(const Image& image, int column, int y0, int y1) {
  std::optional<int> last_sky;
  for (int row = y0; row < y1; ++row) {
    const Rgba8 p = image.at(column, row);
    if (is_sky(p)) last_sky = row;
    if (is_ground(p) && last_sky) return 0.5 * (*last_sky + 1 + row);
  }
  return std::nullopt;
}

inline int differing_pixels(const Image& a, const Image& b, const Rect& r) {
  int n = 0;
  for (int row = static_cast<int>(r.y0); row < static_cast<int>(r.y1); ++row) {
    for (int col = static_cast<int>(r.x0); col < static_cast<int>(r.x1); ++col) {
      const Rgba8 p = a.at(col, row), q = b.at(col, row);
      if (p.r != q.r || p.g != q.g || p.b != q.b || p.a != q.a) ++n;
    }
  }
  return n;
}

/// Where test pictures are written: $FEDSIM_DISPLAYS_TEST_OUTPUT or <tmp>/fedsim_displays_tests.
inline std::filesystem::path output_dir() {
  const char* env = std::getenv("FEDSIM_DISPLAYS_TEST_OUTPUT");
  std::filesystem::path dir =
      env != nullptr ? std::filesystem::path(env)
                     : std::filesystem::temp_directory_path() / "fedsim_displays_tests";
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace fedsim::displays::test
