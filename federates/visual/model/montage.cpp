#include "visual/model/montage.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fedsim::visual {

picture::Image side_by_side(const std::vector<picture::Image>& images, int gap_px, picture::Rgba8 gap) {
  if (images.empty()) throw std::invalid_argument("montage: no images");
  if (gap_px < 0) throw std::invalid_argument("montage: gap " + std::to_string(gap_px) + " px is negative");
  const int height = images.front().height_px;
  int width = gap_px * static_cast<int>(images.size() - 1);
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (images[i].height_px != height) {
      throw std::invalid_argument("montage: image " + std::to_string(i + 1) + " is " +
                                  std::to_string(images[i].height_px) + " px high, the first " +
                                  std::to_string(height) + " px");
    }
    width += images[i].width_px;
  }
  picture::Image out(width, height);
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) out.set(column, row, gap);
  }
  int left = 0;
  for (const picture::Image& image : images) {
    const std::size_t row_bytes = static_cast<std::size_t>(image.width_px) * 4;
    for (int row = 0; row < height; ++row) {
      const auto* from = image.rgba.data() + static_cast<std::size_t>(row) * row_bytes;
      auto* to = out.rgba.data() + (static_cast<std::size_t>(row) * width + left) * 4;
      std::copy(from, from + row_bytes, to);
    }
    left += image.width_px + gap_px;
  }
  return out;
}

}  // namespace fedsim::visual
