#include "flight/federate/flight_program.hpp"
#include "common/aircraft_pack/pack_path.hpp"
#include "common/util/cli_checks.hpp"

#include "flight/model/aircraft/aircraft_pack.hpp"

#include <memory>

namespace fedsim::flight {

namespace {
Turbulence::Severity severity_named(const std::string& name) {
  if (name == "light") return Turbulence::Severity::kLight;
  if (name == "moderate") return Turbulence::Severity::kModerate;
  if (name == "severe") return Turbulence::Severity::kSevere;
  return Turbulence::Severity::kNone;
}
}  // namespace

void add_flight_options(CLI::App& app, FlightOptions& o) {
  app.add_option("--aircraft", o.aircraft,
                 "aircraft pack: a YAML file, or a pack name in data/aircraft (c172, b737, ...)")
      ->required();
  add_start_options(app, o.start);
  app.add_option("--earth", o.earth, "flat | wgs84")
      ->check(CLI::IsMember({"flat", "wgs84"}))
      ->capture_default_str();
  app.add_option("--integrator", o.integrator, "euler | rk4 | ab2 | ab3 | ab4")
      ->check(CLI::IsMember({"euler", "rk4", "ab2", "ab3", "ab4"}))
      ->capture_default_str();
  app.add_option("--substeps", o.substeps, "integration steps per frame")
      ->check(fedsim::util::FiniteRange(1, 1000))
      ->capture_default_str();
  app.add_option("--seed", o.seed, "turbulence seed (unless the IC file's weather names one)")
      ->capture_default_str();
  app.add_option("--turbulence", o.turbulence, "none | light | moderate | severe (MIL-F-8785C)")
      ->check(CLI::IsMember({"none", "light", "moderate", "severe"}));
  app.add_option("--aero-rates", o.aero_rates,
                 "body rates the aerodynamic rate terms see: air (relative to the air mass) | "
                 "inertial (as NASA's check cases define their damping)")
      ->check(CLI::IsMember({"air", "inertial"}))
      ->capture_default_str();
  app.add_option("--controls", o.controls,
                 "absolute: pilot controls are inceptor positions; relative: elevator, aileron, "
                 "rudder and throttle add to the trimmed values")
      ->check(CLI::IsMember({"absolute", "relative"}))
      ->capture_default_str();
  app.add_option("--state-qos", o.state_qos,
                 "QoS profile of fedsim/aircraft_state (default: the catalogue's, state)");
  app.add_flag("--autopilot", o.autopilot,
               "host the AFCS (autopilot, flight director, autothrottle, autoland; gains designed for "
               "the 737 pack): reads the MCP in fedsim/pilot_controls and NAV1's ILS in "
               "fedsim/navigation_state, writes fedsim/autopilot_state");
  app.add_option("--aircraft-id", o.aircraft_id, "aircraft id (topic key)")
      ->check(fedsim::util::FiniteRange(0, 65535))
      ->capture_default_str();
}

AircraftModel::Options model_options(const FlightOptions& o) {
  AircraftModel::Options m;
  m.earth = o.earth == "wgs84" ? EarthModelKind::kWgs84 : EarthModelKind::kFlat;
  m.integrator = integration_method_from_name(o.integrator);
  m.substeps = o.substeps;
  m.turbulence_seed = o.seed;
  m.aero_rates = o.aero_rates == "inertial" ? AircraftModel::AeroRates::kInertial
                                            : AircraftModel::AeroRates::kAirMass;
  if (o.start.runway_elevation_m) m.runway_elevation_m = *o.start.runway_elevation_m;
  return m;
}

FlightSetup prepare_flight(const FlightOptions& o) {
  FlightSetup setup;
  setup.model = std::make_unique<AircraftModel>(load_aircraft_pack(aircraft_pack::resolve_pack_path(o.aircraft)),
                                                model_options(o));
  setup.start = establish_start(o.start, *setup.model);
  if (!o.turbulence.empty()) {
    WeatherSettings weather = setup.model->weather();
    weather.turbulence = severity_named(o.turbulence);
    setup.model->set_weather(weather);
  }
  setup.runways = RunwayTable::load_default();
  setup.controls_mode = o.controls == "relative" ? ControlsMode::kRelative : ControlsMode::kAbsolute;
  setup.aircraft_id = o.aircraft_id;
  if (o.autopilot) setup.autopilot = afcs::AfcsParameters{};
  // The runway of an --airport/--runway start: the progress line's distance to go.
  if (!o.start.airport.empty() && !o.start.runway.empty()) {
    setup.progress_runway =
        RunwayCentreline::from_table(setup.runways, o.start.airport, o.start.runway);
  }
  return setup;
}

void require_trimmed(const FlightSetup& setup) {
  if (setup.start.trim && !setup.start.trim->converged) {
    throw runtime::ProgramError(kExitTrimFailed, "trim failed: " + setup.start.trim->reason);
  }
}

std::unique_ptr<FlightComponent> make_flight_component(const std::string& name,
                                                       const FlightOptions& o) {
  FlightSetup setup = prepare_flight(o);
  require_trimmed(setup);
  const std::optional<TrimResult> trim = setup.start.trim;
  auto component = std::make_unique<FlightComponent>(name, std::move(setup), o.state_qos);
  component->log().info("aircraft={} earth={} integrator={} substeps={} controls={} autopilot={}", o.aircraft,
                        o.earth, o.integrator, o.substeps, o.controls, o.autopilot ? "on" : "off");
  if (trim) component->log().info("trim {}", trim_json(*trim));
  return component;
}

runtime::FederateProgram program() {
  auto options = std::make_shared<FlightOptions>();
  runtime::FederateProgram p;
  p.program = "fedsim-flight";
  p.default_name = "flight";
  p.description = "the flight federate (equations of motion, aero, engines, gear)";
  p.add_options = [options](CLI::App& app) { add_flight_options(app, *options); };
  p.make_component = [options](const runtime::FederateOptions& common) {
    return std::unique_ptr<runtime::Component>(make_flight_component(common.name, *options));
  };
  return p;
}

}  // namespace fedsim::flight
