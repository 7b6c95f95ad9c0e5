#include "common/symbology/canvas_renderer.hpp"

#include "common/gl/gl_program.hpp"
#include "common/gl/osmesa_context.hpp"
#include "common/gl/render_target.hpp"
#include "common/util/input_checks.hpp"

#include <stdexcept>

namespace fedsim::symbology {

namespace {

using gl::GlApi;
using gl::GlProgram;

// Pixels (y down) to clip space; each fragment outside its vertex's clip rectangle is dropped.
const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_colour;
layout(location = 3) in vec4 a_clip;
uniform vec2 u_viewport;
out vec2 v_position;
out vec2 v_uv;
out vec4 v_colour;
flat out vec4 v_clip;
void main() {
  v_position = a_position;
  v_uv = a_uv;
  v_colour = a_colour;
  v_clip = a_clip;
  gl_Position = vec4(2.0 * a_position.x / u_viewport.x - 1.0,
                     1.0 - 2.0 * a_position.y / u_viewport.y, 0.0, 1.0);
}
)";

const char* const kFragmentShader = R"(#version 330 core
in vec2 v_position;
in vec2 v_uv;
in vec4 v_colour;
flat in vec4 v_clip;
uniform sampler2D u_atlas;
out vec4 o_colour;
void main() {
  if (v_position.x < v_clip.x || v_position.y < v_clip.y ||
      v_position.x >= v_clip.z || v_position.y >= v_clip.w) discard;
  float coverage = v_uv.x < 0.0 ? 1.0 : texture(u_atlas, v_uv).r;
  o_colour = vec4(v_colour.rgb, v_colour.a * coverage);
}
)";

void attribute(const GlApi& gl, GLuint index, int size, std::size_t offset_floats) {
  gl.EnableVertexAttribArray(index);
  gl.VertexAttribPointer(index, size, GL_FLOAT, GL_FALSE,
                         static_cast<GLsizei>(Canvas::kFloatsPerVertex * sizeof(float)),
                         reinterpret_cast<const void*>(offset_floats * sizeof(float)));
}

GLuint upload_atlas(const GlApi& gl, const FontAtlas& atlas) {
  GLuint id = 0;
  gl.GenTextures(1, &id);
  gl.BindTexture(GL_TEXTURE_2D, id);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.width(), atlas.height(), 0, GL_RED, GL_UNSIGNED_BYTE,
                atlas.coverage().data());
  gl.GenerateMipmap(GL_TEXTURE_2D);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return id;
}

}  // namespace

void check_picture_size(int width_px, int height_px, const char* where) {
  util::require_in_range(width_px, 16, 4096, where, "width_px");
  util::require_in_range(height_px, 16, 4096, where, "height_px");
}

struct CanvasRenderer::Impl {
  Impl(std::unique_ptr<gl::GlContext> c, const FontPaths& fonts, int samples_in)
      : context(std::move(c)),
        gl((context->make_current(),
            gl::GlProcLoader([this](const char* n) { return context->proc_address(n); }))),
        program(gl, "symbology", kVertexShader, kFragmentShader),
        atlas(fonts),
        canvas(atlas),
        samples(samples_in) {
    if (samples != 1 && samples != 2 && samples != 4) {
      throw std::invalid_argument("CanvasRenderer: samples must be 1, 2 or 4");
    }
    atlas_texture = upload_atlas(gl, atlas);
    gl.GenVertexArrays(1, &vao);
    gl.BindVertexArray(vao);
    gl.GenBuffers(1, &vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    attribute(gl, 0, 2, 0);
    attribute(gl, 1, 2, 2);
    attribute(gl, 2, 4, 4);
    attribute(gl, 3, 4, 8);
    gl.check("symbology set-up");
  }

  ~Impl() {
    context->make_current();
    target.reset();
    gl.DeleteBuffers(1, &vbo);
    gl.DeleteVertexArrays(1, &vao);
    gl.DeleteTextures(1, &atlas_texture);
  }

  double now_ms() const { return clock ? static_cast<double>(clock()) * 1.0e-6 : 0.0; }

  // Draws what the canvas holds into a fresh picture cleared to `background`.
  DrawStats finish(const float background[4], picture::Image& image, double start_ms) {
    const int w = canvas.width_px(), h = canvas.height_px();
    if (!target || !target->matches(w, h, samples)) {
      target.reset();
      target = std::make_unique<gl::RenderTarget>(gl, w, h, samples);
    }
    target->bind_for_drawing();
    gl.ClearColor(background[0], background[1], background[2], background[3]);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_CULL_FACE);
    gl.Enable(GL_BLEND);
    // Colour blended by alpha, alpha accumulated: over a transparent clear this leaves
    // premultiplied colour, what composite_over() expects.
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    program.use();
    program.set("u_viewport", Eigen::Vector2f(static_cast<float>(w), static_cast<float>(h)));
    program.set("u_atlas", 0);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, atlas_texture);
    gl.BindVertexArray(vao);
    gl.BindBuffer(GL_ARRAY_BUFFER, vbo);
    const std::vector<float>& v = canvas.vertices();
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(),
                  GL_STREAM_DRAW);
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(canvas.vertex_count()));
    target->read(image);
    gl.check("symbology frame");
    DrawStats stats;
    stats.triangles = canvas.vertex_count() / 3;
    if (clock) stats.render_time_ms = now_ms() - start_ms;
    return stats;
  }

  std::unique_ptr<gl::GlContext> context;
  GlApi gl;
  GlProgram program;
  FontAtlas atlas;
  Canvas canvas;
  int samples;
  GLuint atlas_texture = 0;
  GLuint vao = 0;
  GLuint vbo = 0;
  std::unique_ptr<gl::RenderTarget> target;
  gl::RenderClock clock;
  double start_ms = 0.0;  // when the picture being drawn was begun
};

CanvasRenderer::CanvasRenderer(std::unique_ptr<gl::GlContext> context, const FontPaths& fonts, int samples)
    : impl_(std::make_unique<Impl>(context ? std::move(context) : std::make_unique<gl::OsMesaContext>(), fonts,
                                   samples)) {}

CanvasRenderer::~CanvasRenderer() = default;

Canvas& CanvasRenderer::begin(int width_px, int height_px) {
  impl_->context->make_current();
  impl_->start_ms = impl_->now_ms();
  impl_->canvas.reset(width_px, height_px);
  return impl_->canvas;
}

DrawStats CanvasRenderer::finish(const float background[4], picture::Image& image) {
  return impl_->finish(background, image, impl_->start_ms);
}

void CanvasRenderer::set_clock(gl::RenderClock clock) { impl_->clock = std::move(clock); }

const FontAtlas& CanvasRenderer::atlas() const { return impl_->atlas; }

std::string CanvasRenderer::description() const {
  impl_->context->make_current();  // the description is read through the current context
  return impl_->context->description();
}

}  // namespace fedsim::symbology
