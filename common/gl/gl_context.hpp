// An OpenGL context the renderer draws with: made current on the calling thread, it hands out
// entry points by name. OsMesaContext (software, llvmpipe; no GPU, no window) is the one here;
// an EGL headless context on a GPU machine implements the same interface.
#pragma once

#include <string>

namespace fedsim::gl {

class GlContext {
 public:
  virtual ~GlContext() = default;
  /// Makes the context current on the calling thread (every GL call must follow this).
  virtual void make_current() = 0;
  /// The address of a GL entry point ("glCreateShader"), nullptr when the context lacks it.
  virtual void* proc_address(const char* name) const = 0;
  /// What it is, e.g. "OSMesa: 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)".
  virtual std::string description() const = 0;
};

}  // namespace fedsim::gl
