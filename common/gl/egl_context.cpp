#include "common/gl/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include "common/gl/osmesa_context.hpp"

#include <cstdio>
#include <stdexcept>
#include <vector>

namespace fedsim::gl {
namespace {

std::string egl_error(const char* call) {
  char text[96];
  std::snprintf(text, sizeof text, "EGL: %s failed (error 0x%04X)", call, static_cast<unsigned>(eglGetError()));
  return text;
}

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  const std::string_view all(list);
  for (std::size_t at = all.find(name); at != std::string_view::npos; at = all.find(name, at + 1)) {
    const bool starts = at == 0 || all[at - 1] == ' ';
    const bool ends = at + name.size() == all.size() || all[at + name.size()] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

template <class F>
F egl_proc(const char* name) {
  auto* f = reinterpret_cast<F>(eglGetProcAddress(name));
  if (f == nullptr) throw std::runtime_error(std::string("EGL: no ") + name);
  return f;
}

// The first EGL device that is not software (EGL_MESA_device_software marks llvmpipe's).
EGLDisplay hardware_device_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_EXT_platform_device") || !has_extension(client, "EGL_EXT_device_enumeration")) {
    throw std::runtime_error("EGL: no EGL_EXT_platform_device / EGL_EXT_device_enumeration");
  }
  auto query_devices = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_string = egl_proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  auto platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  EGLDeviceEXT devices[16];
  EGLint count = 0;
  if (!query_devices(16, devices, &count)) throw std::runtime_error(egl_error("eglQueryDevicesEXT"));
  for (EGLint i = 0; i < count; ++i) {
    if (has_extension(query_string(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software")) continue;
    EGLDisplay display = platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    if (display != EGL_NO_DISPLAY) return display;
  }
  throw std::runtime_error("EGL: no hardware device (" + std::to_string(count) + " device(s), all software)");
}

EGLDisplay surfaceless_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_MESA_platform_surfaceless")) {
    throw std::runtime_error("EGL: no EGL_MESA_platform_surfaceless (is libegl-mesa0 installed?)");
  }
  auto platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  EGLDisplay display = platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) throw std::runtime_error(egl_error("eglGetPlatformDisplayEXT(surfaceless)"));
  return display;
}

}  // namespace

struct EglContext::Handle {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  Platform platform = Platform::kSurfaceless;
};

EglContext::EglContext(Platform platform) : handle_(std::make_unique<Handle>()) {
  handle_->platform = platform;
  handle_->display = platform == Platform::kDevice ? hardware_device_display() : surfaceless_display();
  EGLint major = 0, minor = 0;
  if (!eglInitialize(handle_->display, &major, &minor)) throw std::runtime_error(egl_error("eglInitialize"));
  const char* extensions = eglQueryString(handle_->display, EGL_EXTENSIONS);
  for (const char* needed : {"EGL_KHR_surfaceless_context", "EGL_KHR_no_config_context", "EGL_KHR_create_context"}) {
    if (!has_extension(extensions, needed)) {
      eglTerminate(handle_->display);
      throw std::runtime_error(std::string("EGL: the display lacks ") + needed);
    }
  }
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI(EGL_OPENGL_API)"));
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  handle_->context = eglCreateContext(handle_->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (handle_->context == EGL_NO_CONTEXT) {
    const std::string problem = egl_error("eglCreateContext(OpenGL 3.3 core)");
    eglTerminate(handle_->display);
    throw std::runtime_error(problem);
  }
  make_current();
}

EglContext::~EglContext() {
  if (!handle_ || handle_->display == EGL_NO_DISPLAY) return;
  eglMakeCurrent(handle_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (handle_->context != EGL_NO_CONTEXT) eglDestroyContext(handle_->display, handle_->context);
  // No eglTerminate: the display is shared by every context on it in this process (Mesa
  // reference-counts nothing here), and another renderer may still use it.
}

void EglContext::make_current() {
  if (!eglMakeCurrent(handle_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, handle_->context)) {
    throw std::runtime_error(egl_error("eglMakeCurrent"));
  }
}

void* EglContext::proc_address(const char* name) const { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

std::string EglContext::description() const {
  using GetString = const GLubyte* (*)(GLenum);
  auto get = reinterpret_cast<GetString>(eglGetProcAddress("glGetString"));
  const auto text = [&](GLenum which) {
    const auto* s = get != nullptr ? reinterpret_cast<const char*>(get(which)) : nullptr;
    return std::string(s != nullptr ? s : "?");
  };
  return std::string(handle_->platform == Platform::kDevice ? "EGL device: " : "EGL surfaceless: ") +
         text(GL_VERSION) + ", " + text(GL_RENDERER);
}

std::optional<GlBackend> parse_gl_backend(std::string_view text) {
  if (text == "osmesa") return GlBackend::kOsMesa;
  if (text == "egl") return GlBackend::kEgl;
  if (text == "auto") return GlBackend::kAuto;
  return std::nullopt;
}

std::unique_ptr<GlContext> make_gl_context(GlBackend backend, std::string* fallback_note) {
  switch (backend) {
    case GlBackend::kOsMesa:
      return std::make_unique<OsMesaContext>();
    case GlBackend::kEgl: {
      std::string device_problem;
      try {
        return std::make_unique<EglContext>(EglContext::Platform::kDevice);
      } catch (const std::runtime_error& e) {
        device_problem = e.what();
      }
      try {
        return std::make_unique<EglContext>(EglContext::Platform::kSurfaceless);
      } catch (const std::runtime_error& e) {
        throw std::runtime_error("--gl egl: no EGL context: " + device_problem + "; " + e.what() +
                                 " (--gl osmesa renders on the CPU without EGL)");
      }
    }
    case GlBackend::kAuto:
      try {
        return std::make_unique<EglContext>(EglContext::Platform::kDevice);
      } catch (const std::runtime_error& e) {
        if (fallback_note != nullptr) *fallback_note = std::string(e.what()) + ": OSMesa (llvmpipe) instead";
        return std::make_unique<OsMesaContext>();
      }
  }
  throw std::invalid_argument("make_gl_context: unknown backend");
}

}  // namespace fedsim::gl
