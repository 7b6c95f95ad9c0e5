// Putting the HUD on the outside world (seed 5.9: the HUD projected as an overlay on the
// visual system, focused at infinity with it): the HUD picture from HudRenderer::render()
// blended over the visual channel's picture it was drawn for.
#pragma once

#include "common/picture/image.hpp"

namespace fedsim::hud {

/// Blends `hud` (premultiplied alpha, as HudRenderer::render() gives it: colour already times alpha)
/// over `channel` of the same size, in place: out = hud + channel * (255 - alpha_hud) / 255,
/// per channel (alpha too), rounded to nearest. Throws std::invalid_argument naming both sizes
/// when they differ.
void composite_over(picture::Image& channel, const picture::Image& hud);

}  // namespace fedsim::hud
