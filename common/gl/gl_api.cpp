#include "common/gl/gl_api.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace fedsim::gl {

namespace {

template <typename Pointer>
void load(Pointer& out, const GlProcLoader& loader, const char* name) {
  void* address = loader(name);
  if (address == nullptr) {
    throw std::runtime_error(std::string("OpenGL function ") + name +
                             " is not available in this context (OpenGL 3.3 core with "
                             "GL_ARB_clip_control needed)");
  }
  out = reinterpret_cast<Pointer>(address);
}

}  // namespace

GlApi::GlApi(const GlProcLoader& loader) {
#define FEDSIM_GL_LOAD(type, name) load(name, loader, "gl" #name);
  FEDSIM_GL_FUNCTIONS(FEDSIM_GL_LOAD)
#undef FEDSIM_GL_LOAD
}

void GlApi::check(const char* what) const {
  const GLenum error = GetError();
  if (error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", error);
    throw std::runtime_error(std::string(what) + ": OpenGL error " + code);
  }
}

}  // namespace fedsim::gl
