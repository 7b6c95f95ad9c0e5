// Shared by the HUD's tests (common/hud/test) and the image generator's HUD test, which checks the
// HUD against its own camera: one renderer per test process and a 400 x 300 channel of 40 deg.
#pragma once

#include "common/hud/hud_renderer.hpp"
#include "common/units/units.hpp"
#include "common/view/channel_config.hpp"

#include <cmath>

namespace fedsim::hud::test {

inline HudRenderer& renderer() {
  static HudRenderer r;
  return r;
}

inline view::ChannelConfig channel_400x300() {
  constexpr double kDegToRad = units::kDegToRad;
  view::ChannelConfig c;
  c.width_px = 400;
  c.height_px = 300;
  c.horizontal_fov_rad = 40.0 * kDegToRad;
  c.vertical_fov_rad = 2.0 * std::atan(std::tan(20.0 * kDegToRad) * 300.0 / 400.0);
  return c;
}

}  // namespace fedsim::hud::test
