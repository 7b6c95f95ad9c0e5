// fedsim-flight: the flight federate. Options below; the adapter is flight_component.hpp.
#include "common/runtime/federate_main.hpp"
#include "flight/federate/flight_component.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

using namespace fedsim;

namespace {

constexpr int kTrimFailed = 3;

struct FlightOptions {
  std::string aircraft;
  flight::StartOptions start;
  std::string earth = "flat";
  std::string integrator = "rk4";  // AB2 at 50 Hz is too close to its stability limit with stiff gear
  int substeps = 1;
  std::uint64_t seed = 1;
  std::string controls_mode = "absolute";
  std::string state_qos = std::string(runtime::qos::kState);
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

void add_options(CLI::App& app, FlightOptions& o) {
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
  app.add_option("--aircraft-id", o.aircraft_id, "aircraft id (topic key)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
}

/// Everything that can be wrong with the input is checked here, before joining the federation.
std::unique_ptr<runtime::Component> make_flight(const runtime::FederateOptions& common,
                                                const FlightOptions& o) {
  flight::FlightSetup setup;
  setup.model = std::make_unique<flight::AircraftModel>(
      flight::load_aircraft_pack(flight::resolve_pack_path(o.aircraft)), model_options(o));
  setup.start = flight::establish_start(o.start, *setup.model);
  if (setup.start.trim && !setup.start.trim->converged) {
    throw runtime::ProgramError(kTrimFailed, "trim failed: " + setup.start.trim->reason);
  }
  setup.runways = RunwayTable::load_default();
  setup.controls_mode = o.controls_mode == "relative" ? flight::ControlsMode::kRelative
                                                      : flight::ControlsMode::kAbsolute;
  setup.aircraft_id = o.aircraft_id;
  const std::optional<flight::TrimResult> trim = setup.start.trim;
  auto component = std::make_unique<flight::FlightComponent>(common.name, std::move(setup), o.state_qos);
  component->log().info("aircraft={} earth={} integrator={} substeps={} controls={}", o.aircraft,
                        o.earth, o.integrator, o.substeps, o.controls_mode);
  if (trim) component->log().info("trim {}", flight::trim_json(*trim));
  return component;
}

}  // namespace

int main(int argc, char** argv) {
  FlightOptions options;
  runtime::FederateProgram program;
  program.program = "fedsim-flight";
  program.default_name = "flight";
  program.description = "the flight federate (equations of motion, aero, engines, gear)";
  program.add_options = [&](CLI::App& app) { add_options(app, options); };
  program.make_component = [&](const runtime::FederateOptions& common) {
    return make_flight(common, options);
  };
  return runtime::federate_main(argc, argv, program);
}
