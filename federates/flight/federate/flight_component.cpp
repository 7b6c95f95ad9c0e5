#include "flight/federate/flight_component.hpp"

namespace fedsim::flight {

FlightComponent::FlightComponent(std::string name, FlightSetup setup, std::string_view state_qos)
    : Component(std::move(name)),
      pilot_controls_(reads(runtime::topics::pilot_controls)),
      aircraft_state_(writes(runtime::topics::aircraft_state, state_qos)),
      engine_state_(writes(runtime::topics::engine_state)),
      setup_(std::move(setup)),
      trim_base_(setup_.start.controls) {
  state_.aircraft_id(static_cast<uint16_t>(setup_.aircraft_id));
  engine_.aircraft_id(static_cast<uint16_t>(setup_.aircraft_id));
}

void FlightComponent::on_command(const msg::SimCommand& command) {
  try {
    const std::string what = apply_command(command, *setup_.model, setup_.runways);
    if (command.kind() == msg::COMMAND_REPOSITION) trim_base_ = setup_.model->controls();
    if (!what.empty()) {
      log().info("command seq={} from={}: {}", command.sequence_number(),
                 command.issuer().to_string(), what);
    }
  } catch (const std::exception& e) {
    log().error("command seq={} rejected: {}", command.sequence_number(), e.what());
  }
}

void FlightComponent::apply_pilot_controls(const runtime::FrameContext& frame) {
  const msg::PilotControls* pilot = pilot_controls_.latest();
  if (pilot && pilot_controls_.updates() != controls_seen_) {
    controls_seen_ = pilot_controls_.updates();
    if (const auto problem = check_pilot_controls(*pilot)) {
      report_fault("input_rejected", "frame " + std::to_string(frame.frame) +
                                         ": pilot_controls of frame " +
                                         std::to_string(pilot->stamp().frame()) + " " +
                                         *problem + " (kept the previous controls)");
    } else {
      last_valid_controls_ = *pilot;
      have_valid_controls_ = true;
    }
  }
  // Every frame: relative controls follow the trim base, which a reposition moves.
  if (have_valid_controls_) {
    setup_.model->set_controls(
        controls_from_message(last_valid_controls_, setup_.controls_mode, trim_base_));
  }
}

void FlightComponent::step(const runtime::FrameContext& frame) {
  AircraftModel& model = *setup_.model;
  if (frame.resetting()) {
    model.reset(setup_.start.initial, setup_.start.controls);
    trim_base_ = setup_.start.controls;
    dropped_steps_seen_ = 0;
  } else if (frame.running()) {
    apply_pilot_controls(frame);
    model.step(frame.dt_s);
    const std::uint64_t dropped = model.outputs().dropped_steps;
    if (dropped != dropped_steps_seen_) {
      report_fault("numerical", "frame " + std::to_string(frame.frame) + ": the model dropped " +
                                    std::to_string(dropped - dropped_steps_seen_) +
                                    " integration step(s) that gave a non-finite state");
      dropped_steps_seen_ = dropped;
    }
  }
  write_state(frame);
}

void FlightComponent::write_state(const runtime::FrameContext& frame) {
  fill_aircraft_state(setup_.model->outputs(), setup_.model->controls(), state_);
  state_.stamp(frame.end_stamp());  // the state after this frame's step
  aircraft_state_.write(state_);
  const auto& engines = setup_.model->outputs().engines;
  for (std::size_t i = 0; i < engines.size(); ++i) {
    fill_engine_state(engines[i], i, engine_);
    engine_.stamp(frame.end_stamp());
    engine_state_.write(engine_);
  }
}

}  // namespace fedsim::flight
