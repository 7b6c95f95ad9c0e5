// The glyphs of the displays and the HUD: FreeType rasterises the printable ASCII characters of
// each font face once, at start, into one coverage atlas (8 bits per texel, 0 = none, 255 =
// full), which the renderer uploads as a texture and samples (trilinear, mipmapped) to draw text
// at any size.
//
// Faces: kMono (DejaVu Sans Mono: every number, so digits keep their columns as they change) and
// kSans (DejaVu Sans: labels and modes), from the Debian package fonts-dejavu-core; the paths are
// found at configure time (common/CMakeLists.txt). Metrics are in atlas pixels at the
// rasterised size (`pixel_size()`); a text drawn h pixels high scales them by h / that.
// Throws std::runtime_error naming the file when FreeType cannot load a face.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fedsim::symbology {

enum class Face { kMono = 0, kSans = 1 };

struct Glyph {
  int atlas_x = 0, atlas_y = 0;  // top-left texel of the bitmap in the atlas
  int width = 0, height = 0;     // bitmap size [px]
  int bearing_x = 0;             // pen position to the bitmap's left edge [px]
  int bearing_y = 0;             // baseline to the bitmap's top edge, up positive [px]
  double advance = 0.0;          // pen advance [px]
};

struct FontPaths {
  std::string mono;
  std::string sans;
};

/// DejaVu Sans Mono and DejaVu Sans where the build found them.
FontPaths default_font_paths();

class FontAtlas {
 public:
  static constexpr char kFirst = 32;  // ' '
  static constexpr char kLast = 126;  // '~'

  explicit FontAtlas(const FontPaths& paths = default_font_paths(), int pixel_size = 40);

  int pixel_size() const { return pixel_size_; }
  int width() const { return width_; }
  int height() const { return height_; }
  /// Coverage, width() * height() bytes, rows from the top.
  const std::vector<std::uint8_t>& coverage() const { return coverage_; }
  /// The glyph of `c`; characters outside ' '..'~' are drawn as '?'.
  const Glyph& glyph(Face face, char c) const;
  /// Height of a capital letter (of 'H') above the baseline [px at pixel_size()].
  double cap_height(Face face) const { return cap_height_[static_cast<int>(face)]; }
  /// Width of `text` at pixel_size() [px].
  double advance(Face face, std::string_view text) const;

 private:
  static constexpr int kGlyphs = kLast - kFirst + 1;
  int pixel_size_;
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> coverage_;
  std::array<std::array<Glyph, kGlyphs>, 2> glyphs_{};
  std::array<double, 2> cap_height_{};
};

}  // namespace fedsim::symbology
