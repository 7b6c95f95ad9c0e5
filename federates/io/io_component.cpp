#include "io/io_component.hpp"
#include "common/util/cli_checks.hpp"

#include "io/model/input_profile.hpp"

#include "common/units/units.hpp"

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
  std::uint32_t discretes = out.discretes() & ~(msg::DISCRETE_AUTOPILOT_DISCONNECT | msg::DISCRETE_TOGA);
  if (buttons.held(Channel::kApDisconnect)) discretes |= msg::DISCRETE_AUTOPILOT_DISCONNECT;
  if (buttons.held(Channel::kToga)) discretes |= msg::DISCRETE_TOGA;
  out.discretes(discretes);
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
  mcp_buttons_.update(controls_);
  to_message(controls_, mcp_buttons_, sample_);
  sample_.stamp(frame.stamp());
  pilot_controls_.write(sample_);
}

runtime::FederateProgram program() {
  struct Options {
    std::string profile;
    int aircraft_id = 0;
    std::string controls_qos;
  };
  auto o = std::make_shared<Options>();
  runtime::FederateProgram p;
  p.program = "fedsim-io";
  p.default_name = "io";
  p.description = "publishes pilot controls every frame from an input source";
  p.add_options = [o](CLI::App& app) {
    app.add_option("--profile", o->profile, "scripted input profile (CSV: time_s + channels)")
        ->required();
    app.add_option("--aircraft-id", o->aircraft_id, "aircraft the controls fly")
        ->check(fedsim::util::FiniteRange(0, 65535))
        ->capture_default_str();
    app.add_option("--controls-qos", o->controls_qos,
                   "QoS profile of fedsim/pilot_controls (default: the catalogue's)");
  };
  p.make_component = [o](const runtime::FederateOptions& common) {
    auto source = std::make_unique<InputProfile>(InputProfile::load_file(o->profile));
    return std::unique_ptr<runtime::Component>(
        std::make_unique<IoComponent>(common.name, std::move(source), o->aircraft_id, o->controls_qos));
  };
  return p;
}

}  // namespace fedsim::io
