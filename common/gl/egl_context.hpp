// A headless OpenGL context through EGL, with no window and no surface (EGL_KHR_surfaceless_context:
// the renderers draw into their own framebuffer objects). Where there is a GPU, EGL's device
// platform (EGL_EXT_platform_device) gives a hardware context; without one, Mesa's surfaceless
// platform (EGL_MESA_platform_surfaceless) gives llvmpipe, the same rasteriser as OSMesa, so the
// EGL path is exercised in CI on this machine too. Desktop OpenGL 3.3 core (eglBindAPI
// EGL_OPENGL_API, EGL_KHR_create_context), as the OSMesa context.
//
// GlBackend picks the context at run time (the same renderers, the same code): kOsMesa, kEgl
// (the device platform's first hardware device, else Mesa surfaceless; an error naming what
// failed otherwise), kAuto (EGL on a hardware device when there is one, else OSMesa).
#pragma once

#include "common/gl/gl_context.hpp"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace fedsim::gl {

class EglContext final : public GlContext {
 public:
  enum class Platform { kDevice, kSurfaceless };
  /// kDevice: the first EGL device that is not a software one (throws when there is none);
  /// kSurfaceless: Mesa's surfaceless platform. Throws std::runtime_error naming the EGL call
  /// and its error code.
  explicit EglContext(Platform platform);
  ~EglContext() override;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void make_current() override;
  void* proc_address(const char* name) const override;
  std::string description() const override;

 private:
  struct Handle;
  std::unique_ptr<Handle> handle_;
};

enum class GlBackend { kOsMesa, kEgl, kAuto };

/// "osmesa", "egl", "auto" (what the --gl options take); nullopt for anything else.
std::optional<GlBackend> parse_gl_backend(std::string_view text);

/// The context of that backend. kEgl: the device platform's hardware device, else surfaceless
/// Mesa; throws std::runtime_error naming both failures. kAuto: a hardware EGL device, else
/// OSMesa; `fallback_note` (optional) receives why EGL was not used.
std::unique_ptr<GlContext> make_gl_context(GlBackend backend, std::string* fallback_note = nullptr);

}  // namespace fedsim::gl
