#include "common/hud/composite.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fedsim::hud {

void composite_over(picture::Image& channel, const picture::Image& hud) {
  if (channel.width_px != hud.width_px || channel.height_px != hud.height_px ||
      channel.rgba.size() != hud.rgba.size()) {
    throw std::invalid_argument("composite_over: the HUD is " + std::to_string(hud.width_px) + "x" +
                                std::to_string(hud.height_px) + ", the channel " +
                                std::to_string(channel.width_px) + "x" +
                                std::to_string(channel.height_px));
  }
  for (std::size_t i = 0; i < channel.rgba.size(); i += 4) {
    const int keep = 255 - hud.rgba[i + 3];
    for (std::size_t k = 0; k < 4; ++k) {
      const int out = hud.rgba[i + k] + (channel.rgba[i + k] * keep + 127) / 255;
      channel.rgba[i + k] = static_cast<std::uint8_t>(std::min(out, 255));
    }
  }
}

}  // namespace fedsim::hud
