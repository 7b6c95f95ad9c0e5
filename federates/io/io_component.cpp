#include "io/io_component.hpp"

#include "io/model/stall_entry_pilot.hpp"
#include "common/util/cli_checks.hpp"

#include "io/devices/device_source.hpp"
#include "io/devices/evdev_device.hpp"
#include "io/model/adc_emulation.hpp"
#include "io/model/input_profile.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::io {

std::uint32_t vhf_channel_khz(double frequency_mhz) {
  // VOR/ILS channels are 50 kHz apart (ICAO Annex 10 Vol V 4.2): a dialled value snaps to one.
  return static_cast<std::uint32_t>(std::lround(frequency_mhz * 1000.0 / 50.0)) * 50u;
}

namespace {
static_assert(kMcpButtonCount == msg::MCP_BUTTON_COUNT);
static_assert(static_cast<int>(Channel::kMcpApp) - static_cast<int>(Channel::kMcpCmd) == msg::MCP_APP);
static_assert(static_cast<int>(Channel::kToga) - static_cast<int>(Channel::kMcpCmd) == msg::MCP_TOGA);

void fill_mcp(const ControlInputs& in, const McpButtonCounter& buttons, msg::McpPanel& mcp) {
  for (int i = 0; i < kMcpButtonCount; ++i) {
    mcp.presses()[static_cast<std::size_t>(i)] = buttons.presses()[static_cast<std::size_t>(i)];
  }
  mcp.heading_true_rad(in[Channel::kMcpHeadingDeg] * units::kDegToRad);
  mcp.altitude_msl_m(in[Channel::kMcpAltitudeFt] * units::kFtToM);
  mcp.vertical_speed_mps(in[Channel::kMcpVerticalSpeedFpm] * units::kFtToM / 60.0);
  mcp.airspeed_cas_mps(in[Channel::kMcpSpeedKt] * units::kKtToMps);
  mcp.bank_limit_rad(in[Channel::kMcpBankLimitDeg] * units::kDegToRad);
  mcp.flight_director_on(in[Channel::kFlightDirector] >= 0.5);
  mcp.autothrottle_armed(in[Channel::kAutothrottleArm] >= 0.5);
  mcp.autobrake(static_cast<std::uint16_t>(std::lround(in[Channel::kAutobrake])));
}
}  // namespace

void to_message(const ControlInputs& in, const McpButtonCounter& buttons, msg::PilotControls& out) {
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
  auto& radios = out.radios();
  radios.nav1_khz(vhf_channel_khz(in[Channel::kNav1Mhz]));
  radios.nav2_khz(vhf_channel_khz(in[Channel::kNav2Mhz]));
  radios.adf_khz(static_cast<std::uint32_t>(std::lround(in[Channel::kAdfKhz])));
  radios.obs1_rad(static_cast<float>(in[Channel::kObs1Deg] * units::kDegToRad));
  radios.obs2_rad(static_cast<float>(in[Channel::kObs2Deg] * units::kDegToRad));
  fill_mcp(in, buttons, out.mcp());
  std::uint32_t discretes = out.discretes() & ~(msg::DISCRETE_AUTOPILOT_DISCONNECT | msg::DISCRETE_TOGA |
                                                 msg::DISCRETE_WING_LEVELLER | msg::DISCRETE_INPUTS_INVALID |
                                                 msg::DISCRETE_FORCE_SENSORS);
  if (buttons.held(Channel::kApDisconnect)) discretes |= msg::DISCRETE_AUTOPILOT_DISCONNECT;
  if (buttons.held(Channel::kToga)) discretes |= msg::DISCRETE_TOGA;
  if (in[Channel::kWingLeveller] >= 0.5) discretes |= msg::DISCRETE_WING_LEVELLER;
  out.discretes(discretes);
  out.pilot_force_n()[0] = static_cast<float>(in[Channel::kColumnForceN]);
  out.pilot_force_n()[1] = static_cast<float>(in[Channel::kWheelForceN]);
  out.pilot_force_n()[2] = static_cast<float>(in[Channel::kPedalForceN]);
}

IoComponent::IoComponent(std::string name, std::unique_ptr<InputSource> source, int aircraft_id,
                         std::string_view controls_qos, bool loader_in_the_loop, const ControlInputs& initial)
    : Component(std::move(name)),
      pilot_controls_(writes(runtime::topics::pilot_controls, controls_qos)),
      source_(std::move(source)),
      controls_(initial) {
  if (loader_in_the_loop) control_loading_state_ = &reads(runtime::topics::control_loading_state);
  if (source_->closed_loop()) aircraft_state_ = &reads(runtime::topics::aircraft_state);
  sample_.aircraft_id(static_cast<uint16_t>(aircraft_id));
  log().info("input source: {}{}", source_->describe(),
             loader_in_the_loop ? "; the control loader in the loop (primaries from its positions)" : "");
}

void IoComponent::take_loader_positions() {
  sample_.discretes(sample_.discretes() | msg::DISCRETE_FORCE_SENSORS);
  const msg::ControlLoadingState* loader = control_loading_state_->latest();
  // Before the loader's first state the controls rest centred.
  const double pitch = loader ? loader->pitch().position() : 0.0;
  const double roll = loader ? loader->roll().position() : 0.0;
  const double yaw = loader ? loader->yaw().position() : 0.0;
  if (!std::isfinite(pitch) || !std::isfinite(roll) || !std::isfinite(yaw)) {
    report_fault("input_rejected", "control_loading_state positions not finite (kept the previous primaries)");
    return;
  }
  sample_.elevator(static_cast<float>(std::clamp(pitch, -1.0, 1.0)));
  sample_.aileron(static_cast<float>(std::clamp(roll, -1.0, 1.0)));
  sample_.rudder(static_cast<float>(std::clamp(yaw, -1.0, 1.0)));
}

void IoComponent::watch_validity(bool valid) {
  if (valid == source_valid_) return;
  source_valid_ = valid;
  if (!valid) {
    report_fault("input_device_lost", source_->describe() +
                                          ": pilot controls marked invalid; the flight federate holds the last valid ones");
  } else {
    log().info("input source back: {}", source_->describe());
  }
}

void IoComponent::show_the_pilot_the_aircraft() {
  const msg::AircraftState* s = aircraft_state_->latest();
  if (s == nullptr) return;  // before the flight federate's first state: nothing to fly by
  PilotObservation seen;
  seen.sim_time_s = s->stamp().sim_time_s();
  seen.cas_mps = s->air().cas_mps();
  seen.phi_rad = s->phi_rad();
  seen.theta_rad = s->theta_rad();
  seen.p_radps = s->omega_body_radps()[0];
  seen.q_radps = s->omega_body_radps()[1];
  seen.elevator = s->controls().elevator();
  seen.elevator_trim = s->controls().pitch_trim();
  for (double v : {seen.sim_time_s, seen.cas_mps, seen.phi_rad, seen.theta_rad, seen.p_radps, seen.q_radps,
                   seen.elevator, seen.elevator_trim}) {
    if (!std::isfinite(v)) {
      report_fault("input_rejected", "aircraft_state not finite: the test pilot holds the controls");
      return;
    }
  }
  source_->observe(seen);
}

void IoComponent::step(const runtime::FrameContext& frame) {
  if (aircraft_state_ != nullptr) show_the_pilot_the_aircraft();
  source_->sample(frame.sim_time_s, controls_);
  watch_validity(source_->valid());
  mcp_buttons_.update(controls_);
  const float held[3] = {sample_.elevator(), sample_.aileron(), sample_.rudder()};
  to_message(controls_, mcp_buttons_, sample_);
  if (control_loading_state_ != nullptr) {
    sample_.elevator(held[0]);  // until the loader's positions replace them
    sample_.aileron(held[1]);
    sample_.rudder(held[2]);
    take_loader_positions();
  }
  if (!source_valid_) sample_.discretes(sample_.discretes() | msg::DISCRETE_INPUTS_INVALID);
  sample_.stamp(frame.stamp());
  pilot_controls_.write(sample_);
}

std::unique_ptr<InputSource> make_input_source(const InputOptions& o) {
  if (o.profile.empty() && o.device.empty() && o.device_name.empty()) {
    throw std::invalid_argument("fedsim-io needs --profile, --device or --device-name");
  }
  if (!o.device.empty() && !o.device_name.empty()) {
    throw std::invalid_argument("--device and --device-name both name the device: give one");
  }
  const bool device = !o.device.empty() || !o.device_name.empty();
  if (device && o.calibration.empty()) {
    throw std::invalid_argument("--device/--device-name need --calibration FILE (fedsim io calibrate writes one)");
  }
  if (!device && !o.calibration.empty()) throw std::invalid_argument("--calibration needs --device or --device-name");
  std::vector<std::unique_ptr<InputSource>> layers;
  if (!o.profile.empty()) layers.push_back(std::make_unique<InputProfile>(InputProfile::load_file(o.profile)));
  if (device) {
    const std::string what = !o.device.empty() ? o.device : "named '" + o.device_name + "'";
    layers.push_back(std::make_unique<DeviceSource>(evdev_opener(o.device, o.device_name), what,
                                                    InceptorCalibration::load_file(o.calibration)));
  }
  std::unique_ptr<InputSource> source = layers.size() == 1 ? std::move(layers.front())
                                                           : std::make_unique<LayeredSource>(std::move(layers));
  if (!o.adc.empty()) source = std::make_unique<AdcSource>(std::move(source), AdcSpec::load_file(o.adc));
  return source;
}

runtime::FederateProgram program() {
  struct Options {
    InputOptions input;
    int aircraft_id = 0;
    std::string controls_qos;
    bool loader_in_the_loop = false;
  };
  auto o = std::make_shared<Options>();
  runtime::FederateProgram p;
  p.program = "fedsim-io";
  p.default_name = "io";
  p.description = "publishes pilot controls every frame from an input source";
  p.add_options = [o](CLI::App& app) {
    app.add_option("--profile", o->input.profile, "scripted input profile (CSV: time_s + channels)");
    app.add_option("--device", o->input.device, "input device, e.g. /dev/input/event5 (joystick, yoke, pedals)");
    app.add_option("--device-name", o->input.device_name,
                   "input device by its name (as `fedsim io calibrate --list` shows it)");
    app.add_option("--calibration", o->input.calibration,
                   "the device's calibration (YAML, data/inceptors/README.md; `fedsim io calibrate` writes one)");
    app.add_option("--adc", o->input.adc, "pass the inputs through an emulated A/D interface (YAML)");
    app.add_option("--aircraft-id", o->aircraft_id, "aircraft the controls fly")
        ->check(fedsim::util::FiniteRange(0, 65535))
        ->capture_default_str();
    app.add_option("--controls-qos", o->controls_qos,
                   "QoS profile of fedsim/pilot_controls (default: the catalogue's)");
    app.add_flag("--loader-in-the-loop", o->loader_in_the_loop,
                 "send the force channels to fedsim-control-loading and report its positions as the primaries");
  };
  p.make_component = [o](const runtime::FederateOptions& common) {
    return std::unique_ptr<runtime::Component>(
        std::make_unique<IoComponent>(common.name, make_input_source(o->input), o->aircraft_id, o->controls_qos,
                                      o->loader_in_the_loop));
  };
  return p;
}

}  // namespace fedsim::io
