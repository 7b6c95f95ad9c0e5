// fedsim-io: the I/O federate (the seed's node 1 inputs). Publishes the pilot controls every
// frame from an input source - today a scripted profile; joystick and A/D emulation implement
// the same InputSource interface.
//
// Subscribes: fedsim/frame_tick, fedsim/sim_command (runtime).
// Publishes:  fedsim/pilot_controls ("lockstep_data": reliable keep-last 1) every frame,
//             stamped with the frame it was computed in.
#include "common/runtime/federate.hpp"
#include "common/runtime/shutdown.hpp"
#include "io/input_profile.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

using namespace fedsim;

namespace {

void to_message(const io::ControlInputs& in, msg::PilotControls& out) {
  using io::Channel;
  out.elevator(static_cast<float>(in[Channel::kElevator]));
  out.aileron(static_cast<float>(in[Channel::kAileron]));
  out.rudder(static_cast<float>(in[Channel::kRudder]));
  out.elevator_trim(static_cast<float>(in[Channel::kElevatorTrim]));
  out.aileron_trim(static_cast<float>(in[Channel::kAileronTrim]));
  out.rudder_trim(static_cast<float>(in[Channel::kRudderTrim]));
  for (int e = 0; e < io::kMaxEngines; ++e) {
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

}  // namespace

int main(int argc, char** argv) {
  runtime::install_shutdown_handler();
  runtime::FederateOptions common;
  std::string profile_path;
  int aircraft_id = 0;
  std::string controls_qos = "lockstep_data";
  CLI::App app{"fedsim-io: publishes pilot controls every frame from an input source"};
  runtime::add_federate_options(app, common, "io");
  app.add_option("--profile", profile_path, "scripted input profile (CSV: time_s + channels)")
      ->required();
  app.add_option("--aircraft-id", aircraft_id, "aircraft the controls fly")->capture_default_str();
  app.add_option("--controls-qos", controls_qos, "QoS profile of fedsim/pilot_controls")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::unique_ptr<io::InputSource> source;
  try {
    source = std::make_unique<io::InputProfile>(io::InputProfile::load_file(profile_path));
  } catch (const std::exception& e) {
    std::cerr << "fedsim-io: " << e.what() << "\n";
    return 2;
  }
  try {
    runtime::Federate federate(common);
    federate.log().info("input source: {}", source->describe());
    auto& controls_pub =
        federate.publish<msg::PilotControls>(msg::TOPIC_PILOT_CONTROLS, controls_qos);
    msg::PilotControls sample;
    sample.aircraft_id(static_cast<uint16_t>(aircraft_id));
    io::ControlInputs controls = io::default_controls();
    return federate.run([&](const runtime::FrameContext& ctx) {
      source->sample(ctx.sim_time_s, controls);
      to_message(controls, sample);
      sample.stamp(ctx.stamp());
      controls_pub.publish(sample);
    });
  } catch (const std::exception& e) {
    std::cerr << "fedsim-io: " << e.what() << "\n";
    return 2;
  }
}
