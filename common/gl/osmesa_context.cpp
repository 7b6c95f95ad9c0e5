#include "common/gl/osmesa_context.hpp"

#include <GL/osmesa.h>

#include <stdexcept>

namespace fedsim::gl {

namespace {
constexpr int kSurfacePx = 16;  // the context's own buffer; frames go to framebuffer objects
}  // namespace

struct OsMesaContext::Handle {
  OSMesaContext context = nullptr;
};

OsMesaContext::OsMesaContext()
    : handle_(std::make_unique<Handle>()), surface_(kSurfacePx * kSurfacePx * 4, 0) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  handle_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (handle_->context == nullptr) {
    throw std::runtime_error(
        "OSMesa: cannot create an OpenGL 3.3 core context (is libosmesa6 installed?)");
  }
  make_current();
}

OsMesaContext::~OsMesaContext() {
  if (handle_ && handle_->context != nullptr) OSMesaDestroyContext(handle_->context);
}

void OsMesaContext::make_current() {
  if (!OSMesaMakeCurrent(handle_->context, surface_.data(), GL_UNSIGNED_BYTE, kSurfacePx,
                         kSurfacePx)) {
    throw std::runtime_error("OSMesa: cannot make the context current");
  }
}

void* OsMesaContext::proc_address(const char* name) const {
  return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

std::string OsMesaContext::description() const {
  const auto text = [](GLenum which) {
    const auto* s = reinterpret_cast<const char*>(glGetString(which));
    return std::string(s != nullptr ? s : "?");
  };
  return "OSMesa: " + text(GL_VERSION) + ", " + text(GL_RENDERER);
}

}  // namespace fedsim::gl
