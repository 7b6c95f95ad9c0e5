// The displays' colours, by what they mean (Boeing EFIS practice, as the 737 FCOM's display
// chapter describes it): white scales and present values, magenta targets and flight director
// (what the crew or the autoflight selected), green active modes and VOR, cyan ADF, navaids and
// the sky, amber cautions, red warning flags; the HUD one green. The tests find symbols by these
// colours, so each is distinct in hue.
#pragma once

#include "common/symbology/canvas.hpp"

namespace fedsim::symbology::palette {

inline constexpr Colour kWhite{1.0f, 1.0f, 1.0f, 1.0f};
inline constexpr Colour kBlack{0.0f, 0.0f, 0.0f, 1.0f};
inline constexpr Colour kMagenta{1.0f, 0.25f, 1.0f, 1.0f};
inline constexpr Colour kGreen{0.2f, 0.95f, 0.3f, 1.0f};
inline constexpr Colour kCyan{0.1f, 0.85f, 1.0f, 1.0f};
inline constexpr Colour kAmber{1.0f, 0.7f, 0.05f, 1.0f};
inline constexpr Colour kRed{1.0f, 0.1f, 0.1f, 1.0f};
inline constexpr Colour kSky{0.12f, 0.45f, 0.85f, 1.0f};
inline constexpr Colour kGround{0.55f, 0.32f, 0.12f, 1.0f};
inline constexpr Colour kTape{0.32f, 0.34f, 0.38f, 1.0f};
inline constexpr Colour kHudGreen{0.2f, 1.0f, 0.35f, 1.0f};

}  // namespace fedsim::symbology::palette
