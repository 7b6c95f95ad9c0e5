#include "flight/federate/flight_component.hpp"

#include <algorithm>

namespace fedsim::flight {

FlightComponent::FlightComponent(std::string name, FlightSetup setup, std::string_view state_qos)
    : Component(std::move(name)),
      pilot_controls_(reads(runtime::topics::pilot_controls)),
      applied_controls_(writes(runtime::topics::applied_controls, state_qos)),
      aircraft_state_(writes(runtime::topics::aircraft_state, state_qos)),
      engine_state_(writes(runtime::topics::engine_state)),
      replay_state_(monitors(runtime::topics::replay_state)),
      setup_(std::move(setup)),
      trim_base_(setup_.start.controls),
      gate_(PilotInputLimits{setup_.aircraft_id}),
      screen_(PilotInputLimits{setup_.aircraft_id}) {
  pilot_controls_.accept_only([this](const msg::PilotControls& s) { return screen_.accept(s); });
  state_.aircraft_id(static_cast<uint16_t>(setup_.aircraft_id));
  applied_.aircraft_id(static_cast<uint16_t>(setup_.aircraft_id));
  engine_.aircraft_id(static_cast<uint16_t>(setup_.aircraft_id));
  if (setup_.autopilot) {
    setup_.autopilot->validate();
    gear_ = afcs::GearGeometry::of(setup_.model->pack());
    // The ILS arrives at the state's own QoS (lockstep_data in lockstep, like the state).
    navigation_state_ = &reads(runtime::topics::navigation_state, state_qos);
    autopilot_state_ = &writes(runtime::topics::autopilot_state, state_qos);
    autopilot_sample_.aircraft_id(static_cast<uint16_t>(setup_.aircraft_id));
  }
}

void FlightComponent::on_command(const msg::SimCommand& command) {
  try {
    if (apply_autopilot_failure(command)) return;
    const std::string what = apply_command(command, *setup_.model, setup_.runways);
    if (command.kind() == msg::COMMAND_REPOSITION) {
      trim_base_ = setup_.model->controls();
      if (afcs_) afcs_->reset();  // a new place: the autopilot starts disengaged
    }
    if (!what.empty()) {
      log().info("command seq={} from={}: {}", command.sequence_number(),
                 command.issuer().to_string(), what);
    }
  } catch (const std::exception& e) {
    log().error("command seq={} rejected: {}", command.sequence_number(), e.what());
  }
}

bool FlightComponent::apply_autopilot_failure(const msg::SimCommand& command) {
  if (command.kind() != msg::COMMAND_FAILURE) return false;
  const std::string target = command.target().to_string();
  bool* failed = target == "autopilot"      ? &afcs_failures_.autopilot
                 : target == "autothrottle" ? &afcs_failures_.autothrottle
                                            : nullptr;
  if (failed == nullptr) return false;
  if (!setup_.autopilot) throw std::invalid_argument(target + ": this flight federate hosts no autopilot (--autopilot)");
  *failed = command.failure().active();
  log().info("command seq={} from={}: {} {}", command.sequence_number(), command.issuer().to_string(), target,
             *failed ? "failed" : "restored");
  return true;
}

void FlightComponent::take_pilot_controls(const runtime::FrameContext& frame) {
  screen_.frame_started(frame.frame);
  report_screened_controls(frame);
  watch_controls_writers(frame);
  const msg::PilotControls* pilot = pilot_controls_.latest();
  bool accepted = false;
  if (pilot && pilot_controls_.updates() != controls_seen_) {
    controls_seen_ = pilot_controls_.updates();
    const bool ours = pilot->aircraft_id() == setup_.aircraft_id;
    const bool invalid = ours && (pilot->discretes() & msg::DISCRETE_INPUTS_INVALID) != 0;
    if (ours && invalid != pilot_inputs_invalid_) {
      pilot_inputs_invalid_ = invalid;
      if (invalid) {
        report_fault("pilot_inputs_invalid", "frame " + std::to_string(frame.frame) +
                                                 ": the I/O federate has lost its input device (pilot_controls of frame " +
                                                 std::to_string(pilot->stamp().frame()) +
                                                 " marked invalid): holding the last valid controls");
      } else {
        log().info("frame {}: pilot inputs valid again: taking them", frame.frame);
      }
    }
    if (invalid) {
      accepted = true;  // the writer is alive: the device is what is lost (reported above)
    } else if (const auto problem = gate_.offer(*pilot, frame.frame)) {
      report_fault(fault_kind(problem->kind), "frame " + std::to_string(frame.frame) +
                                                  ": pilot_controls of frame " +
                                                  std::to_string(pilot->stamp().frame()) + " refused: " +
                                                  problem->message + " (kept the last good input)");
    } else {
      accepted = true;
      controls_accepted_ = controls_seen_;
    }
  }
  switch (gate_.frame(frame.frame, accepted)) {
    case PilotInputGate::HoldEvent::kHoldStarted:
      log().warn("frame {}: no good pilot_controls sample for {} frames: flying the last good input, held",
                 frame.frame, gate_.quiet_frames());
      break;
    case PilotInputGate::HoldEvent::kHoldEnded:
      log().info("frame {}: pilot_controls flowing again ({} held frames so far)", frame.frame,
                 gate_.held_frames());
      break;
    case PilotInputGate::HoldEvent::kNone:
      break;
  }
}

void FlightComponent::report_screened_controls(const runtime::FrameContext& frame) {
  constexpr std::uint64_t kMostPerFrame = 1000;  // a flood is counted, not logged sample by sample
  const std::uint64_t other = screen_.other_aircraft();
  if (other != screened_other_) {
    const std::string message = "frame " + std::to_string(frame.frame) + ": pilot_controls for aircraft_id " +
                                std::to_string(screen_.last_other_aircraft_id()) + " ignored (this is aircraft " +
                                std::to_string(setup_.aircraft_id) + ")";
    for (std::uint64_t i = 0; i < std::min(other - screened_other_, kMostPerFrame); ++i) {
      report_fault(fault_kind(InputRejection::kOtherAircraft), message);
    }
    screened_other_ = other;
  }
  const std::uint64_t future = screen_.future_stamps();
  if (future != screened_future_) {
    const std::string message = "frame " + std::to_string(frame.frame) + ": pilot_controls stamped frame " +
                                std::to_string(screen_.last_future_stamp()) + " refused (more than " +
                                std::to_string(gate_.limits().max_stamp_age_frames) + " frames ahead)";
    for (std::uint64_t i = 0; i < std::min(future - screened_future_, kMostPerFrame); ++i) {
      report_fault(fault_kind(InputRejection::kBadStamp), message);
    }
    screened_future_ = future;
  }
}

void FlightComponent::watch_controls_writers(const runtime::FrameContext& frame) {
  const int writers = pilot_controls_.writers();
  switch (gate_.writers_matched(writers)) {
    case PilotInputGate::WriterEvent::kSecondWriter:
      // A warning, not a fault: a trainer taking the aircraft over (a stronger writer) is a
      // legitimate use; the count is in the stop summary.
      log().warn("frame {}: controls_second_writer: fedsim/pilot_controls has {} writers: only the "
                 "strongest (exclusive ownership) flies aircraft {}, the others are ignored",
                 frame.frame, writers, setup_.aircraft_id);
      break;
    case PilotInputGate::WriterEvent::kSingleWriterAgain:
      log().info("frame {}: fedsim/pilot_controls has one writer again", frame.frame);
      break;
    case PilotInputGate::WriterEvent::kNone:
      break;
  }
}

void FlightComponent::apply_pilot_controls(const runtime::FrameContext& frame) {
  // Every RUN frame: relative controls follow the trim base, which a reposition moves.
  if (const msg::PilotControls* good = gate_.last_good()) {
    setup_.model->set_controls(controls_from_message(*good, setup_.controls_mode, trim_base_));
    apply_wing_leveller_switch(frame);
  }
}

void FlightComponent::apply_wing_leveller_switch(const runtime::FrameContext& frame) {
  AircraftModel& model = *setup_.model;
  if (!model.pack().flight_controls.wing_leveller) return;
  const bool on = (gate_.last_good()->discretes() & msg::DISCRETE_WING_LEVELLER) != 0;
  if (on == model.wing_leveller_engaged()) return;
  model.set_wing_leveller_engaged(on);
  log().info("frame {}: wing leveller {}", frame.frame, on ? "engaged" : "disengaged");
}

void FlightComponent::take_mcp(const runtime::FrameContext& frame) {
  const msg::PilotControls* sample = pilot_controls_.latest();
  if (sample == nullptr || pilot_controls_.updates() == mcp_seen_) return;
  mcp_seen_ = pilot_controls_.updates();
  if (controls_accepted_ != mcp_seen_) return;  // refused by the gate (or marked invalid): not flown
  const msg::PilotControls& pilot = *sample;
  if ((pilot.discretes() & msg::DISCRETE_INPUTS_INVALID) != 0) return;  // not the pilot's panel
  if (const auto problem = check_mcp(pilot.mcp())) {
    report_fault("input_rejected", "frame " + std::to_string(frame.frame) + ": pilot_controls of frame " +
                                       std::to_string(pilot.stamp().frame()) + " " + *problem +
                                       " (kept the previous MCP; its presses are ignored)");
    return;
  }
  last_valid_mcp_ = pilot.mcp();
  have_valid_mcp_ = true;
  pending_presses_ |= mcp_presses_.presses(pilot.mcp());
}

void FlightComponent::take_pilot_forces(const runtime::FrameContext& frame) {
  const msg::PilotControls* sample = pilot_controls_.latest();
  if (sample == nullptr || pilot_controls_.updates() == forces_seen_) return;
  forces_seen_ = pilot_controls_.updates();
  if (controls_accepted_ != forces_seen_) return;  // refused by the gate (or marked invalid)
  const msg::PilotControls& pilot = *sample;
  const bool sensors = (pilot.discretes() & msg::DISCRETE_FORCE_SENSORS) != 0 &&
                       (pilot.discretes() & msg::DISCRETE_INPUTS_INVALID) == 0;
  if (sensors) {
    if (const auto problem = check_pilot_forces(pilot)) {
      report_fault("input_rejected", "frame " + std::to_string(frame.frame) + ": pilot_controls of frame " +
                                         std::to_string(pilot.stamp().frame()) + " " + *problem +
                                         " (kept the previous control-wheel steering input)");
      return;
    }
  }
  cws_ = cws_inputs(pilot, *setup_.autopilot);  // hands off without the sensors
}

afcs::AfcsIlsSignals FlightComponent::nav1_ils() const {
  const msg::NavigationState* nav = navigation_state_->latest();
  if (nav == nullptr || nav->aircraft_id() != setup_.aircraft_id) return {};
  return ils_signals_from_receiver(nav->nav()[0]);
}

void FlightComponent::log_transition(const afcs::ModeTransition& t) {
  ++transitions_;
  log().info("AFCS t={:.2f}s {}: {} -> {} ({})", t.time_s, afcs::to_string(t.channel),
             t.from.empty() ? "-" : t.from, t.to.empty() ? "-" : t.to, t.reason);
}

void FlightComponent::fly_autopilot(const runtime::FrameContext& frame) {
  if (!afcs_ || std::abs(afcs_dt_s_ - frame.dt_s) > 1e-9) {
    if (afcs_) log().warn("frame period changed from {} s to {} s: the AFCS restarts", afcs_dt_s_, frame.dt_s);
    afcs_ = std::make_unique<afcs::Afcs>(*setup_.autopilot, frame.dt_s,
                                         [this](const afcs::ModeTransition& t) { log_transition(t); });
    afcs_dt_s_ = frame.dt_s;
  }
  AircraftModel& model = *setup_.model;
  const AircraftOutputs& o = model.outputs();
  const AircraftControls pilot = model.controls();
  afcs::AfcsInputs in;
  in.aircraft = afcs::afcs_aircraft_state(o, model.pack(), gear_, pilot);
  in.ils = nav1_ils();
  in.buttons = pending_presses_;
  pending_presses_ = {};
  in.mcp = have_valid_mcp_ ? mcp_selections(last_valid_mcp_) : mcp_before_first_sample(in.aircraft);
  in.mcp.pilot_pitch_input = cws_.pitch;  // control-wheel steering: the pilot's forces
  in.mcp.pilot_roll_input = cws_.roll;
  in.failures = afcs_failures_;
  const afcs::AfcsOutputs& out = afcs_->step(in);
  model.set_controls(afcs::apply_afcs_outputs(out, pilot, o.pitch_trim_norm));
  // Trim switches are momentary: where the auto-trim leaves the trim, the pilot finds it.
  if (out.autopilot_engaged) trim_base_.elevator_trim = o.pitch_trim_norm;
  // The autothrottle back-drives the thrust levers (as a 737's servos do): relative controls
  // fly about where it left them, so its disconnect after a retard leaves the levers at idle.
  // Absolute controls take the I/O federate's levers again (a control loader would back-drive
  // those).
  if (out.autothrottle_engaged) trim_base_.set_throttle(out.throttle);
}

bool FlightComponent::follow_replay(const runtime::FrameContext& frame) {
  std::string problem;
  const auto event = playback_.update(replay_state_.updates(), replay_state_.latest(), problem);
  if (!problem.empty()) {
    report_fault("input_rejected", "fedsim/replay_state: " + problem + " is not finite or out of range (sample not flown)");
  }
  if (event == ReplayPlayback::Event::kStarted) {
    log().info("replay: the aircraft state follows fedsim/replay_state (frame {})", frame.frame);
  } else if (event == ReplayPlayback::Event::kEnded) {
    // Take control from here: the model flies on from the last replayed state.
    setup_.model->set_state(state_from_replay(playback_.last()));
    log().info("replay ended after {} samples: taking control at {:.6f} {:.6f} deg, {:.0f} m (frame {})",
               playback_.samples(), playback_.last().latitude_rad() * 180.0 / M_PI,
               playback_.last().longitude_rad() * 180.0 / M_PI, playback_.last().altitude_msl_m(), frame.frame);
  }
  return playback_.active();
}

void FlightComponent::step(const runtime::FrameContext& frame) {
  AircraftModel& model = *setup_.model;
  if (follow_replay(frame)) {
    write_state(frame);
    return;
  }
  if (frame.resetting()) {
    model.reset(setup_.start.initial, setup_.start.controls);
    trim_base_ = setup_.start.controls;
    dropped_steps_seen_ = 0;
    if (afcs_) afcs_->reset();
    pending_presses_ = {};
    cws_ = {};
    fill_applied_controls(model.controls(), gate_.last_good(), applied_);
  } else if (frame.running()) {
    take_pilot_controls(frame);
    apply_pilot_controls(frame);
    if (setup_.autopilot) {
      take_mcp(frame);
      take_pilot_forces(frame);
      fly_autopilot(frame);
    }
    fill_applied_controls(model.controls(), gate_.last_good(), applied_);  // what this step flies
    model.step(frame.dt_s);
    const std::uint64_t dropped = model.outputs().dropped_steps;
    if (dropped != dropped_steps_seen_) {
      report_fault("numerical", "frame " + std::to_string(frame.frame) + ": the model dropped " +
                                    std::to_string(dropped - dropped_steps_seen_) +
                                    " integration step(s) that gave a non-finite state");
      dropped_steps_seen_ = dropped;
    }
  } else {
    take_pilot_controls(frame);  // frozen: checked and counted, flown from the next RUN frame
    if (setup_.autopilot) take_mcp(frame);  // its presses wait for the next RUN frame
    fill_applied_controls(model.controls(), gate_.last_good(), applied_);
  }
  write_state(frame);
}

void FlightComponent::on_stop() {
  log().info("pilot_controls: {} samples flown, {} refused (other aircraft {}, not finite {}, out of range {}, "
             "bad stamp {}), {} frames held, second writer seen {} times",
             gate_.accepted(), gate_.rejected_total() + screen_.other_aircraft() + screen_.future_stamps(),
             gate_.rejected(InputRejection::kOtherAircraft) + screen_.other_aircraft(),
             gate_.rejected(InputRejection::kNotFinite), gate_.rejected(InputRejection::kOutOfRange),
             gate_.rejected(InputRejection::kBadStamp) + screen_.future_stamps(), gate_.held_frames(),
             gate_.second_writer_events());
}

std::string FlightComponent::progress_note() const {
  afcs::ApproachAircraft aircraft;
  aircraft.lat_rad = state_.latitude_rad();
  aircraft.lon_rad = state_.longitude_rad();
  aircraft.height_agl_m = state_.height_agl_m();
  aircraft.cas_mps = state_.air().cas_mps();
  aircraft.ground_speed_mps = state_.ground_speed_mps();
  aircraft.on_ground = state_.on_ground();
  const afcs::ModeState modes = afcs_ ? afcs_->modes() : afcs::ModeState{};
  return afcs::approach_progress_line(modes, aircraft,
                                      setup_.progress_runway ? &*setup_.progress_runway : nullptr);
}

void FlightComponent::write_state(const runtime::FrameContext& frame) {
  if (playback_.active()) {
    state_ = playback_.last();  // the replay, as this aircraft's state of this frame
    state_.aircraft_id(static_cast<std::uint16_t>(setup_.aircraft_id));
  } else {
    fill_aircraft_state(setup_.model->outputs(), setup_.model->controls(), state_);
  }
  state_.stamp(frame.end_stamp());  // the state after this frame's step
  aircraft_state_.write(state_);
  applied_.stamp(frame.stamp());  // the controls this frame's step flew
  applied_controls_.write(applied_);
  const auto& engines = setup_.model->outputs().engines;
  for (std::size_t i = 0; i < engines.size(); ++i) {
    fill_engine_state(engines[i], i, engine_);
    engine_.stamp(frame.end_stamp());
    engine_state_.write(engine_);
  }
  if (autopilot_state_ != nullptr) {
    if (afcs_) fill_autopilot_state(*afcs_, transitions_, autopilot_sample_);
    autopilot_sample_.stamp(frame.end_stamp());
    autopilot_state_->write(autopilot_sample_);
  }
}

}  // namespace fedsim::flight
