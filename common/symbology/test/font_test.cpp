// FreeType rasterises the DejaVu faces into the atlas: real glyphs with coverage, a blank
// space, monospaced digits in the mono face (readouts keep their columns), and a missing font
// named in the error.
#include "common/symbology/font_atlas.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fedsim::symbology {
namespace {

long coverage_sum(const FontAtlas& atlas, const Glyph& g) {
  long sum = 0;
  for (int row = 0; row < g.height; ++row) {
    for (int col = 0; col < g.width; ++col) {
      sum += atlas.coverage()[static_cast<std::size_t>(g.atlas_y + row) * atlas.width() +
                              g.atlas_x + col];
    }
  }
  return sum;
}

TEST(FontAtlas, GlyphsHaveCoverage) {
  const FontAtlas atlas;
  for (Face face : {Face::kMono, Face::kSans}) {
    for (char c : std::string("AHM0123456789/-")) {
      const Glyph& g = atlas.glyph(face, c);
      EXPECT_GT(g.width, 0) << c;
      EXPECT_GT(coverage_sum(atlas, g), 255L * 10) << "'" << c << "' has (almost) no ink";
    }
    // Negative control: the space has an advance and no ink.
    EXPECT_EQ(atlas.glyph(face, ' ').width * atlas.glyph(face, ' ').height, 0);
    EXPECT_GT(atlas.glyph(face, ' ').advance, 0.0);
    // Capitals about 0.73 em high in DejaVu.
    EXPECT_NEAR(atlas.cap_height(face) / atlas.pixel_size(), 0.73, 0.05);
  }
  // 'M' has more ink than 'I'.
  EXPECT_GT(coverage_sum(atlas, atlas.glyph(Face::kSans, 'M')),
            coverage_sum(atlas, atlas.glyph(Face::kSans, 'I')));
}

TEST(FontAtlas, MonoDigitsShareOneWidthSansLettersDoNot) {
  const FontAtlas atlas;
  EXPECT_DOUBLE_EQ(atlas.advance(Face::kMono, "1111"), atlas.advance(Face::kMono, "8888"));
  EXPECT_DOUBLE_EQ(atlas.advance(Face::kMono, "iiii"), atlas.advance(Face::kMono, "MMMM"));
  EXPECT_LT(atlas.advance(Face::kSans, "iiii"), atlas.advance(Face::kSans, "MMMM"));  // control
  // Characters outside printable ASCII are drawn as '?'.
  EXPECT_EQ(&atlas.glyph(Face::kSans, '\t'), &atlas.glyph(Face::kSans, '?'));
}

TEST(FontAtlas, MissingFontIsNamed) {
  try {
    FontAtlas atlas({"/nonexistent/Mono.ttf", default_font_paths().sans});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/Mono.ttf"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("fonts-dejavu-core"), std::string::npos);
  }
}

}  // namespace
}  // namespace fedsim::symbology
