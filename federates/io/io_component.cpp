#include "io/io_component.hpp"

namespace fedsim::io {

void to_message(const ControlInputs& in, msg::PilotControls& out) {
  out.elevator(static_cast<float>(in[Channel::kElevator]));
  out.aileron(static_cast<float>(in[Channel::kAileron]));
  out.rudder(static_cast<float>(in[Channel::kRudder]));
  out.elevator_trim(static_cast<float>(in[Channel::kElevatorTrim]));
  out.aileron_trim(static_cast<float>(in[Channel::kAileronTrim]));
  out.rudder_trim(static_cast<float>(in[Channel::kRudderTrim]));
  for (int e = 0; e < kMaxEngines; ++e) {
    out.throttle()[e] = static_cast<float>(in.throttle(e));
    out.mixture()[e] = static_cast<float>(in.mixture(e));
    out.propeller()[e] = static_cast<float>(in.propeller(e));
  }
  out.flaps(static_cast<float>(in[Channel::kFlaps]));
  out.speedbrake(static_cast<float>(in[Channel::kSpeedbrake]));
  out.gear_down(in[Channel::kGearDown] >= 0.5);
  out.brake_left(static_cast<float>(in[Channel::kBrakeLeft]));
  out.brake_right(static_cast<float>(in[Channel::kBrakeRight]));
  out.nosewheel_steering(static_cast<float>(in[Channel::kNosewheelSteering]));
}

IoComponent::IoComponent(std::string name, std::unique_ptr<InputSource> source, int aircraft_id,
                         std::string_view controls_qos)
    : Component(std::move(name)),
      pilot_controls_(writes(runtime::topics::pilot_controls, controls_qos)),
      source_(std::move(source)) {
  sample_.aircraft_id(static_cast<uint16_t>(aircraft_id));
  log().info("input source: {}", source_->describe());
}

void IoComponent::step(const runtime::FrameContext& frame) {
  source_->sample(frame.sim_time_s, controls_);
  to_message(controls_, sample_);
  sample_.stamp(frame.stamp());
  pilot_controls_.write(sample_);
}

}  // namespace fedsim::io
