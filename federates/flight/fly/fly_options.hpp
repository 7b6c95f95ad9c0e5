// Command-line options of fedsim-fly (the start options are shared with fedsim-flight).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "flight/federate/start_options.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"

namespace fedsim::flight {

struct FlyOptions {
  std::string aircraft;            // --aircraft: pack file, or a pack name in data/aircraft
  StartOptions start;              // --ic | --trim ... (shared with fedsim-flight)
  std::string inputs;              // --inputs profile.csv
  bool inputs_relative = false;    // --inputs-relative
  double duration_s = 0.0;         // --duration
  double rate_hz = 0.0;            // --rate
  int substeps = 1;                // --substeps
  std::string earth = "flat";      // --earth
  std::string integrator = "rk4";  // --integrator
  std::uint64_t seed = 1;          // --seed (turbulence)
  std::string aero_rates = "air";  // --aero-rates air|inertial
  std::string turbulence;          // --turbulence none|light|moderate|severe (overrides the IC)
  std::string out;                 // --out file.csv
  int output_every = 1;            // --output-every N frames
  bool quiet = false;              // --quiet: no progress on stderr
};

/// Adds every fedsim-fly option to `app`.
void add_fly_options(CLI::App& app, FlyOptions& options);

/// The model options the command line asks for.
AircraftModel::Options model_options(const FlyOptions& options);


}  // namespace fedsim::flight
