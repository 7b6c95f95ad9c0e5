// The image generator's channels from a YAML file (data/visual/README.md documents the keys;
// data/visual/channels.yaml is the default: one centre channel; three_channels.yaml the
// left/centre/right set that meets edge to edge). Angles in degrees at the edge (a person writes
// them), radians inside. Unknown keys are refused, every number is range-checked, two channels
// with the same name are refused, and each channel is validated as ChannelConfig: a bad file is
// a util::ConfigError naming file, line and field before anything is drawn.
#pragma once

#include "common/util/config_node.hpp"
#include "common/view/channel_config.hpp"

#include <string>
#include <vector>

namespace fedsim::visual {

/// Reads every channel of the file (throws util::ConfigError).
std::vector<view::ChannelConfig> load_channels(const std::string& path);
/// The same from YAML text; `origin` names it in errors.
std::vector<view::ChannelConfig> parse_channels(const std::string& text, const std::string& origin);
/// Where the channel called `name` is in `channels` (read from `origin`); util::ConfigError
/// "<origin>: no channel '<name>' (the file has: a, b)" when absent.
std::size_t channel_index(const std::vector<view::ChannelConfig>& channels, const std::string& name,
                          const std::string& origin);
/// The channel called `name` of the file; util::ConfigError listing the names when absent.
view::ChannelConfig load_channel(const std::string& path, const std::string& name);

}  // namespace fedsim::visual
