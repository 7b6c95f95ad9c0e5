// fedsim-flight: the flight federate (the seed's node 2). Steps the aircraft model once per
// frame from the pilot controls and publishes the aircraft and engine state.
//
// Subscribes: fedsim/pilot_controls ("lockstep_data", lockstep input: frame N flies the controls
//             of frame N-1), fedsim/frame_tick and fedsim/sim_command (runtime).
// Publishes:  fedsim/aircraft_state (--state-qos, default "state") and fedsim/engine_state
//             ("state", one instance per engine) every frame, stamped with the frame.
// Run states: RUN integrates one frame period; FREEZE holds the aircraft and keeps publishing;
//             RESET returns to the start state. Commands: reposition (point, runway threshold,
//             approach gate), weather, engine failures.
#include "common/runtime/federate.hpp"
#include "common/runtime/shutdown.hpp"
#include "flight/federate/flight_adapter.hpp"
#include "flight/federate/start_options.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

using namespace fedsim;

namespace {

struct FlightOptions {
  std::string aircraft;
  flight::StartOptions start;
  std::string earth = "flat";
  std::string integrator = "rk4";  // AB2 at 50 Hz is too close to its stability limit with stiff gear
  int substeps = 1;
  std::uint64_t seed = 1;
  std::string controls_mode = "absolute";
  std::string state_qos = "state";
  int aircraft_id = 0;
};

flight::AircraftModel::Options model_options(const FlightOptions& o) {
  flight::AircraftModel::Options m;
  m.earth = o.earth == "wgs84" ? flight::EarthModelKind::kWgs84 : flight::EarthModelKind::kFlat;
  m.integrator = integration_method_from_name(o.integrator);
  m.substeps = o.substeps;
  m.turbulence_seed = o.seed;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  runtime::install_shutdown_handler();
  runtime::FederateOptions common;
  FlightOptions o;
  CLI::App app{"fedsim-flight: the flight federate (equations of motion, aero, engines, gear)"};
  runtime::add_federate_options(app, common, "flight");
  app.add_option("--aircraft", o.aircraft,
                 "aircraft pack: a YAML file, or a pack name in data/aircraft (c172, b737)")
      ->required();
  flight::add_start_options(app, o.start);
  app.add_option("--earth", o.earth, "flat | wgs84")->check(CLI::IsMember({"flat", "wgs84"}))->capture_default_str();
  app.add_option("--integrator", o.integrator, "euler | rk4 | ab2 | ab3 | ab4")
      ->check(CLI::IsMember({"euler", "rk4", "ab2", "ab3", "ab4"}))->capture_default_str();
  app.add_option("--substeps", o.substeps, "integration steps per frame")->check(CLI::Range(1, 100));
  app.add_option("--seed", o.seed, "turbulence seed")->capture_default_str();
  app.add_option("--controls", o.controls_mode,
                 "absolute: controls are inceptor positions; relative: elevator, aileron, rudder "
                 "and throttle add to the trimmed values")
      ->check(CLI::IsMember({"absolute", "relative"}))->capture_default_str();
  app.add_option("--state-qos", o.state_qos, "QoS profile of fedsim/aircraft_state")->capture_default_str();
  app.add_option("--aircraft-id", o.aircraft_id, "aircraft id (topic key)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  // Everything that can be wrong with the input is checked before joining the federation.
  std::unique_ptr<flight::AircraftModel> model;
  flight::StartState start;
  RunwayTable runways;
  try {
    model = std::make_unique<flight::AircraftModel>(
        flight::load_aircraft_pack(flight::resolve_pack_path(o.aircraft)),
                                                    model_options(o));
    start = flight::establish_start(o.start, *model);
    if (start.trim && !start.trim->converged) {
      std::cerr << "fedsim-flight: trim failed: " << start.trim->reason << "\n";
      return 3;
    }
    runways = RunwayTable::load_default();
  } catch (const std::exception& e) {
    std::cerr << "fedsim-flight: " << e.what() << "\n";
    return 2;
  }
  const auto mode = o.controls_mode == "relative" ? flight::ControlsMode::kRelative
                                                  : flight::ControlsMode::kAbsolute;
  try {
    runtime::Federate federate(common);
    auto& log = federate.log();
    log.info("aircraft={} earth={} integrator={} substeps={} controls={}", o.aircraft, o.earth,
             o.integrator, o.substeps, o.controls_mode);
    if (start.trim) log.info("trim {}", flight::trim_json(*start.trim));
    auto& controls_sub = federate.subscribe<msg::PilotControls>(msg::TOPIC_PILOT_CONTROLS,
                                                                 "lockstep_data", true);
    auto& state_pub = federate.publish<msg::AircraftState>(msg::TOPIC_AIRCRAFT_STATE, o.state_qos);
    auto& engine_pub = federate.publish<msg::EngineState>(msg::TOPIC_ENGINE_STATE, "state");
    // Relative controls fly about the latest trim: the start's, or a reposition's.
    flight::AircraftControls trim_base = start.controls;
    federate.on_command([&](const msg::SimCommand& command) {
      try {
        const std::string what = flight::apply_command(command, *model, runways);
        if (command.kind() == msg::COMMAND_REPOSITION) trim_base = model->controls();
        if (!what.empty()) log.info("command seq={} from={}: {}", command.sequence_number(),
                                    command.issuer().to_string(), what);
      } catch (const std::exception& e) {
        log.error("command seq={} rejected: {}", command.sequence_number(), e.what());
      }
    });

    msg::PilotControls pilot;
    msg::AircraftState state;
    msg::EngineState engine;
    state.aircraft_id(static_cast<uint16_t>(o.aircraft_id));
    engine.aircraft_id(static_cast<uint16_t>(o.aircraft_id));
    return federate.run([&](const runtime::FrameContext& ctx) {
      if (ctx.resetting()) {
        model->reset(start.initial, start.controls);
        trim_base = start.controls;
      } else if (ctx.running()) {
        if (controls_sub.latest_before(ctx.frame, pilot)) {
          model->set_controls(flight::controls_from_message(pilot, mode, trim_base));
        }
        model->step(ctx.dt_s);
      }
      flight::fill_aircraft_state(model->outputs(), state);
      state.stamp(ctx.stamp());
      state_pub.publish(state);
      const auto& engines = model->outputs().engines;
      for (std::size_t i = 0; i < engines.size(); ++i) {
        flight::fill_engine_state(engines[i], i, engine);
        engine.stamp(ctx.stamp());
        engine_pub.publish(engine);
      }
    });
  } catch (const std::exception& e) {
    std::cerr << "fedsim-flight: " << e.what() << "\n";
    return 2;
  }
}
