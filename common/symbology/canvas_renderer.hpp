// Draws a Canvas (canvas.hpp) off-screen: the canvas' triangles are drawn in one call with
// OpenGL 3.3 core into a multisampled framebuffer (gl::RenderTarget, 4 samples: smooth lines and
// text) and read back into a picture::Image (RGBA8, rows from the top; write_png() for a file).
// What the cockpit displays (the PFD and ND of fedsim-displays) and the head-up display
// (common/hud, drawn over fedsim-visual's centre channel) are drawn with.
//
// A picture is begun (begin(): the canvas emptied for that size), drawn into the canvas, and
// finished (finish(): cleared to a background, drawn, read back). An opaque display clears to
// black (alpha 255); symbology for an overlay to transparent (alpha 0), and the blend then
// leaves premultiplied alpha (the colour channels already multiplied by alpha), ready for
// hud::composite_over().
//
// Text: the FontAtlas (FreeType, DejaVu) is built and uploaded once, in the constructor.
// Render time: measured with the clock the caller lends (set_clock()), from begin() to the image
// in memory; this library reads no clock itself. The renderer owns its GL context (any
// gl::GlContext: OSMesa, EGL on a GPU machine) and must be used from one thread. GL failures
// throw std::runtime_error.
#pragma once

#include "common/gl/gl_context.hpp"
#include "common/gl/render_clock.hpp"
#include "common/picture/image.hpp"
#include "common/symbology/canvas.hpp"
#include "common/symbology/font_atlas.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace fedsim::symbology {

struct DrawStats {
  double render_time_ms = 0.0;  // begin() to the image in memory (0 without a clock) [ms]
  std::size_t triangles = 0;    // triangles drawn
};

/// Throws std::invalid_argument "<where>: field 'width_px': ..." unless both sides are 16..4096 px.
void check_picture_size(int width_px, int height_px, const char* where);

class CanvasRenderer {
 public:
  static constexpr int kDefaultSamples = 4;

  /// A null context: a new OSMesa one (software, no GPU); `samples`: multisampling 1, 2 or 4.
  explicit CanvasRenderer(std::unique_ptr<gl::GlContext> context = nullptr,
                          const FontPaths& fonts = default_font_paths(), int samples = kDefaultSamples);
  ~CanvasRenderer();
  CanvasRenderer(const CanvasRenderer&) = delete;
  CanvasRenderer& operator=(const CanvasRenderer&) = delete;

  /// Makes the context current, starts the clock and empties the canvas for a picture of
  /// width x height pixels (checked by the caller: check_picture_size()).
  Canvas& begin(int width_px, int height_px);
  /// Draws what the canvas holds over `background` (RGBA 0..1) into `image`, its storage reused.
  DrawStats finish(const float background[4], picture::Image& image);

  void set_clock(gl::RenderClock clock);
  const FontAtlas& atlas() const;
  std::string description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fedsim::symbology
