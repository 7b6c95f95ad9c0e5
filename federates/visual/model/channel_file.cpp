#include "visual/model/channel_file.hpp"

#include "common/units/units.hpp"

#include <set>
#include <stdexcept>

namespace fedsim::visual {
namespace {

using units::kDegToRad;
using units::kRadToDeg;

view::ChannelConfig read_channel(const util::ConfigNode& node) {
  node.reject_unknown_keys({"name", "eye_offset_m", "heading_offset_deg", "pitch_offset_deg", "roll_offset_deg",
                            "horizontal_fov_deg", "vertical_fov_deg", "width_px", "height_px", "near_m",
                            "samples"});
  view::ChannelConfig c;
  c.name = node.string("name");
  if (c.name.empty() || c.name.size() > 31 || c.name.find_first_not_of(
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos) {
    node.fail_at("name", "'" + c.name + "': 1-31 characters of [A-Za-z0-9_-] (it names files and topics)");
  }
  if (node.has("eye_offset_m")) {
    const std::vector<double> v = node.numbers("eye_offset_m", 3);
    for (int i = 0; i < 3; ++i) {
      if (!(v[i] >= -100.0 && v[i] <= 100.0)) node.fail_at("eye_offset_m", "each component within +-100 m");
      c.eye_offset_body_m[i] = v[i];
    }
  }
  c.heading_offset_rad = node.number_or("heading_offset_deg", 0.0, -180.0, 180.0) * kDegToRad;
  c.pitch_offset_rad = node.number_or("pitch_offset_deg", 0.0, -90.0, 90.0) * kDegToRad;
  c.roll_offset_rad = node.number_or("roll_offset_deg", 0.0, -180.0, 180.0) * kDegToRad;
  c.horizontal_fov_rad =
      node.number_or("horizontal_fov_deg", c.horizontal_fov_rad * kRadToDeg, 1.0, 150.0) * kDegToRad;
  c.vertical_fov_rad = node.number_or("vertical_fov_deg", c.vertical_fov_rad * kRadToDeg, 1.0, 150.0) * kDegToRad;
  c.width_px = node.integer_or("width_px", c.width_px, 16, 8192);
  c.height_px = node.integer_or("height_px", c.height_px, 16, 8192);
  c.near_m = node.number_or("near_m", c.near_m, 0.01, 100.0);
  c.samples = node.integer_or("samples", c.samples, 1, 4);
  try {
    validate(c, "channels");
  } catch (const std::invalid_argument& e) {
    node.fail(e.what());
  }
  return c;
}

std::vector<view::ChannelConfig> read_channels(const util::ConfigNode& root) {
  root.reject_unknown_keys({"channels"});
  std::vector<view::ChannelConfig> channels;
  std::set<std::string> names;
  for (const util::ConfigNode& item : root.child("channels").items()) {
    view::ChannelConfig c = read_channel(item);
    if (!names.insert(c.name).second) item.fail_at("name", "'" + c.name + "' is named twice");
    channels.push_back(std::move(c));
  }
  if (channels.empty()) root.fail_at("channels", "at least one channel");
  return channels;
}

}  // namespace

std::vector<view::ChannelConfig> load_channels(const std::string& path) {
  return read_channels(util::ConfigNode::load_file(path));
}

std::vector<view::ChannelConfig> parse_channels(const std::string& text, const std::string& origin) {
  return read_channels(util::ConfigNode::parse(text, origin));
}

std::size_t channel_index(const std::vector<view::ChannelConfig>& channels, const std::string& name,
                          const std::string& origin) {
  std::string names;
  for (std::size_t i = 0; i < channels.size(); ++i) {
    if (channels[i].name == name) return i;
    names += (names.empty() ? "" : ", ") + channels[i].name;
  }
  throw util::ConfigError(origin + ": no channel '" + name + "' (the file has: " + names + ")");
}

view::ChannelConfig load_channel(const std::string& path, const std::string& name) {
  const std::vector<view::ChannelConfig> channels = load_channels(path);
  return channels[channel_index(channels, name, path)];
}

}  // namespace fedsim::visual
