#include "common/view/channel_config.hpp"

#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"

#include <stdexcept>
#include <string>

namespace fedsim::view {

using units::kDegToRad;
using units::kPi;

namespace {

void check_fields(const ChannelConfig& c, std::string_view at) {
  util::require_in_range(c.horizontal_fov_rad, 1.0 * kDegToRad, 150.0 * kDegToRad, at,
                   "horizontal_fov_rad", "rad");
  util::require_in_range(c.vertical_fov_rad, 1.0 * kDegToRad, 150.0 * kDegToRad, at, "vertical_fov_rad",
                   "rad");
  util::require_in_range(c.width_px, 16, 8192, at, "width_px");
  util::require_in_range(c.height_px, 16, 8192, at, "height_px");
  util::require_in_range(c.near_m, 0.01, 100.0, at, "near_m", "m");
  util::require_in_range(c.heading_offset_rad, -kPi, kPi, at, "heading_offset_rad", "rad");
  util::require_in_range(c.pitch_offset_rad, -0.5 * kPi, 0.5 * kPi, at, "pitch_offset_rad", "rad");
  util::require_in_range(c.roll_offset_rad, -kPi, kPi, at, "roll_offset_rad", "rad");
  const char* axes[] = {"eye_offset_body_m.x", "eye_offset_body_m.y", "eye_offset_body_m.z"};
  for (int i = 0; i < 3; ++i) {
    util::require_in_range(c.eye_offset_body_m[i], -100.0, 100.0, at, axes[i], "m");
  }
  if (c.samples != 1 && c.samples != 2 && c.samples != 4) {
    util::reject(at, "samples", std::to_string(c.samples) + " is not 1, 2 or 4");
  }
}

}  // namespace

void validate(const ChannelConfig& c, std::string_view where) {
  try {
    check_fields(c, where);
  } catch (const std::invalid_argument& e) {
    // Name the channel in the message (built only on failure: validate runs every frame).
    std::string message = e.what();
    message.insert(where.size(), " (channel '" + c.name + "')");
    throw std::invalid_argument(message);
  }
}

std::vector<ChannelConfig> three_channel_layout(const ChannelConfig& centre) {
  validate(centre, "three_channel_layout");
  if (centre.horizontal_fov_rad > 2.0 * kPi / 3.0) {
    util::reject("three_channel_layout", "horizontal_fov_rad",
           "three channels of more than 120 deg each would overlap behind the eye");
  }
  std::vector<ChannelConfig> channels(3, centre);
  channels[0].name = "left";
  channels[0].heading_offset_rad = centre.heading_offset_rad - centre.horizontal_fov_rad;
  channels[1].name = "centre";
  channels[2].name = "right";
  channels[2].heading_offset_rad = centre.heading_offset_rad + centre.horizontal_fov_rad;
  for (auto& c : channels) validate(c, "three_channel_layout");
  return channels;
}

}  // namespace fedsim::view
