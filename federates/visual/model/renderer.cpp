#include "visual/model/renderer.hpp"

#include "common/gl/gl_program.hpp"
#include "common/gl/osmesa_context.hpp"
#include "common/gl/render_target.hpp"
#include "visual/model/procedural_texture.hpp"
#include "visual/model/shaders.hpp"
#include "visual/model/sky_model.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace fedsim::visual {

namespace {

constexpr std::uint64_t kGroundSeed = 0x6f7265646e756f67ULL;
constexpr std::uint64_t kPavementSeed = 0x746e656d65766170ULL;
constexpr int kGroundTexturePx = 512;
constexpr int kPavementTexturePx = 256;
constexpr float kRedFilter = 0.15f;  // PAPI red beam: the white through the red filter
constexpr float kNoCloudM = 1.0e9f;

// Everything of the atmosphere a frame needs, from the environment and the eye.
struct Atmosphere {
  SkyState sky;
  Eigen::Vector3f sun_scene;
  Eigen::Vector3f haze_colour;
  Eigen::Vector3f cloud_colour;
  float sigma_haze = 0.0f;
  float haze_top = 0.0f;
  float sigma_cloud = 0.0f;
  float cloud_base = kNoCloudM;
  float cloud_top = kNoCloudM + 1.0f;
  double threshold_lux = 0.0;
};

float luminance(const Eigen::Vector3f& c) {
  return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z();
}

Atmosphere atmosphere_of(const Environment& e) {
  Atmosphere a;
  a.sky = sky_state(e.sun_elevation_rad);
  const double ce = std::cos(e.sun_elevation_rad);
  a.sun_scene = Eigen::Vector3d(ce * std::cos(e.sun_azimuth_rad), ce * std::sin(e.sun_azimuth_rad),
                                -std::sin(e.sun_elevation_rad))
                    .cast<float>();
  // The haze scatters the horizon's light, greyer than the clear horizon itself.
  const Eigen::Vector3f grey = Eigen::Vector3f::Constant(luminance(a.sky.horizon_rgb));
  a.haze_colour = 0.5f * (a.sky.horizon_rgb + grey);
  a.sigma_haze = static_cast<float>(extinction_per_m(e.visibility_m));
  a.haze_top = static_cast<float>(e.haze_top_agl_m);
  double background = a.sky.background_luminance_cd_per_m2;
  const float daylight = luminance(a.sky.ambient_rgb);
  a.cloud_colour = Eigen::Vector3f::Constant(0.95f * daylight);
  if (e.cloud) {
    // Under an overcast the ground has only the diffuse light through the cloud.
    a.sky.ambient_rgb *= 0.55f;
    a.sky.sun_rgb.setZero();
    a.cloud_colour = Eigen::Vector3f::Constant(0.62f * daylight);
    a.haze_colour = a.cloud_colour * 1.05f;
    background *= 0.5;
    a.haze_top = static_cast<float>(std::min(e.haze_top_agl_m, e.cloud->base_agl_m));
    a.sigma_cloud = static_cast<float>(extinction_per_m(e.cloud->visibility_in_cloud_m));
    a.cloud_base = static_cast<float>(e.cloud->base_agl_m);
    a.cloud_top = static_cast<float>(e.cloud->top_agl_m);
  }
  a.threshold_lux = light_threshold_lux(background);
  return a;
}

void set_atmosphere(const gl::GlProgram& p, const Atmosphere& a, const ChannelCamera& camera,
                    const Scene& scene) {
  p.set("u_eye", camera.eye_scene_m().cast<float>().eval());
  p.set("u_eye_height", static_cast<float>(camera.eye_height_above_ground_m()));
  p.set("u_ground_radius", static_cast<float>(scene.frame.ground_radius_m()));
  p.set("u_sigma_haze", a.sigma_haze);
  p.set("u_haze_top", a.haze_top);
  p.set("u_sigma_cloud", a.sigma_cloud);
  p.set("u_cloud_base", a.cloud_base);
  p.set("u_cloud_top", a.cloud_top);
  p.set("u_haze_colour", a.haze_colour);
  p.set("u_cloud_colour", a.cloud_colour);
}

GLuint upload_texture(const gl::GlApi& gl, const TextureImage& t) {
  GLuint id = 0;
  gl.GenTextures(1, &id);
  gl.BindTexture(GL_TEXTURE_2D, id);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t.size_px, t.size_px, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                t.rgba.data());
  gl.GenerateMipmap(GL_TEXTURE_2D);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  return id;
}

void attribute(const gl::GlApi& gl, GLuint index, int size, std::size_t stride_floats,
               std::size_t offset_floats) {
  gl.EnableVertexAttribArray(index);
  gl.VertexAttribPointer(index, size, GL_FLOAT, GL_FALSE,
                         static_cast<GLsizei>(stride_floats * sizeof(float)),
                         reinterpret_cast<const void*>(offset_floats * sizeof(float)));
}

std::vector<float> surface_data(const Scene& scene) {
  std::vector<float> d;
  d.reserve(scene.triangles.size() * 6);
  for (const auto& v : scene.triangles) {
    d.insert(d.end(), {v.position_scene_m.x(), v.position_scene_m.y(), v.position_scene_m.z(),
                       v.texture_m.x(), v.texture_m.y(), static_cast<float>(v.material)});
  }
  return d;
}

constexpr std::size_t kLightFloats = 17;

std::vector<float> light_data(const Scene& scene) {
  std::vector<float> d;
  d.reserve(scene.lights.size() * kLightFloats);
  for (const auto& l : scene.lights) {
    d.insert(d.end(), {l.position_scene_m.x(), l.position_scene_m.y(), l.position_scene_m.z(),
                       l.beam_axis_scene.x(), l.beam_axis_scene.y(), l.beam_axis_scene.z(),
                       l.up_scene.x(), l.up_scene.y(), l.up_scene.z(), l.colour_rgb.x(),
                       l.colour_rgb.y(), l.colour_rgb.z(), l.intensity_cd, l.beam_half_width_h_rad,
                       l.beam_half_width_v_rad, l.papi_transition_rad, static_cast<float>(l.beam)});
  }
  return d;
}

void check_scene(const Scene& scene) {
  for (const auto& l : scene.lights) {
    const bool finite = l.position_scene_m.allFinite() && l.beam_axis_scene.allFinite() &&
                        l.up_scene.allFinite() && std::isfinite(l.intensity_cd);
    if (!finite || l.intensity_cd < 0.0f || l.beam_half_width_h_rad <= 0.0f ||
        l.beam_half_width_v_rad <= 0.0f) {
      throw std::invalid_argument(
          "Renderer: a light of the scene has a non-finite position or "
          "a bad intensity or beam width");
    }
  }
  for (const auto& v : scene.triangles) {
    if (!v.position_scene_m.allFinite()) {
      throw std::invalid_argument("Renderer: a surface vertex is not finite");
    }
  }
}

}  // namespace

struct Renderer::Impl {
  Impl(Scene s, std::unique_ptr<gl::GlContext> c)
      : scene(std::move(s)),
        context(std::move(c)),
        gl((context->make_current(),
            gl::GlProcLoader([this](const char* n) { return context->proc_address(n); }))),
        environment(gl, "environment", shaders::kEnvironmentVertex, shaders::kEnvironmentFragment),
        surfaces(gl, "surfaces", shaders::kSurfaceVertex, shaders::kSurfaceFragment),
        lights(gl, "lights", shaders::kLightVertex, shaders::kLightFragment) {
    check_scene(scene);
    gl.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    ground_texture_id = upload_texture(gl, ground_texture_image());
    pavement_texture_id = upload_texture(gl, pavement_texture_image());
    gl.GenVertexArrays(1, &empty_vao);
    upload_surfaces();
    upload_lights();
    gl.check("renderer set-up");
  }

  ~Impl() {
    context->make_current();
    target.reset();
    const GLuint buffers[] = {surface_vbo, light_vbo};
    gl.DeleteBuffers(2, buffers);
    const GLuint arrays[] = {empty_vao, surface_vao, light_vao};
    gl.DeleteVertexArrays(3, arrays);
    const GLuint textures[] = {ground_texture_id, pavement_texture_id};
    gl.DeleteTextures(2, textures);
  }

  static TextureImage ground_texture_image() {
    return visual::ground_texture(kGroundSeed, kGroundTexturePx);
  }
  static TextureImage pavement_texture_image() {
    return visual::pavement_texture(kPavementSeed, kPavementTexturePx);
  }

  void upload_surfaces() {
    const std::vector<float> d = surface_data(scene);
    gl.GenVertexArrays(1, &surface_vao);
    gl.BindVertexArray(surface_vao);
    gl.GenBuffers(1, &surface_vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, surface_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(d.size() * sizeof(float)), d.data(),
                  GL_STATIC_DRAW);
    attribute(gl, 0, 3, 6, 0);
    attribute(gl, 1, 2, 6, 3);
    attribute(gl, 2, 1, 6, 5);
  }

  void upload_lights() {
    const std::vector<float> d = light_data(scene);
    gl.GenVertexArrays(1, &light_vao);
    gl.BindVertexArray(light_vao);
    gl.GenBuffers(1, &light_vbo);
    gl.BindBuffer(GL_ARRAY_BUFFER, light_vbo);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(d.size() * sizeof(float)), d.data(),
                  GL_STATIC_DRAW);
    attribute(gl, 0, 3, kLightFloats, 0);
    attribute(gl, 1, 3, kLightFloats, 3);
    attribute(gl, 2, 3, kLightFloats, 6);
    attribute(gl, 3, 3, kLightFloats, 9);
    attribute(gl, 4, 4, kLightFloats, 12);
    attribute(gl, 5, 1, kLightFloats, 16);
  }

  gl::RenderTarget& target_for(const view::ChannelConfig& c) {
    if (!target || !target->matches(c.width_px, c.height_px, c.samples)) {
      target.reset();
      target.emplace(gl, c.width_px, c.height_px, c.samples);
    }
    return *target;
  }

  void draw_environment(const ChannelCamera& camera, const Atmosphere& a) {
    const view::ChannelConfig& c = camera.config();
    gl.Disable(GL_DEPTH_TEST);
    gl.DepthMask(GL_FALSE);
    environment.use();
    set_atmosphere(environment, a, camera, scene);
    const Eigen::Matrix3f scene_from_gl =
        camera.view_rotation_gl().topLeftCorner<3, 3>().transpose();
    environment.set("u_scene_from_gl", scene_from_gl);
    environment.set("u_tan_half", Eigen::Vector2f(static_cast<float>(camera.tan_half_horizontal()),
                                                  static_cast<float>(camera.tan_half_vertical())));
    environment.set("u_viewport", Eigen::Vector2f(static_cast<float>(c.width_px),
                                                  static_cast<float>(c.height_px)));
    const Eigen::Vector3d centre(0.0, 0.0, scene.frame.ground_radius_m());
    environment.set("u_eye_up", (camera.eye_scene_m() - centre).normalized().cast<float>().eval());
    environment.set("u_sun", a.sun_scene);
    const Eigen::Vector3f up = (camera.eye_scene_m() - centre).normalized().cast<float>();
    Eigen::Vector3f sun_horizontal = a.sun_scene - a.sun_scene.dot(up) * up;
    if (sun_horizontal.norm() > 1.0e-4f)
      sun_horizontal.normalize();
    else
      sun_horizontal.setZero();
    environment.set("u_sun_horizontal", sun_horizontal);
    environment.set("u_zenith", a.sky.zenith_rgb);
    environment.set("u_horizon", a.sky.horizon_rgb);
    environment.set("u_horizon_sun", a.sky.horizon_sunward_rgb);
    environment.set("u_sun_rgb", a.sky.sun_rgb);
    environment.set("u_ambient", a.sky.ambient_rgb);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, ground_texture_id);
    environment.set("u_ground_texture", 0);
    gl.BindVertexArray(empty_vao);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  }

  void draw_surfaces(const ChannelCamera& camera, const Atmosphere& a) {
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_GREATER);  // reversed Z: nearer is larger
    gl.DepthMask(GL_TRUE);
    surfaces.use();
    set_atmosphere(surfaces, a, camera, scene);
    surfaces.set("u_view", camera.view_rotation_gl());
    surfaces.set("u_projection", camera.projection_gl());
    surfaces.set("u_ambient", a.sky.ambient_rgb);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, pavement_texture_id);
    surfaces.set("u_pavement_texture", 0);
    gl.BindVertexArray(surface_vao);
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(scene.triangles.size()));
  }

  void draw_lights(const ChannelCamera& camera, const Atmosphere& a) {
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_GEQUAL);
    gl.DepthMask(GL_FALSE);
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl.Enable(GL_PROGRAM_POINT_SIZE);
    lights.use();
    set_atmosphere(lights, a, camera, scene);
    lights.set("u_view", camera.view_rotation_gl());
    lights.set("u_projection", camera.projection_gl());
    lights.set("u_threshold_lux", static_cast<float>(a.threshold_lux));
    lights.set("u_papi_red", Eigen::Vector3f(1.0f, 0.1f, 0.08f));
    lights.set("u_red_filter", kRedFilter);
    lights.set("u_min_size_px", camera.config().samples > 1 ? 2.0f : 1.0f);
    gl.BindVertexArray(light_vao);
    gl.DrawArrays(GL_POINTS, 0, static_cast<GLsizei>(scene.lights.size()));
    gl.Disable(GL_BLEND);
  }

  RenderStats render(const view::ChannelConfig& channel, const EyePose& eye, const Environment& env,
                     picture::Image& image) {
    validate(env, "Renderer environment");
    const ChannelCamera camera(scene.frame, channel, eye);
    const Atmosphere a = atmosphere_of(env);
    context->make_current();
    gl::RenderTarget& t = target_for(channel);
    const std::int64_t start_ns = clock ? clock() : 0;
    t.bind_for_drawing();
    gl.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl.ClearDepth(0.0);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw_environment(camera, a);
    draw_surfaces(camera, a);
    if (env.airport_lights_on) draw_lights(camera, a);
    const std::int64_t submitted_ns = clock ? clock() : 0;
    t.read(image);
    const std::int64_t done_ns = clock ? clock() : 0;
    gl.check("render");
    RenderStats stats;
    stats.submit_time_ms = static_cast<double>(submitted_ns - start_ns) * 1.0e-6;
    stats.render_time_ms = static_cast<double>(done_ns - start_ns) * 1.0e-6;
    stats.triangles = scene.triangles.size() / 3;
    stats.lights = env.airport_lights_on ? scene.lights.size() : 0;
    stats.light_threshold_lux = a.threshold_lux;
    return stats;
  }

  Scene scene;
  std::unique_ptr<gl::GlContext> context;
  gl::GlApi gl;
  gl::GlProgram environment;
  gl::GlProgram surfaces;
  gl::GlProgram lights;
  GLuint ground_texture_id = 0;
  GLuint pavement_texture_id = 0;
  GLuint empty_vao = 0;
  GLuint surface_vao = 0;
  GLuint surface_vbo = 0;
  GLuint light_vao = 0;
  GLuint light_vbo = 0;
  gl::RenderClock clock;
  std::optional<gl::RenderTarget> target;
};

Renderer::Renderer(Scene scene) : Renderer(std::move(scene), std::make_unique<gl::OsMesaContext>()) {}

Renderer::Renderer(Scene scene, std::unique_ptr<gl::GlContext> context) {
  if (!context) throw std::invalid_argument("Renderer: no GL context given");
  impl_ = std::make_unique<Impl>(std::move(scene), std::move(context));
}

Renderer::~Renderer() = default;

RenderStats Renderer::render(const view::ChannelConfig& channel, const EyePose& eye,
                             const Environment& environment, picture::Image& image) {
  return impl_->render(channel, eye, environment, image);
}

RenderedFrame Renderer::render(const view::ChannelConfig& channel, const EyePose& eye,
                               const Environment& environment) {
  RenderedFrame f;
  f.stats = impl_->render(channel, eye, environment, f.image);
  return f;
}

void Renderer::set_clock(gl::RenderClock clock) { impl_->clock = std::move(clock); }

ChannelCamera Renderer::camera(const view::ChannelConfig& channel, const EyePose& eye) const {
  return ChannelCamera(impl_->scene.frame, channel, eye);
}

const Scene& Renderer::scene() const { return impl_->scene; }

std::string Renderer::description() const { return impl_->context->description(); }

}  // namespace fedsim::visual
