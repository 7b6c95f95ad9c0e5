// The image generator's renderer: draws one channel's picture of a Scene for an eye pose and an
// environment, off-screen, and reads it back as an Image (PNG with write_png()).
//
// Passes, into a framebuffer object (RGBA8 colour, 32-bit float depth, optional multisampling):
//  1. environment: each pixel's ray (channel_camera.hpp) meets the ground sphere (textured
//     ground, procedural_texture.hpp) or the sky (sky_model.hpp), both through the atmosphere
//     (environment.hpp); no depth written (the ground lies below every pavement);
//  2. surfaces: pavements and markings, lit by the ambient light, through the atmosphere,
//     depth-tested (reversed Z: markings 3 cm above the pavement win);
//  3. light points (light_point.hpp): GL points, blended over the picture, depth-tested against
//     the surfaces (not written), sized and faded by Allard's law (shaders.cpp).
// Render time: measured with a monotonic clock the caller lends (set_clock(); the adapter's
// clock, a test's fake one), so this library reads no clock itself: from the clear to the image
// in memory, and to the last draw submitted (llvmpipe rasterises when the read-back flushes, so
// most of the time lies after that). GL timer queries are not used: on llvmpipe 22.3 they are
// taken when commands are queued, and GL_TIME_ELAPSED returns a raw timestamp for the first
// query of a context.
//
// The renderer owns its GL context (OSMesa by default) and must be used from one thread.
// Errors: a bad config, pose or environment throws std::invalid_argument naming the field;
// GL failures throw std::runtime_error.
#pragma once

#include "common/gl/gl_context.hpp"
#include "common/gl/render_clock.hpp"
#include "common/picture/image.hpp"
#include "common/view/channel_config.hpp"
#include "visual/model/channel_camera.hpp"
#include "visual/model/environment.hpp"
#include "visual/model/eye_pose.hpp"
#include "visual/model/scene.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace fedsim::visual {

struct RenderStats {
  double render_time_ms = 0.0;       // clear to the image in memory (0 without a clock) [ms]
  double submit_time_ms = 0.0;       // clear to the last draw call issued [ms]
  std::size_t triangles = 0;         // surface triangles submitted
  std::size_t lights = 0;            // light points submitted
  double light_threshold_lux = 0.0;  // E_T the frame used
};

struct RenderedFrame {
  picture::Image image;
  RenderStats stats;
};

class Renderer {
 public:
  /// Renders with a new OSMesa context (software, no GPU).
  explicit Renderer(Scene scene);
  Renderer(Scene scene, std::unique_ptr<gl::GlContext> context);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Draws into `image` (resized to the channel), reusing its storage frame to frame.
  RenderStats render(const view::ChannelConfig& channel, const EyePose& eye,
                     const Environment& environment, picture::Image& image);
  RenderedFrame render(const view::ChannelConfig& channel, const EyePose& eye,
                       const Environment& environment);

  /// The clock render() times frames with (none: the times stay 0).
  void set_clock(gl::RenderClock clock);

  ChannelCamera camera(const view::ChannelConfig& channel, const EyePose& eye) const;
  const Scene& scene() const;
  std::string description() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fedsim::visual
