#include "common/runtime/topic_catalogue.hpp"

#include <algorithm>

namespace fedsim::runtime {

const std::vector<std::string_view>& qos::all() {
  static const std::vector<std::string_view> profiles = {kTick,         kFrameDone, kState,
                                                         kLockstepData, kCommand,   kStatus, kPicture, kPilotControls};
  return profiles;
}

namespace {
template <class T>
Topic<T> topic(const std::string& name, std::string_view qos, bool lockstep_input,
               std::string description) {
  typename TopicType<T>::PubSubType support;
  return Topic<T>{TopicInfo{name, support.getName(), std::string(qos), lockstep_input,
                            std::move(description)}};
}
/// A topic whose writers write every frame (simulation state and inputs).
template <class T>
Topic<T> frame_topic(const std::string& name, std::string_view qos, bool lockstep_input,
                     std::string description) {
  Topic<T> t = topic<T>(name, qos, lockstep_input, std::move(description));
  t.info.every_frame = true;
  return t;
}

/// A topic each writer keys by its own name (one instance per writer), e.g. per visual channel.
template <class T>
Topic<T> per_writer_topic(const std::string& name, std::string_view qos, std::string description) {
  Topic<T> t = topic<T>(name, qos, false, std::move(description));
  t.info.instance_per_writer = true;
  return t;
}
}  // namespace

namespace topics {
// Backbone (the runtime's own): tick and acknowledgement, commands, status.
const Topic<msg::FrameTick> frame_tick =
    topic<msg::FrameTick>(msg::TOPIC_FRAME_TICK, qos::kTick, false,
                          "start of frame from fedsim-timing: frame number, sim time, run state");
const Topic<msg::FrameDone> frame_done =
    topic<msg::FrameDone>(msg::TOPIC_FRAME_DONE, qos::kFrameDone, false,
                          "a federate finished a frame (keyed by federate)");
const Topic<msg::SimCommand> sim_command = topic<msg::SimCommand>(
    msg::TOPIC_SIM_COMMAND, qos::kCommand, false,
    "instructor commands: run/freeze/reset, reposition, weather, failures, shutdown");
const Topic<msg::FederateStatus> federate_status =
    topic<msg::FederateStatus>(msg::TOPIC_FEDERATE_STATUS, qos::kStatus, false,
                               "each federate's state, frame statistics and faults");
// Simulation data.
const Topic<msg::PilotControls> pilot_controls =
    frame_topic<msg::PilotControls>(msg::TOPIC_PILOT_CONTROLS, qos::kPilotControls, true,
                              "inceptor, lever and switch positions (one owner per aircraft: exclusive ownership)");
const Topic<msg::PilotControls> applied_controls = frame_topic<msg::PilotControls>(
    msg::TOPIC_APPLIED_CONTROLS, qos::kState, true,
    "the controls the flight model flew in each frame (after checks, ownership, trim, autopilot)");
const Topic<msg::AircraftState> aircraft_state =
    frame_topic<msg::AircraftState>(msg::TOPIC_AIRCRAFT_STATE, qos::kState, true,
                              "position, velocity, attitude, rates, air data of each aircraft");
const Topic<msg::AircraftState> replay_state = topic<msg::AircraftState>(
    msg::TOPIC_REPLAY_STATE, qos::kState, false,
    "a recorded aircraft state played back: the flight federate shows it while it arrives");
const Topic<msg::EngineState> engine_state = frame_topic<msg::EngineState>(
    msg::TOPIC_ENGINE_STATE, qos::kState, true, "each engine's thrust, speeds, temperatures");
const Topic<msg::NavigationState> navigation_state = frame_topic<msg::NavigationState>(
    msg::TOPIC_NAVIGATION_STATE, qos::kState, true, "radio aids, INS, GPS, flight director");
const Topic<msg::AutopilotState> autopilot_state = frame_topic<msg::AutopilotState>(
    msg::TOPIC_AUTOPILOT_STATE, qos::kState, true,
    "autopilot, flight director and autothrottle modes (the FMA), FD bars, AFCS commands");
const Topic<msg::MotionPlatformState> motion_state = frame_topic<msg::MotionPlatformState>(
    msg::TOPIC_MOTION_STATE, qos::kState, true, "motion platform pose and actuator lengths");
const Topic<msg::ControlLoadingState> control_loading_state = frame_topic<msg::ControlLoadingState>(
    msg::TOPIC_CONTROL_LOADING_STATE, qos::kState, true, "control loader positions and forces");
const Topic<msg::VisualChannelStatus> visual_status = per_writer_topic<msg::VisualChannelStatus>(
    msg::TOPIC_VISUAL_STATUS, qos::kStatus, "each image generator's render time and age");
const Topic<msg::VisualPicture> visual_picture = per_writer_topic<msg::VisualPicture>(
    msg::TOPIC_VISUAL_PICTURE, qos::kPicture,
    "each image generator's live picture (JPEG, a few per second)");

const std::vector<const TopicInfo*>& all() {
  static const std::vector<const TopicInfo*> every = {
      &frame_tick.info,     &frame_done.info,       &sim_command.info,
      &federate_status.info, &pilot_controls.info,  &applied_controls.info, &aircraft_state.info,
      &engine_state.info,   &navigation_state.info, &autopilot_state.info, &motion_state.info,
      &control_loading_state.info, &visual_status.info, &visual_picture.info, &replay_state.info};
  return every;
}

const TopicInfo* find(std::string_view name) {
  const auto& every = all();
  const auto it =
      std::find_if(every.begin(), every.end(), [&](const TopicInfo* t) { return t->name == name; });
  return it == every.end() ? nullptr : *it;
}

bool is_backbone(std::string_view name) {
  return name == frame_tick.info.name || name == frame_done.info.name ||
         name == sim_command.info.name || name == federate_status.info.name;
}
}  // namespace topics

}  // namespace fedsim::runtime
