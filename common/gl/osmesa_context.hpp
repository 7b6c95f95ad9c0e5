// A software OpenGL context from OSMesa (Mesa's off-screen interface; llvmpipe rasterises on the
// CPU), so the image generator runs on machines without a GPU or a display (CI).
//
// Asks for a core profile of at least OpenGL 3.3 (OSMesaCreateContextAttribs; Mesa 22.3 gives
// 4.5 core), RGBA. The renderer draws into its own framebuffer objects (colour and a 32-bit float
// depth buffer), so the OSMesa buffer is only the tiny surface the context needs to be current.
// Throws std::runtime_error when the context cannot be made.
#pragma once

#include "common/gl/gl_context.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::gl {

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext();
  ~OsMesaContext() override;
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void make_current() override;
  void* proc_address(const char* name) const override;
  std::string description() const override;

 private:
  struct Handle;
  std::unique_ptr<Handle> handle_;
  std::vector<std::uint8_t> surface_;  // the OSMesa colour buffer (kSurfacePx square, RGBA)
};

}  // namespace fedsim::gl
