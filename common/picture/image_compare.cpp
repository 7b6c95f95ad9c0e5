#include "common/picture/image_compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace fedsim::picture {

std::string ImageDifference::describe() const {
  char text[96];
  std::snprintf(text, sizeof text, "mean |diff| %.2f levels, %.3f %% of pixels differ", mean_abs_diff,
                100.0 * differing_fraction);
  return text;
}

ImageDifference compare_images(const Image& a, const Image& b, int pixel_threshold) {
  if (a.width_px != b.width_px || a.height_px != b.height_px) {
    throw std::invalid_argument("compare_images: " + std::to_string(a.width_px) + "x" + std::to_string(a.height_px) +
                                " against " + std::to_string(b.width_px) + "x" + std::to_string(b.height_px));
  }
  const std::size_t pixels = static_cast<std::size_t>(a.width_px) * static_cast<std::size_t>(a.height_px);
  ImageDifference d;
  if (pixels == 0) return d;
  std::uint64_t sum = 0, differing = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    int largest = 0;
    for (std::size_t c = 0; c < 3; ++c) {  // RGB; alpha is 255 in both (opaque frames)
      const int diff = std::abs(static_cast<int>(a.rgba[4 * i + c]) - static_cast<int>(b.rgba[4 * i + c]));
      sum += static_cast<std::uint64_t>(diff);
      largest = std::max(largest, diff);
    }
    if (largest > pixel_threshold) ++differing;
  }
  d.mean_abs_diff = static_cast<double>(sum) / (3.0 * static_cast<double>(pixels));
  d.differing_fraction = static_cast<double>(differing) / static_cast<double>(pixels);
  return d;
}

}  // namespace fedsim::picture
