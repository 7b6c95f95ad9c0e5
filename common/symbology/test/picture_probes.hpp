// Probes of rendered symbology for the tests of the displays, the HUD and the image generator's
// HUD: how many pixels of a rectangle pass a test, where their centre is, how many differ
// between two pictures.
#pragma once

#include "common/picture/image.hpp"
#include "common/symbology/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace fedsim::symbology::test {

using picture::Image;
using picture::Rgba8;

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

}  // namespace fedsim::symbology::test
