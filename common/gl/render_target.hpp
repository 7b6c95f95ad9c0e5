// The framebuffer a channel draws into: RGBA8 colour and a 32-bit float depth buffer (reversed Z
// needs the float), multisampled when asked, with a single-sampled copy to read back from.
#pragma once

#include "common/gl/gl_api.hpp"
#include "common/picture/image.hpp"

#include <vector>

namespace fedsim::gl {

class RenderTarget {
 public:
  RenderTarget(const GlApi& gl, int width_px, int height_px, int samples);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  void bind_for_drawing() const;
  /// Resolves the samples (if any) and reads the picture into `image`, rows from the top.
  void read(picture::Image& image);
  bool matches(int width_px, int height_px, int samples) const {
    return width_ == width_px && height_ == height_px && samples_ == samples;
  }

 private:
  const GlApi* gl_;
  int width_;
  int height_;
  int samples_;
  GLuint draw_framebuffer_ = 0;
  GLuint draw_colour_ = 0;
  GLuint draw_depth_ = 0;
  GLuint resolve_framebuffer_ = 0;  // 0 when single-sampled
  GLuint resolve_colour_ = 0;
  std::vector<std::uint8_t> bottom_up_;  // glReadPixels' row order
};

}  // namespace fedsim::gl
