#include "common/gl/render_target.hpp"

#include <cstring>
#include <stdexcept>

namespace fedsim::gl {

namespace {

GLuint make_renderbuffer(const GlApi& gl, GLenum format, int width, int height, int samples) {
  GLuint rb = 0;
  gl.GenRenderbuffers(1, &rb);
  gl.BindRenderbuffer(GL_RENDERBUFFER, rb);
  if (samples > 1) {
    gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  } else {
    gl.RenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  }
  return rb;
}

void require_complete(const GlApi& gl, const char* what) {
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error(std::string("render target: ") + what +
                             " framebuffer incomplete (status " + std::to_string(status) + ")");
  }
}

}  // namespace

RenderTarget::RenderTarget(const GlApi& gl, int width_px, int height_px, int samples)
    : gl_(&gl), width_(width_px), height_(height_px), samples_(samples) {
  gl.GenFramebuffers(1, &draw_framebuffer_);
  gl.BindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer_);
  draw_colour_ = make_renderbuffer(gl, GL_RGBA8, width_px, height_px, samples);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_colour_);
  draw_depth_ = make_renderbuffer(gl, GL_DEPTH_COMPONENT32F, width_px, height_px, samples);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, draw_depth_);
  require_complete(gl, "draw");
  if (samples > 1) {
    gl.GenFramebuffers(1, &resolve_framebuffer_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, resolve_framebuffer_);
    resolve_colour_ = make_renderbuffer(gl, GL_RGBA8, width_px, height_px, 1);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                               resolve_colour_);
    require_complete(gl, "resolve");
  }
  gl.check("render target");
  bottom_up_.resize(static_cast<std::size_t>(width_px) * height_px * 4);
}

RenderTarget::~RenderTarget() {
  const GLuint framebuffers[] = {draw_framebuffer_, resolve_framebuffer_};
  const GLuint renderbuffers[] = {draw_colour_, draw_depth_, resolve_colour_};
  gl_->DeleteFramebuffers(2, framebuffers);
  gl_->DeleteRenderbuffers(3, renderbuffers);
}

void RenderTarget::bind_for_drawing() const {
  gl_->BindFramebuffer(GL_FRAMEBUFFER, draw_framebuffer_);
  gl_->Viewport(0, 0, width_, height_);
}

void RenderTarget::read(picture::Image& image) {
  GLuint source = draw_framebuffer_;
  if (resolve_framebuffer_ != 0) {
    gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, draw_framebuffer_);
    gl_->BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_framebuffer_);
    gl_->BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                         GL_NEAREST);
    source = resolve_framebuffer_;
  }
  gl_->BindFramebuffer(GL_READ_FRAMEBUFFER, source);
  gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_->ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up_.data());
  gl_->check("read back");
  if (image.width_px != width_ || image.height_px != height_) image = picture::Image(width_, height_);
  const std::size_t row_bytes = static_cast<std::size_t>(width_) * 4;
  for (int row = 0; row < height_; ++row) {
    std::memcpy(image.rgba.data() + row * row_bytes,
                bottom_up_.data() + (height_ - 1 - row) * row_bytes, row_bytes);
  }
}

}  // namespace fedsim::gl
