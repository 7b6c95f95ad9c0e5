#include "common/hud/hud_renderer.hpp"

#include "common/hud/hud.hpp"

namespace fedsim::hud {

namespace {
constexpr float kTransparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
}  // namespace

symbology::DrawStats HudRenderer::render(const HudInputs& in, const view::ChannelConfig& channel,
                                         picture::Image& image) {
  view::validate(channel, "render_hud channel");
  symbology::check_picture_size(channel.width_px, channel.height_px, "render_hud channel");
  draw_hud(canvas_.begin(channel.width_px, channel.height_px), in, channel);
  return canvas_.finish(kTransparent, image);
}

}  // namespace fedsim::hud
