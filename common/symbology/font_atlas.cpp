#include "common/symbology/font_atlas.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace fedsim::symbology {

namespace {

constexpr int kAtlasWidth = 1024;
constexpr int kPadding = 2;  // texels between glyphs, so that mipmaps do not bleed

struct LibraryCloser {
  void operator()(FT_Library l) const { FT_Done_FreeType(l); }
};
struct FaceCloser {
  void operator()(FT_Face f) const { FT_Done_Face(f); }
};
using Library = std::unique_ptr<std::remove_pointer_t<FT_Library>, LibraryCloser>;
using FaceHandle = std::unique_ptr<std::remove_pointer_t<FT_Face>, FaceCloser>;

Library open_library() {
  FT_Library library = nullptr;
  if (FT_Init_FreeType(&library) != 0) throw std::runtime_error("FreeType: cannot initialise");
  return Library(library);
}

FaceHandle open_face(FT_Library library, const std::string& path, int pixel_size) {
  FT_Face face = nullptr;
  if (FT_New_Face(library, path.c_str(), 0, &face) != 0) {
    throw std::runtime_error("FreeType: cannot load the font " + path +
                             " (Debian package fonts-dejavu-core)");
  }
  FaceHandle handle(face);
  if (FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixel_size)) != 0) {
    throw std::runtime_error("FreeType: cannot size the font " + path);
  }
  return handle;
}

// A rasterised glyph before it has its place in the atlas.
struct Bitmap {
  Glyph glyph;
  std::vector<std::uint8_t> pixels;
};

Bitmap rasterise(FT_Face face, char c, const std::string& path) {
  if (FT_Load_Char(face, static_cast<FT_ULong>(static_cast<unsigned char>(c)), FT_LOAD_RENDER) !=
      0) {
    throw std::runtime_error(std::string("FreeType: cannot render '") + c + "' of " + path);
  }
  const FT_GlyphSlot slot = face->glyph;
  Bitmap b;
  b.glyph.width = static_cast<int>(slot->bitmap.width);
  b.glyph.height = static_cast<int>(slot->bitmap.rows);
  b.glyph.bearing_x = slot->bitmap_left;
  b.glyph.bearing_y = slot->bitmap_top;
  b.glyph.advance = slot->advance.x / 64.0;  // 26.6 fixed point
  b.pixels.resize(static_cast<std::size_t>(b.glyph.width) * b.glyph.height);
  for (int row = 0; row < b.glyph.height; ++row) {
    std::memcpy(b.pixels.data() + static_cast<std::size_t>(row) * b.glyph.width,
                slot->bitmap.buffer + row * slot->bitmap.pitch, b.glyph.width);
  }
  return b;
}

}  // namespace

FontPaths default_font_paths() { return {FEDSIM_DISPLAYS_FONT_MONO, FEDSIM_DISPLAYS_FONT_SANS}; }

FontAtlas::FontAtlas(const FontPaths& paths, int pixel_size) : pixel_size_(pixel_size) {
  if (pixel_size < 8 || pixel_size > 128) {
    throw std::invalid_argument("FontAtlas: pixel_size must be 8..128");
  }
  const Library library = open_library();
  const std::string files[2] = {paths.mono, paths.sans};
  std::vector<Bitmap> bitmaps;
  for (int f = 0; f < 2; ++f) {
    const FaceHandle face = open_face(library.get(), files[f], pixel_size);
    for (char c = kFirst; c <= kLast; ++c) bitmaps.push_back(rasterise(face.get(), c, files[f]));
    cap_height_[f] =
        bitmaps[static_cast<std::size_t>(f) * kGlyphs + ('H' - kFirst)].glyph.bearing_y;
  }
  // Shelf packing: glyphs left to right in rows as high as the tallest glyph.
  const int shelf = pixel_size * 3 / 2 + kPadding;
  int x = kPadding, y = kPadding;
  for (Bitmap& b : bitmaps) {
    if (x + b.glyph.width + kPadding > kAtlasWidth) {
      x = kPadding;
      y += shelf;
    }
    b.glyph.atlas_x = x;
    b.glyph.atlas_y = y;
    x += b.glyph.width + kPadding;
  }
  width_ = kAtlasWidth;
  height_ = 1;
  while (height_ < y + shelf) height_ *= 2;  // a power of two keeps every mip level whole
  coverage_.assign(static_cast<std::size_t>(width_) * height_, 0);
  for (std::size_t i = 0; i < bitmaps.size(); ++i) {
    const Bitmap& b = bitmaps[i];
    for (int row = 0; row < b.glyph.height; ++row) {
      std::memcpy(coverage_.data() + static_cast<std::size_t>(b.glyph.atlas_y + row) * width_ +
                      b.glyph.atlas_x,
                  b.pixels.data() + static_cast<std::size_t>(row) * b.glyph.width, b.glyph.width);
    }
    glyphs_[i / kGlyphs][i % kGlyphs] = b.glyph;
  }
}

const Glyph& FontAtlas::glyph(Face face, char c) const {
  if (c < kFirst || c > kLast) c = '?';
  return glyphs_[static_cast<int>(face)][c - kFirst];
}

double FontAtlas::advance(Face face, std::string_view text) const {
  double sum = 0.0;
  for (char c : text) sum += glyph(face, c).advance;
  return sum;
}

}  // namespace fedsim::symbology
