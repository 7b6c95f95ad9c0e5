#include "displays/model/display_renderer.hpp"

#include "displays/model/nd.hpp"
#include "displays/model/pfd.hpp"

namespace fedsim::displays {

namespace {
constexpr float kOpaqueBlack[4] = {0.0f, 0.0f, 0.0f, 1.0f};
}  // namespace

DisplayStats DisplayRenderer::render_pfd(const PfdInputs& in, int width_px, int height_px,
                                         picture::Image& image) {
  symbology::check_picture_size(width_px, height_px, "render_pfd");
  draw_pfd(canvas_.begin(width_px, height_px), in);
  return canvas_.finish(kOpaqueBlack, image);
}

DisplayStats DisplayRenderer::render_nd(const NdInputs& in, int width_px, int height_px,
                                        picture::Image& image) {
  symbology::check_picture_size(width_px, height_px, "render_nd");
  draw_nd(canvas_.begin(width_px, height_px), in);
  return canvas_.finish(kOpaqueBlack, image);
}

}  // namespace fedsim::displays
