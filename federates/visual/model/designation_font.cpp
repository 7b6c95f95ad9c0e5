#include "visual/model/designation_font.hpp"

#include <stdexcept>
#include <string>

namespace fedsim::visual {

namespace {

constexpr double W = kGlyphWidthM;
constexpr double H = kGlyphHeightM;
constexpr double T = kGlyphStrokeM;

Quad2 box(double u0, double v0, double u1, double v1) {
  return {{Eigen::Vector2d(u0, v0), Eigen::Vector2d(u1, v0), Eigen::Vector2d(u1, v1),
           Eigen::Vector2d(u0, v1)}};
}

// Seven segments: a top, b upper right, c lower right, d bottom, e lower left, f upper left,
// g middle.
Quad2 segment(char s) {
  switch (s) {
    case 'a':
      return box(0, H - T, W, H);
    case 'b':
      return box(W - T, 0.5 * H, W, H);
    case 'c':
      return box(W - T, 0, W, 0.5 * H);
    case 'd':
      return box(0, 0, W, T);
    case 'e':
      return box(0, 0, T, 0.5 * H);
    case 'f':
      return box(0, 0.5 * H, T, H);
    default:
      return box(0, 0.5 * (H - T), W, 0.5 * (H + T));  // 'g'
  }
}

std::vector<Quad2> segments(const char* list) {
  std::vector<Quad2> out;
  for (const char* s = list; *s != '\0'; ++s) out.push_back(segment(*s));
  return out;
}

}  // namespace

std::vector<Quad2> glyph_quads(char c) {
  switch (c) {
    case '0':
      return segments("abcdef");
    case '1':
      return {box(0.5 * (W - T), 0, 0.5 * (W + T), H)};
    case '2':
      return segments("abged");
    case '3':
      return segments("abgcd");
    case '4':
      return segments("fgbc");
    case '5':
      return segments("afgcd");
    case '6':
      return segments("afgedc");
    case '7':
      return segments("abc");
    case '8':
      return segments("abcdefg");
    case '9':
      return segments("abcdfg");
    case 'L':
      return segments("fed");
    case 'C':
      return segments("afed");
    case 'R': {
      auto quads = segments("afebg");
      // The leg: from the middle bar down to the lower right corner, stroke T wide.
      quads.push_back({{Eigen::Vector2d(0.5 * W - 0.5 * T, 0.5 * (H - T)),
                        Eigen::Vector2d(0.5 * W + 0.5 * T, 0.5 * (H - T)), Eigen::Vector2d(W, 0),
                        Eigen::Vector2d(W - T, 0)}});
      return quads;
    }
    default:
      throw std::invalid_argument(std::string("runway designation: no glyph for '") + c + "'");
  }
}

}  // namespace fedsim::visual
