// Shared helpers of the displays' tests: one renderer per test process, colour classes that
// find the symbols by their meaning's colour (palette.hpp, after 4x multisampling blends their
// edges), and where test pictures go; centroids and counts over rectangles are common/symbology's
// (test/picture_probes.hpp).
#pragma once

#include "common/picture/image.hpp"
#include "common/symbology/test/picture_probes.hpp"
#include "displays/model/display_renderer.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace fedsim::displays::test {

using picture::Image;
using picture::Rgba8;
using symbology::Rect;
using symbology::Vec2;
using symbology::polar;
using symbology::test::centroid;
using symbology::test::count;
using symbology::test::differing_pixels;
using symbology::test::PixelTest;

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
