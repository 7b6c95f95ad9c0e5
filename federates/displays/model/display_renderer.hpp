// Renders the cockpit displays off-screen: a display is drawn into a Canvas (pfd.hpp, nd.hpp,
// hud.hpp), the canvas' triangles are drawn in one call with OpenGL 3.3 core into a
// multisampled framebuffer (gl::RenderTarget, 4 samples: smooth lines and text) and read
// back into a picture::Image (RGBA8, rows from the top; write_png() for a file).
//
// The PFD and ND are opaque (black background, alpha 255). The HUD is green symbology on a
// transparent background (alpha 0) with premultiplied alpha (the colour channels already
// multiplied by alpha, as the blend leaves them), ready for composite_over() onto the visual
// channel whose ChannelConfig it was drawn for.
//
// Text: the FontAtlas (FreeType, DejaVu) is built and uploaded once, in the constructor.
// Render time: measured with the clock the caller lends (set_clock(), as visual::Renderer),
// from the start of drawing to the image in memory; this library reads no clock itself.
// The renderer owns its GL context (OSMesa by default; any gl::GlContext, e.g. EGL on a
// GPU machine) and must be used from one thread. Bad inputs throw std::invalid_argument naming
// the field; GL failures std::runtime_error.
#pragma once

#include "displays/model/display_inputs.hpp"
#include "displays/model/font_atlas.hpp"
#include "common/view/channel_config.hpp"
#include "common/gl/gl_context.hpp"
#include "common/gl/render_clock.hpp"
#include "common/picture/image.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace fedsim::displays {

struct DisplayStats {
  double render_time_ms = 0.0;  // drawing start to the image in memory (0 without a clock) [ms]
  std::size_t triangles = 0;    // triangles drawn
};

class DisplayRenderer {
 public:
  static constexpr int kDefaultSamples = 4;

  /// Renders with a new OSMesa context and the fonts the build found.
  DisplayRenderer();
  /// `samples`: multisampling 1, 2 or 4.
  DisplayRenderer(std::unique_ptr<gl::GlContext> context, const FontPaths& fonts,
                  int samples = kDefaultSamples);
  ~DisplayRenderer();
  DisplayRenderer(const DisplayRenderer&) = delete;
  DisplayRenderer& operator=(const DisplayRenderer&) = delete;

  /// Pictures of width x height pixels (16..4096) into `image`, its storage reused.
  DisplayStats render_pfd(const PfdInputs& in, int width_px, int height_px, picture::Image& image);
  DisplayStats render_nd(const NdInputs& in, int width_px, int height_px, picture::Image& image);
  /// The HUD for the visual channel `channel` (its size, field of view and offsets), so that
  /// its conformal symbols fall on what that channel's camera shows.
  DisplayStats render_hud(const HudInputs& in, const view::ChannelConfig& channel,
                          picture::Image& image);

  void set_clock(gl::RenderClock clock);
  const FontAtlas& atlas() const;
  std::string description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fedsim::displays
