// The topics the instructor station reads, stated once: fedsim-ios subscribes to them and
// `fedsim graph` draws them. Besides these it reads the backbone (fedsim/frame_tick,
// fedsim/federate_status, fedsim/sim_command) and writes fedsim/sim_command.
#pragma once

#include <string_view>

namespace fedsim::ios {

struct StationRead {
  std::string_view topic;
  std::string_view qos;  // best effort, keep last 1: never holds a writer back
};

inline constexpr StationRead kStationReads[] = {
    {"fedsim/aircraft_state", "state"},        {"fedsim/engine_state", "state"},
    {"fedsim/navigation_state", "state"},      {"fedsim/autopilot_state", "state"},
    {"fedsim/motion_state", "state"},          {"fedsim/control_loading_state", "state"},
    {"fedsim/visual_status", "state"},         {"fedsim/pilot_controls", "pilot_controls"},
    {"fedsim/visual_picture", "picture"},
};

/// What it writes besides fedsim/sim_command: the replay (station_replay.hpp), while one runs.
inline constexpr StationRead kStationWrites[] = {{"fedsim/replay_state", "state"}};

}  // namespace fedsim::ios
