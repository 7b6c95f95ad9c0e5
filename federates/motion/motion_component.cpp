#include "motion/motion_component.hpp"

#include <cstdio>

#include "common/util/cli_checks.hpp"
#include "motion/model/motion_parameter_file.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::motion {
namespace {

bool finite3(const std::array<double, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

msg::MotionStatus to_message(MotionStatus s) {
  switch (s) {
    case MotionStatus::kParked: return msg::MOTION_PARKED;
    case MotionStatus::kEngaging: return msg::MOTION_ENGAGING;
    case MotionStatus::kEngaged: return msg::MOTION_ENGAGED;
    case MotionStatus::kParking: return msg::MOTION_PARKING;
    case MotionStatus::kFault: return msg::MOTION_FAULT;
  }
  return msg::MOTION_FAULT;
}

}  // namespace

std::optional<std::string> inputs_from_message(const msg::AircraftState& s, MotionInputs& out) {
  if (!finite3(s.specific_force_eye_body_mps2())) return std::string("specific_force_eye_body_mps2 not finite");
  if (!finite3(s.omega_body_radps())) return std::string("omega_body_radps not finite");
  for (int i = 0; i < 3; ++i) {
    out.specific_force_eye_body_mps2[i] = s.specific_force_eye_body_mps2()[i];
    out.omega_body_radps[i] = s.omega_body_radps()[i];
  }
  return std::nullopt;
}

void to_message(const MotionPlatformOutputs& out, const std::string& fault_reason, msg::MotionPlatformState& m) {
  m.status(to_message(out.status));
  for (int i = 0; i < 3; ++i) {
    m.position_m()[i] = out.pose.position_i_m[i];
    m.specific_force_cmd_mps2()[i] = out.specific_force_demand_mps2[i];
    m.specific_force_cue_mps2()[i] = out.specific_force_cue_p_mps2[i];
  }
  m.attitude_rad()[0] = out.pose.attitude.phi_rad;
  m.attitude_rad()[1] = out.pose.attitude.theta_rad;
  m.attitude_rad()[2] = out.pose.attitude.psi_rad;
  for (int k = 0; k < kJackCount; ++k) {
    m.jack_length_m()[k] = out.jack_length_m[k];
    m.jack_velocity_mps()[k] = out.jack_velocity_mps[k];
    m.jack_command_m()[k] = out.jack_command_m[k];
  }
  m.workspace_limited(out.workspace_limited);
  m.fault_reason(out.status == MotionStatus::kFault ? fault_reason.substr(0, 96) : std::string());
}

MotionComponent::MotionComponent(std::string name, MotionSetup setup)
    : Component(std::move(name)),
      aircraft_state_(reads(runtime::topics::aircraft_state)),
      motion_state_(writes(runtime::topics::motion_state, setup.state_qos)),
      setup_(std::move(setup)),
      engage_wanted_(setup_.engage_on_start) {
  if (setup_.silent_frames_limit < 1) throw std::invalid_argument("silent_frames_limit must be >= 1");
}

void MotionComponent::on_command(const msg::SimCommand& command) {
  if (command.kind() != msg::COMMAND_FAILURE || command.target().to_string() != "motion") return;
  if (command.failure().active()) {
    instructor_cut_ = true;
    restore_requested_ = false;
    log().warn("command seq={}: motion cut off by the instructor", command.sequence_number());
  } else {
    instructor_cut_ = false;
    restore_requested_ = true;
    log().info("command seq={}: motion restored (engages once the platform is down)", command.sequence_number());
  }
}

void MotionComponent::take_aircraft_state(const runtime::FrameContext& frame) {
  const msg::AircraftState* state = aircraft_state_.latest();
  if (!state || aircraft_state_.updates() == updates_seen_) {
    // Silence counts only while the platform moves with the aircraft.
    if (have_inputs_ && platform_->status() == MotionStatus::kEngaged && ++silent_frames_ >= setup_.silent_frames_limit) {
      const std::string why = "aircraft_state silent for " + std::to_string(silent_frames_) + " frames";
      report_fault("input_silent", "frame " + std::to_string(frame.frame) + ": " + why + " (motion cut off)");
      platform_->trip(why);
    }
    return;
  }
  updates_seen_ = aircraft_state_.updates();
  silent_frames_ = 0;
  MotionInputs candidate;
  if (const auto problem = inputs_from_message(*state, candidate)) {
    report_fault("input_rejected", "frame " + std::to_string(frame.frame) + ": aircraft_state of frame " +
                                       std::to_string(state->stamp().frame()) + " " + *problem + " (motion cut off)");
    platform_->trip("aircraft_state " + *problem);
    return;
  }
  inputs_ = candidate;
  have_inputs_ = true;
}

void MotionComponent::apply_instructor() {
  if (instructor_cut_ && platform_->status() != MotionStatus::kFault) platform_->trip("instructor cut-off");
  if (restore_requested_ && platform_->status() == MotionStatus::kFault) {
    if (platform_->clear_fault()) {  // only once the platform is down and settled
      restore_requested_ = false;
      engage_wanted_ = true;
    }
  } else if (restore_requested_) {
    restore_requested_ = false;
    engage_wanted_ = true;
  }
  if (engage_wanted_ && have_inputs_ && platform_->status() == MotionStatus::kParked) {
    platform_->engage();
    engage_wanted_ = false;
  }
}

void MotionComponent::report_status_change(const runtime::FrameContext& frame) {
  const MotionStatus now = platform_->status();
  if (now == last_status_) return;
  if (now == MotionStatus::kFault) {
    report_fault("motion_fault", "frame " + std::to_string(frame.frame) + ": " + platform_->fault_reason());
  }
  log().info("motion t={:.2f}s {} -> {}{}", frame.sim_time_s, motion::to_string(last_status_), motion::to_string(now),
             now == MotionStatus::kFault ? " (" + platform_->fault_reason() + ")" : std::string());
  last_status_ = now;
}

void MotionComponent::on_ticks_stopped(const runtime::FrameContext& last, double silent_s) {
  if (!platform_) return;
  const double silent_periods = last.frame_period_s > 0.0 ? silent_s / last.frame_period_s : 1e9;
  // A late tick: hold the last command (the jacks' servos do) and wait for it (tick_gap_watch.hpp).
  if (tick_gaps_.on_silence(silent_periods) != timing::TickGapWatch::Verdict::kStopped) return;
  if (platform_->status() != MotionStatus::kFault && platform_->status() != MotionStatus::kParked) {
    char why[96];
    std::snprintf(why, sizeof why, "no frame tick for %.0f ms after frame %llu", silent_s * 1000.0,
                  static_cast<unsigned long long>(last.frame));
    platform_->trip(why);
  }
  // The park goes on at the frame period, as many steps as the silence has lasted: the last
  // frame's inputs are held (the washout's demand is ignored in a fault; the park path rules).
  const auto due = static_cast<std::uint64_t>(silent_s / platform_dt_s_);
  while (park_steps_without_ticks_ < due) {
    ++park_steps_without_ticks_;
    platform_->step(inputs_);
    report_status_change(last);  // (simulation time does not advance without ticks)
    to_message(platform_->outputs(), platform_->fault_reason(), sample_);
    sample_.stamp(last.end_stamp());
    motion_state_.write(sample_);
  }
}

void MotionComponent::step(const runtime::FrameContext& frame) {
  park_steps_without_ticks_ = 0;
  const auto tick = tick_gaps_.on_tick(frame.frame);
  if (!platform_ || std::abs(platform_dt_s_ - frame.dt_s) > 1e-9) {
    // Built at the federation's frame period: the washout's filters and the actuator sub-steps
    // depend on it (validate() names the field a period makes invalid).
    platform_ = std::make_unique<MotionPlatform>(setup_.parameters, frame.dt_s);
    platform_dt_s_ = frame.dt_s;
    last_status_ = platform_->status();
  }
  take_aircraft_state(frame);
  apply_instructor();
  if (tick != timing::TickGapWatch::Verdict::kOnTime) {
    log().warn("frame={} late tick: none for {:.0f} ms before it, {} ({} late so far)", frame.frame,
               tick_gaps_.last_gap_periods() * frame.frame_period_s * 1000.0,
               tick == timing::TickGapWatch::Verdict::kBurst ? "too many: cut off" : "ridden through",
               tick_gaps_.late_ticks());
  }
  if (tick == timing::TickGapWatch::Verdict::kBurst && platform_->status() != MotionStatus::kFault &&
      platform_->status() != MotionStatus::kParked) {
    platform_->trip(std::to_string(tick_gaps_.limits().burst_late_ticks) + " late frame ticks within " +
                    std::to_string(tick_gaps_.limits().burst_window_frames) + " frames");
  }
  platform_->step(inputs_);  // a fault parks on its own path; before any input: 1 g at rest
  report_status_change(frame);
  to_message(platform_->outputs(), platform_->fault_reason(), sample_);
  sample_.stamp(frame.end_stamp());
  motion_state_.write(sample_);
}

runtime::FederateProgram program() {
  struct Options {
    std::string parameters;
    std::string engage = "on";
    std::string state_qos;
  };
  auto o = std::make_shared<Options>();
  runtime::FederateProgram p;
  p.program = "fedsim-motion";
  p.default_name = "motion";
  p.description = "motion platform: classical washout and a 6-6 Stewart platform cueing the aircraft state";
  p.add_options = [o](CLI::App& app) {
    app.add_option("--parameters", o->parameters,
                   "washout and platform parameters (YAML, data/motion/README.md; default: the built-in tuning)");
    app.add_option("--engage", o->engage, "rise to neutral and cue once the aircraft state arrives")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    app.add_option("--state-qos", o->state_qos,
                   "QoS profile of fedsim/motion_state (default: the catalogue's; lockstep_data to record every frame)");
  };
  p.make_component = [o](const runtime::FederateOptions& common) {
    MotionSetup setup;
    // Checked at 50 Hz here (a clear error before joining); checked again at the real period.
    if (!o->parameters.empty()) setup.parameters = load_motion_parameters(o->parameters, 0.02);
    setup.engage_on_start = o->engage == "on";
    setup.state_qos = o->state_qos;
    // The common --silent-frames (the host's silent-writer check) sets the cut-off too; the
    // motion never goes without one (0 there: the default 10 here).
    setup.silent_frames_limit =
        common.silent_frames == 0 ? 10 : static_cast<int>(std::min<std::uint64_t>(common.silent_frames, 1000));
    return std::unique_ptr<runtime::Component>(std::make_unique<MotionComponent>(common.name, std::move(setup)));
  };
  return p;
}

}  // namespace fedsim::motion
