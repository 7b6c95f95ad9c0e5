// Maps each fedsim message type (generated from idl/) to its Fast DDS type support, and
// gathers the generated headers in one place. Topic names are constants in the IDL
// (fedsim::msg::TOPIC_*), so grepping a topic finds its type, publishers and subscribers.
#pragma once

#include "fedsim/msg/aircraft_statePubSubTypes.h"
#include "fedsim/msg/autopilotPubSubTypes.h"
#include "fedsim/msg/commandPubSubTypes.h"
#include "fedsim/msg/controlsPubSubTypes.h"
#include "fedsim/msg/framePubSubTypes.h"
#include "fedsim/msg/motionPubSubTypes.h"
#include "fedsim/msg/navigationPubSubTypes.h"
#include "fedsim/msg/statusPubSubTypes.h"
#include "fedsim/msg/visualPubSubTypes.h"

#include <concepts>

namespace fedsim::runtime {

template <class T>
struct TopicType;  // specialised below for every message type

#define FEDSIM_TOPIC_TYPE(Msg)                                   \
  template <>                                                    \
  struct TopicType<fedsim::msg::Msg> {                           \
    using PubSubType = fedsim::msg::Msg##PubSubType;             \
  };

FEDSIM_TOPIC_TYPE(FrameTick)
FEDSIM_TOPIC_TYPE(FrameDone)
FEDSIM_TOPIC_TYPE(SimCommand)
FEDSIM_TOPIC_TYPE(PilotControls)
FEDSIM_TOPIC_TYPE(AircraftState)
FEDSIM_TOPIC_TYPE(EngineState)
FEDSIM_TOPIC_TYPE(NavigationState)
FEDSIM_TOPIC_TYPE(AutopilotState)
FEDSIM_TOPIC_TYPE(MotionPlatformState)
FEDSIM_TOPIC_TYPE(ControlLoadingState)
FEDSIM_TOPIC_TYPE(FederateStatus)
FEDSIM_TOPIC_TYPE(VisualChannelStatus)
FEDSIM_TOPIC_TYPE(VisualPicture)

#undef FEDSIM_TOPIC_TYPE

/// Messages that carry a FrameStamp (needed for lockstep inputs).
template <class T>
concept Stamped = requires(const T& sample) {
  { sample.stamp().frame() } -> std::convertible_to<unsigned long long>;
};

}  // namespace fedsim::runtime
