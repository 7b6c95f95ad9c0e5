// Draws the head-up display off-screen for one visual channel (common/symbology's canvas
// renderer: OpenGL 3.3 core, FreeType text): green symbology on a transparent background
// (alpha 0) with premultiplied alpha, ready for composite_over() onto the picture of the channel
// whose ChannelConfig it was drawn for (fedsim-visual --hud draws it over its centre channel).
// Bad inputs throw std::invalid_argument naming the field; GL failures std::runtime_error.
#pragma once

#include "common/hud/hud_inputs.hpp"
#include "common/symbology/canvas_renderer.hpp"
#include "common/view/channel_config.hpp"

#include <memory>
#include <string>

namespace fedsim::hud {

class HudRenderer {
 public:
  /// A null context: a new OSMesa one; the fonts the build found; `samples`: 1, 2 or 4.
  explicit HudRenderer(std::unique_ptr<gl::GlContext> context = nullptr,
                       const symbology::FontPaths& fonts = symbology::default_font_paths(),
                       int samples = symbology::CanvasRenderer::kDefaultSamples)
      : canvas_(std::move(context), fonts, samples) {}

  /// The HUD for the visual channel `channel` (its size, field of view and offsets), so that
  /// its conformal symbols fall on what that channel's camera shows.
  symbology::DrawStats render(const HudInputs& in, const view::ChannelConfig& channel,
                              picture::Image& image);

  void set_clock(gl::RenderClock clock) { canvas_.set_clock(std::move(clock)); }
  std::string description() const { return canvas_.description(); }

 private:
  symbology::CanvasRenderer canvas_;
};

}  // namespace fedsim::hud
