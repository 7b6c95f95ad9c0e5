// Renders the cockpit displays off-screen: the PFD and the ND are drawn into a Canvas (pfd.hpp,
// nd.hpp) and the canvas drawn with OpenGL 3.3 core into a picture by common/symbology's canvas
// renderer (multisampled: smooth lines and text; FreeType, DejaVu). Both are opaque (black
// background, alpha 255). The HUD, drawn with the same symbology for fedsim-visual's centre
// channel, is common/hud's HudRenderer.
//
// Render time: measured with the clock the caller lends (set_clock()), from the start of drawing
// to the image in memory; this library reads no clock itself. The renderer owns its GL context
// (OSMesa by default; any gl::GlContext, e.g. EGL on a GPU machine) and must be used from one
// thread. Bad inputs throw std::invalid_argument naming the field; GL failures
// std::runtime_error.
#pragma once

#include "common/gl/gl_context.hpp"
#include "common/gl/render_clock.hpp"
#include "common/picture/image.hpp"
#include "common/symbology/canvas_renderer.hpp"
#include "displays/model/display_inputs.hpp"

#include <memory>
#include <string>

namespace fedsim::displays {

using DisplayStats = symbology::DrawStats;

class DisplayRenderer {
 public:
  static constexpr int kDefaultSamples = symbology::CanvasRenderer::kDefaultSamples;

  /// A null context: a new OSMesa one; the fonts the build found; `samples`: 1, 2 or 4.
  explicit DisplayRenderer(std::unique_ptr<gl::GlContext> context = nullptr,
                           const symbology::FontPaths& fonts = symbology::default_font_paths(),
                           int samples = kDefaultSamples)
      : canvas_(std::move(context), fonts, samples) {}

  /// Pictures of width x height pixels (16..4096) into `image`, its storage reused.
  DisplayStats render_pfd(const PfdInputs& in, int width_px, int height_px, picture::Image& image);
  DisplayStats render_nd(const NdInputs& in, int width_px, int height_px, picture::Image& image);

  void set_clock(gl::RenderClock clock) { canvas_.set_clock(std::move(clock)); }
  const symbology::FontAtlas& atlas() const { return canvas_.atlas(); }
  std::string description() const { return canvas_.description(); }

 private:
  symbology::CanvasRenderer canvas_;
};

}  // namespace fedsim::displays
