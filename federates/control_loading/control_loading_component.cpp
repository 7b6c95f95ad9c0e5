#include "control_loading/control_loading_component.hpp"
#include "common/aircraft_pack/pack_facts.hpp"
#include "common/aircraft_pack/pack_path.hpp"

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fedsim::control_loading {
namespace {

msg::ControlLoadingStatus to_message(LoaderStatus s) {
  switch (s) {
    case LoaderStatus::kSafe: return msg::CONTROL_LOADING_SAFE;
    case LoaderStatus::kFadingIn: return msg::CONTROL_LOADING_FADING_IN;
    case LoaderStatus::kActive: return msg::CONTROL_LOADING_ACTIVE;
  }
  return msg::CONTROL_LOADING_SAFE;
}

void fill_axis(const AxisOutputs& a, msg::ControlAxis& m) {
  m.position(a.position_norm);
  m.velocity_ps(a.velocity_norm_ps);
  m.force_n(a.feel_force_n);
  m.trim_position(a.trim_norm);
}

bool finite(double v) { return std::isfinite(v); }

}  // namespace

double scheduled_shaker_alpha_rad(const ControlLoadingSetup& setup, double flap_norm) {
  const auto& x = setup.shaker_flap_norm;
  const auto& y = setup.shaker_alpha_rad;
  if (x.empty() || x.size() != y.size()) return std::numeric_limits<double>::quiet_NaN();
  const double f = std::isfinite(flap_norm) ? std::clamp(flap_norm, x.front(), x.back()) : x.front();
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (f <= x[i]) return y[i - 1] + (y[i] - y[i - 1]) * (f - x[i - 1]) / (x[i] - x[i - 1]);
  }
  return y.back();
}

void schedule_shaker_from_pack(const std::string& pack_path, ControlLoadingSetup& setup) {
  const aircraft_pack::PackFacts facts = aircraft_pack::load_pack_facts(pack_path);
  const aircraft_pack::StallWarningSpec& schedule = aircraft_pack::stall_warning_of(facts);
  setup.shaker_flap_norm = schedule.flap_norm;
  setup.shaker_alpha_rad = schedule.alpha_rad;
}

std::optional<std::string> inputs_from_messages(const msg::AircraftState& aircraft, double now_s,
                                                const msg::PilotControls* pilot,
                                                const msg::AutopilotState* autopilot, ControlLoadingInputs& out) {
  if (!finite(aircraft.air().qbar_pa())) return std::string("aircraft_state air.qbar_pa not finite");
  if (!finite(aircraft.air().alpha_rad())) return std::string("aircraft_state air.alpha_rad not finite");
  ControlLoadingInputs in = out;
  in.qbar_pa = aircraft.air().qbar_pa();
  // Air/ground logic: the stall warning is inhibited with weight on the wheels (a stopped
  // aircraft's angle of attack is meaningless), as a transport's stall-warning computer does.
  in.alpha_rad = aircraft.weight_on_wheels() ? 0.0 : aircraft.air().alpha_rad();
  in.flight_data_age_s = std::max(0.0, now_s - aircraft.stamp().sim_time_s());
  if (pilot != nullptr) {
    const double targets[kAxisCount] = {pilot->elevator(), pilot->aileron(), pilot->rudder()};
    const double trims[kAxisCount] = {pilot->elevator_trim(), pilot->aileron_trim(), pilot->rudder_trim()};
    for (int i = 0; i < kAxisCount; ++i) {
      if (!finite(targets[i]) || !finite(trims[i])) return std::string("pilot_controls primaries or trims not finite");
      in.axes[i].pilot_target_norm = std::clamp(targets[i], -1.0, 1.0);
      in.axes[i].trim_norm = std::clamp(trims[i], -1.0, 1.0);
    }
  }
  for (auto& a : in.axes) a.backdrive_active = false;
  in.pilot_source = PilotSource::kSimulatedPilot;
  const bool sensors = pilot != nullptr && (pilot->discretes() & msg::DISCRETE_FORCE_SENSORS) != 0;
  if (sensors) {
    // The loop with the I/O federate: the pilot's hands are the force sensors' readings (the
    // model checks their range), whoever else drives the controls.
    in.pilot_source = PilotSource::kForceSensor;
    for (int i = 0; i < kAxisCount; ++i) {
      const double f = pilot->pilot_force_n()[static_cast<std::size_t>(i)];
      if (!finite(f)) return std::string("pilot_controls pilot_force_n not finite");
      in.axes[i].pilot_force_n = f;
    }
  } else if (autopilot != nullptr && (autopilot->fma().autopilot_engaged() || autopilot->rollout_engaged())) {
    // While the autopilot flies, the pilot is hands and feet off (no force on any control): the
    // back-driven controls follow the servo, the others rest at their trim datum.
    in.pilot_source = PilotSource::kForceSensor;
    for (auto& a : in.axes) a.pilot_force_n = 0.0;
  }
  if (autopilot != nullptr) {
    const double commands[kAxisCount] = {autopilot->elevator(), autopilot->aileron(), autopilot->rudder()};
    const bool driven[kAxisCount] = {autopilot->fma().autopilot_engaged(), autopilot->fma().autopilot_engaged(),
                                     autopilot->rollout_engaged()};
    for (int i = 0; i < kAxisCount; ++i) {
      if (!driven[i]) continue;
      if (!finite(commands[i])) return std::string("autopilot_state commands not finite");
      in.axes[i].backdrive_active = true;
      in.axes[i].backdrive_target_norm = std::clamp(commands[i], -1.0, 1.0);
    }
  }
  out = in;
  return std::nullopt;
}

void to_message(const ControlLoadingOutputs& out, const ControlLoadingInputs& in, const std::string& reason,
                msg::ControlLoadingState& m) {
  m.status(to_message(out.status));
  fill_axis(out.axes[static_cast<int>(Axis::kPitch)], m.pitch());
  fill_axis(out.axes[static_cast<int>(Axis::kRoll)], m.roll());
  fill_axis(out.axes[static_cast<int>(Axis::kYaw)], m.yaw());
  m.stick_shaker(out.stick_shaker);
  m.pitch_backdriven(in.axes[static_cast<int>(Axis::kPitch)].backdrive_active);
  m.roll_backdriven(in.axes[static_cast<int>(Axis::kRoll)].backdrive_active);
  m.yaw_backdriven(in.axes[static_cast<int>(Axis::kYaw)].backdrive_active);
  m.cut_off_reason(out.status == LoaderStatus::kSafe ? reason.substr(0, 96) : std::string());
}

ControlLoadingComponent::ControlLoadingComponent(std::string name, ControlLoadingSetup setup)
    : Component(std::move(name)),
      aircraft_state_(reads(runtime::topics::aircraft_state)),
      pilot_controls_(reads(runtime::topics::pilot_controls)),
      autopilot_state_(monitors(runtime::topics::autopilot_state)),
      control_loading_state_(writes(runtime::topics::control_loading_state, setup.state_qos)),
      setup_(std::move(setup)),
      loader_(setup_.parameters),
      engage_wanted_(setup_.engage_on_start) {
  if (setup_.shaker_flap_norm.empty()) {
    log().info("stick shaker at {:.3f} rad (no --aircraft: the loader's fixed angle)", setup_.parameters.shaker_alpha_rad);
    return;
  }
  std::string schedule;
  for (std::size_t i = 0; i < setup_.shaker_flap_norm.size(); ++i) {
    char item[48];
    std::snprintf(item, sizeof item, "%s%.2f: %.3f", i ? ", " : "", setup_.shaker_flap_norm[i], setup_.shaker_alpha_rad[i]);
    schedule += item;
  }
  log().info("stick shaker from the pack's stall-warning angles (flaps: alpha rad) {}", schedule);
}

void ControlLoadingComponent::on_command(const msg::SimCommand& command) {
  if (command.kind() != msg::COMMAND_FAILURE || command.target().to_string() != "control_loading") return;
  instructor_cut_ = command.failure().active();
  if (instructor_cut_) {
    loader_.cut_off("instructor cut-off");
    log().warn("command seq={}: control loading cut off by the instructor", command.sequence_number());
  } else {
    engage_wanted_ = true;
    log().info("command seq={}: control loading restored", command.sequence_number());
  }
}

void ControlLoadingComponent::take_inputs(const runtime::FrameContext& frame) {
  const msg::AircraftState* aircraft = aircraft_state_.latest();
  if (aircraft == nullptr) return;
  const bool fresh = aircraft_state_.updates() != aircraft_seen_;
  aircraft_seen_ = aircraft_state_.updates();
  if (!fresh && have_inputs_) {
    // No new state: the same flight data, older by now (the model's watchdog judges its age).
    inputs_.flight_data_age_s = std::max(0.0, frame.sim_time_s - aircraft->stamp().sim_time_s());
    return;
  }
  // The autopilot's commands count while they keep coming (its writer may stop or leave).
  if (autopilot_state_.updates() != autopilot_seen_) {
    autopilot_seen_ = autopilot_state_.updates();
    autopilot_stale_frames_ = 0;
  } else if (autopilot_stale_frames_ < kAutopilotStaleFrames) {
    ++autopilot_stale_frames_;
  }
  const msg::AutopilotState* autopilot =
      autopilot_stale_frames_ < kAutopilotStaleFrames ? autopilot_state_.latest() : nullptr;
  if (const auto problem = inputs_from_messages(*aircraft, frame.sim_time_s, pilot_controls_.latest(),
                                                autopilot, inputs_)) {
    report_fault("input_rejected", "frame " + std::to_string(frame.frame) + ": " + *problem +
                                       " (control loading cut off)");
    loader_.cut_off(*problem);
    return;
  }
  inputs_.shaker_alpha_rad = scheduled_shaker_alpha_rad(setup_, aircraft->flap_norm());
  have_inputs_ = true;
}

void ControlLoadingComponent::report_status_change(const runtime::FrameContext& frame) {
  const LoaderStatus now = loader_.status();
  if (now == last_status_) return;
  if (now == LoaderStatus::kSafe) {
    report_fault("control_loading_cut_off", "frame " + std::to_string(frame.frame) + ": " + loader_.cut_off_reason());
  }
  log().info("control loading t={:.2f}s {} -> {}{}", frame.sim_time_s, to_string(last_status_), to_string(now),
             now == LoaderStatus::kSafe ? " (" + loader_.cut_off_reason() + ")" : std::string());
  last_status_ = now;
}

void ControlLoadingComponent::on_ticks_stopped(const runtime::FrameContext& last, double silent_s) {
  const double silent_periods = last.frame_period_s > 0.0 ? silent_s / last.frame_period_s : 1e9;
  // A late tick: hold the forces and wait for it (tick_gap_watch.hpp).
  if (tick_gaps_.on_silence(silent_periods) != timing::TickGapWatch::Verdict::kStopped) return;
  if (loader_.status() == LoaderStatus::kSafe) return;
  char why[96];
  std::snprintf(why, sizeof why, "no frame tick for %.0f ms after frame %llu", silent_s * 1000.0,
                static_cast<unsigned long long>(last.frame));
  loader_.cut_off(why);
  report_status_change(last);
  // The SAFE state goes out now: the loader's own readers (a hardware driver) must not wait for
  // a frame that is not coming.
  to_message(loader_.outputs(), inputs_, loader_.cut_off_reason(), sample_);
  sample_.stamp(last.end_stamp());
  control_loading_state_.write(sample_);
}

void ControlLoadingComponent::step(const runtime::FrameContext& frame) {
  const auto tick = tick_gaps_.on_tick(frame.frame);
  if (tick != timing::TickGapWatch::Verdict::kOnTime) {
    log().warn("frame={} late tick: none for {:.0f} ms before it, {} ({} late so far)", frame.frame,
               tick_gaps_.last_gap_periods() * frame.frame_period_s * 1000.0,
               tick == timing::TickGapWatch::Verdict::kBurst ? "too many: cut off" : "ridden through",
               tick_gaps_.late_ticks());
  }
  if (tick == timing::TickGapWatch::Verdict::kBurst && loader_.status() != LoaderStatus::kSafe) {
    loader_.cut_off(std::to_string(tick_gaps_.limits().burst_late_ticks) + " late frame ticks within " +
                    std::to_string(tick_gaps_.limits().burst_window_frames) + " frames");
  }
  take_inputs(frame);
  if (engage_wanted_ && have_inputs_ && !instructor_cut_ && loader_.status() == LoaderStatus::kSafe) {
    loader_.engage();
    engage_wanted_ = false;
  }
  // The controls live in the cockpit's time, not the aircraft's: the loader steps in FREEZE too
  // (the flight data then stays fresh: the aircraft state keeps arriving, frozen).
  loader_.step(inputs_, frame.dt_s);
  report_status_change(frame);
  to_message(loader_.outputs(), inputs_, loader_.cut_off_reason(), sample_);
  sample_.stamp(frame.end_stamp());
  control_loading_state_.write(sample_);
}

runtime::FederateProgram program() {
  struct Options {
    std::string engage = "on";
    std::string aircraft;
    std::string state_qos;
  };
  auto o = std::make_shared<Options>();
  runtime::FederateProgram p;
  p.program = "fedsim-control-loading";
  p.default_name = "control_loading";
  p.description = "control loading: force feel of the column, wheel and pedals, stick shaker, autopilot back-drive";
  p.add_options = [o](CLI::App& app) {
    app.add_option("--engage", o->engage, "fade the forces in once the aircraft state arrives")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    app.add_option("--aircraft", o->aircraft,
                   "aircraft pack (file or name in data/aircraft): the stick shaker at its stall-warning angle "
                   "(1.05 V_s) for the flap setting; default: a fixed 0.24 rad");
    app.add_option("--state-qos", o->state_qos,
                   "QoS profile of fedsim/control_loading_state (default: the catalogue's; lockstep_data to record every frame)");
  };
  p.make_component = [o](const runtime::FederateOptions& common) {
    ControlLoadingSetup setup;
    setup.engage_on_start = o->engage == "on";
    setup.state_qos = o->state_qos;
    if (!o->aircraft.empty()) schedule_shaker_from_pack(aircraft_pack::resolve_pack_path(o->aircraft), setup);
    return std::unique_ptr<runtime::Component>(
        std::make_unique<ControlLoadingComponent>(common.name, std::move(setup)));
  };
  return p;
}

}  // namespace fedsim::control_loading
