// The topic catalogue: every fedsim topic stated once, with its message type, its default QoS
// profile (qos/fedsim_qos.xml) and whether a federate that reads it in lockstep waits for the
// previous frame's sample. Federates declare ports on these (common/runtime/component.hpp);
// nothing else binds a topic name to a type or a profile.
//
// The topic names themselves are the IDL constants (fedsim::msg::TOPIC_*), so that a team using
// fedsim's IDL from another DDS vendor reads them from the same place.
#pragma once

#include "common/runtime/topic_types.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace fedsim::runtime {

/// QoS profile names of qos/fedsim_qos.xml (the reasoning is in qos/README.md).
namespace qos {
inline constexpr std::string_view kTick = "tick";                  // best-effort frame tick
inline constexpr std::string_view kFrameDone = "frame_done";       // best effort, keyed by federate
inline constexpr std::string_view kState = "state";                // best effort, keep last 1
inline constexpr std::string_view kLockstepData = "lockstep_data"; // reliable, transient local
inline constexpr std::string_view kPilotControls = "pilot_controls"; // lockstep_data + exclusive ownership
inline constexpr std::string_view kCommand = "command";            // reliable, transient local
inline constexpr std::string_view kStatus = "status";              // reliable, liveliness
inline constexpr std::string_view kPicture = "picture";            // best effort, keep last 1, large
/// Suffix of the reliable variants of tick and frame_done (--sync-qos reliable).
inline constexpr std::string_view kReliableSuffix = "_reliable";
/// Every data profile above (participant profiles are listed in qos/README.md).
const std::vector<std::string_view>& all();
}  // namespace qos

/// What the catalogue says of a topic, whatever its type (for tools and the port graph).
struct TopicInfo {
  std::string name;          // DDS topic name, e.g. "fedsim/aircraft_state"
  std::string type_name;     // DDS type name, e.g. "fedsim::msg::AircraftState"
  std::string default_qos;   // profile name in qos/fedsim_qos.xml
  bool lockstep_input = false;  // readers wait for the previous frame's sample in lockstep
  std::string description;
  bool every_frame = false;     // its writers write once per frame: a reader reports a matched
                                // writer silent for --silent-frames frames (a silent writer)
  bool instance_per_writer = false;  // keyed by its writer (a visual channel's name): several
                                     // writers in one federation each own their own instances
};

/// A topic with its message type T.
template <class T>
struct Topic {
  using Message = T;
  TopicInfo info;
  const std::string& name() const { return info.name; }
};

/// The catalogue. Topics of the federation backbone (tick, done, command, status) belong to the
/// runtime; the others to the federates that write them.
namespace topics {
extern const Topic<msg::FrameTick> frame_tick;
extern const Topic<msg::FrameDone> frame_done;
extern const Topic<msg::SimCommand> sim_command;
extern const Topic<msg::FederateStatus> federate_status;
extern const Topic<msg::PilotControls> pilot_controls;
extern const Topic<msg::PilotControls> applied_controls;
extern const Topic<msg::AircraftState> aircraft_state;
extern const Topic<msg::EngineState> engine_state;
extern const Topic<msg::NavigationState> navigation_state;
extern const Topic<msg::AutopilotState> autopilot_state;
extern const Topic<msg::MotionPlatformState> motion_state;
extern const Topic<msg::ControlLoadingState> control_loading_state;
extern const Topic<msg::VisualChannelStatus> visual_status;
extern const Topic<msg::VisualPicture> visual_picture;
extern const Topic<msg::AircraftState> replay_state;

/// Every topic above, in this order.
const std::vector<const TopicInfo*>& all();
/// The topic of that name, or nullptr.
const TopicInfo* find(std::string_view name);
/// True for the backbone topics every federate uses through the runtime.
bool is_backbone(std::string_view name);

/// Calls visitor(topic) with the typed catalogue topic of that name (a generic lambda sees its
/// message type); false if the catalogue has no such topic.
template <class Visitor>
bool visit(std::string_view name, Visitor&& visitor) {
  auto try_one = [&](const auto& topic) {
    if (topic.name() != name) return false;
    visitor(topic);
    return true;
  };
  return try_one(frame_tick) || try_one(frame_done) || try_one(sim_command) ||
         try_one(federate_status) || try_one(pilot_controls) || try_one(applied_controls) ||
         try_one(aircraft_state) ||
         try_one(engine_state) || try_one(navigation_state) || try_one(autopilot_state) || try_one(motion_state) ||
         try_one(control_loading_state) || try_one(visual_status) || try_one(visual_picture) ||
         try_one(replay_state);
}
}  // namespace topics

}  // namespace fedsim::runtime
