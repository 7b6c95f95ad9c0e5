// The runway designation characters (digits 0-9 and the letters L, C, R) as painted
// rectangles, 9 m high (ICAO Annex 14 Vol I 5.2.2 and Figure 5-3: the characters are 9 m high).
// Glyph cell 3.0 m wide, strokes 0.75 m: block forms of the Figure's shapes (segments, with a
// diagonal leg for R), which is what a pilot reads at 1-3 NM; the Figure's exact outlines are
// not reproduced.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace fedsim::visual {

inline constexpr double kGlyphHeightM = 9.0;
inline constexpr double kGlyphWidthM = 3.0;
inline constexpr double kGlyphStrokeM = 0.75;

/// A painted quadrilateral, corners in order around it, in a 2-D plane [m].
struct Quad2 {
  std::array<Eigen::Vector2d, 4> corners;
};

/// The quads of one character in glyph coordinates (u to the right of the reader, v up the
/// character, origin at its lower left corner); throws std::invalid_argument for a character
/// that is not a digit, 'L', 'C' or 'R'.
std::vector<Quad2> glyph_quads(char character);

}  // namespace fedsim::visual
