// An RGBA image with 8 bits per channel, rows from the top (row 0 is the top of the picture, as
// in PNG), and its PNG file form (libpng).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fedsim::picture {

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  /// Relative luminance 0..1 of the displayed value (ITU-R BT.709 weights).
  double luminance() const { return (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255.0; }
};

struct Image {
  int width_px = 0;
  int height_px = 0;
  std::vector<std::uint8_t> rgba;  // width_px * height_px * 4, row-major from the top

  Image() = default;
  Image(int width, int height);
  /// The pixel in column `column` (from the left) and row `row` (from the top); throws
  /// std::out_of_range outside the image.
  Rgba8 at(int column, int row) const;
  void set(int column, int row, Rgba8 value);
};

/// Writes an 8-bit RGB PNG (alpha dropped: frames are opaque); throws std::runtime_error naming
/// the path when the file cannot be written.
void write_png(const Image& image, const std::string& path);
/// Reads an 8-bit RGB or RGBA PNG (tests read back what write_png wrote); throws
/// std::runtime_error naming the path for a missing or malformed file.
Image read_png(const std::string& path);

}  // namespace fedsim::picture
