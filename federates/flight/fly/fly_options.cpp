// Command-line options of fedsim-fly.
#include "flight/fly/fly_options.hpp"

#include <filesystem>
#include <stdexcept>

namespace fedsim::flight {

void add_fly_options(CLI::App& app, FlyOptions& o) {
  app.add_option("--aircraft", o.aircraft,
                 "aircraft pack: a YAML file, or a name in data/aircraft (c172, b737, ...)")
      ->required();
  add_start_options(app, o.start);
  app.add_option("--inputs", o.inputs, "scripted input profile (CSV of control channels)");
  app.add_flag(
      "--inputs-relative", o.inputs_relative,
      "add the profile's values to the start (trimmed) controls instead of replacing them");
  app.add_option("--duration", o.duration_s, "simulated time [s]")
      ->required()
      ->check(CLI::Range(0.0, 1.0e6));
  app.add_option("--rate", o.rate_hz, "frame rate [Hz]: one CSV row per frame")
      ->required()
      ->check(CLI::Range(1.0, 100000.0));
  app.add_option("--substeps", o.substeps, "integration steps per frame")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--earth", o.earth, "flat | wgs84")
      ->check(CLI::IsMember({"flat", "wgs84"}))
      ->capture_default_str();
  app.add_option("--integrator", o.integrator, "euler | rk4 | ab2 | ab3 | ab4")
      ->check(CLI::IsMember({"euler", "rk4", "ab2", "ab3", "ab4"}))
      ->capture_default_str();
  app.add_option("--seed", o.seed, "turbulence seed (unless the IC file's weather names one)")
      ->capture_default_str();
  app.add_option("--aero-rates", o.aero_rates,
                 "body rates the aerodynamic rate terms see: air (relative to the air mass) | "
                 "inertial (as NASA's check cases define their damping)")
      ->check(CLI::IsMember({"air", "inertial"}))
      ->capture_default_str();
  app.add_option("--turbulence", o.turbulence, "none | light | moderate | severe (MIL-F-8785C)")
      ->check(CLI::IsMember({"none", "light", "moderate", "severe"}));
  app.add_option("--out", o.out, "output CSV file")->required();
  app.add_option("--output-every", o.output_every, "write every Nth frame (the last always)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  app.add_flag("--quiet", o.quiet, "no progress messages on stderr");
}

AircraftModel::Options model_options(const FlyOptions& o) {
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


}  // namespace fedsim::flight
