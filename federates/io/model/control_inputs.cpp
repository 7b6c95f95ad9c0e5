#include "io/model/control_inputs.hpp"

#include <algorithm>

namespace fedsim::io {

namespace {
constexpr std::array<ChannelInfo, kChannelCount> kChannels{{
    {"elevator", -1, 1}, {"aileron", -1, 1}, {"rudder", -1, 1},
    {"elevator_trim", -1, 1}, {"aileron_trim", -1, 1}, {"rudder_trim", -1, 1},
    {"throttle1", 0, 1}, {"throttle2", 0, 1}, {"throttle3", 0, 1}, {"throttle4", 0, 1},
    {"mixture1", 0, 1}, {"mixture2", 0, 1}, {"mixture3", 0, 1}, {"mixture4", 0, 1},
    {"propeller1", 0, 1}, {"propeller2", 0, 1}, {"propeller3", 0, 1}, {"propeller4", 0, 1},
    {"flaps", 0, 1}, {"speedbrake", 0, 1}, {"gear_down", 0, 1},
    {"brake_left", 0, 1}, {"brake_right", 0, 1},
    {"nosewheel_steering", -1, 1}, {"wing_leveller", 0, 1},
    {"column_force_n", -1500, 1500}, {"wheel_force_n", -1500, 1500}, {"pedal_force_n", -1500, 1500},
    {"nav1_mhz", 0, 117.95}, {"nav2_mhz", 0, 117.95}, {"adf_khz", 0, 1750},
    {"obs1_deg", 0, 360}, {"obs2_deg", 0, 360},
    {"mcp_heading_deg", 0, 360}, {"mcp_altitude_ft", -1000, 50000}, {"mcp_vs_fpm", -6000, 6000},
    {"mcp_speed_kt", 80, 380}, {"mcp_bank_limit_deg", 5, 30},
    {"fd", 0, 1}, {"at_arm", 0, 1}, {"autobrake", 0, 4},
    {"mcp_cmd", 0, 1}, {"mcp_cws", 0, 1}, {"ap_disconnect", 0, 1}, {"at_disconnect", 0, 1},
    {"mcp_hdg_sel", 0, 1}, {"mcp_wlv", 0, 1}, {"mcp_vor_loc", 0, 1}, {"mcp_app", 0, 1},
    {"mcp_alt_hld", 0, 1}, {"mcp_vs", 0, 1}, {"mcp_lvl_chg", 0, 1}, {"mcp_speed", 0, 1},
    {"mcp_n1", 0, 1}, {"toga", 0, 1},
}};

std::vector<Channel> engine_group(Channel first) {
  std::vector<Channel> out;
  for (int i = 0; i < kMaxEngines; ++i) out.push_back(static_cast<Channel>(static_cast<int>(first) + i));
  return out;
}
}  // namespace

const ChannelInfo& channel_info(Channel channel) {
  return kChannels[static_cast<std::size_t>(channel)];
}

std::vector<Channel> channels_named(std::string_view name) {
  if (name == "throttle") return engine_group(Channel::kThrottle1);
  if (name == "mixture") return engine_group(Channel::kMixture1);
  if (name == "propeller") return engine_group(Channel::kPropeller1);
  if (name == "brakes") return {Channel::kBrakeLeft, Channel::kBrakeRight};
  for (int i = 0; i < kChannelCount; ++i) {
    if (kChannels[static_cast<std::size_t>(i)].name == name) return {static_cast<Channel>(i)};
  }
  return {};
}

std::vector<std::string> known_channel_names() {
  std::vector<std::string> out{"throttle", "mixture", "propeller", "brakes"};
  for (const auto& c : kChannels) out.emplace_back(c.name);
  return out;
}

void ControlInputs::clamp() {
  for (int i = 0; i < kChannelCount; ++i) {
    const auto& info = kChannels[static_cast<std::size_t>(i)];
    value[static_cast<std::size_t>(i)] = std::clamp(value[static_cast<std::size_t>(i)], info.min, info.max);
  }
}

ControlInputs default_controls() {
  ControlInputs c;
  for (Channel ch : engine_group(Channel::kMixture1)) c[ch] = 1.0;
  for (Channel ch : engine_group(Channel::kPropeller1)) c[ch] = 1.0;
  c[Channel::kGearDown] = 1.0;
  c[Channel::kMcpSpeedKt] = 150.0;
  c[Channel::kMcpBankLimitDeg] = 25.0;
  c[Channel::kFlightDirector] = 1.0;
  return c;
}

void McpButtonCounter::update(const ControlInputs& controls) {
  for (int i = 0; i < kMcpButtonCount; ++i) {
    const bool now = controls[static_cast<Channel>(static_cast<int>(Channel::kMcpCmd) + i)] >= 0.5;
    if (now && !held_[static_cast<std::size_t>(i)]) ++presses_[static_cast<std::size_t>(i)];
    held_[static_cast<std::size_t>(i)] = now;
  }
}

bool McpButtonCounter::held(Channel button) const {
  const int i = static_cast<int>(button) - static_cast<int>(Channel::kMcpCmd);
  return i >= 0 && i < kMcpButtonCount && held_[static_cast<std::size_t>(i)];
}

}  // namespace fedsim::io
