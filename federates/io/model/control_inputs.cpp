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
    {"nosewheel_steering", -1, 1},
    {"nav1_mhz", 0, 117.95}, {"nav2_mhz", 0, 117.95}, {"adf_khz", 0, 1750},
    {"obs1_deg", 0, 360}, {"obs2_deg", 0, 360},
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
  return c;
}

}  // namespace fedsim::io
