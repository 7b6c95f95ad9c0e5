// Command-line options of fedsim-fly: the flight federate's own options (flight_program.hpp,
// one set for both programs) plus the batch run's.
#pragma once

#include "flight/federate/flight_program.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace fedsim::flight {

struct FlyOptions {
  FlightOptions flight;          // --aircraft, start, model and weather options
  std::string inputs;            // --inputs profile.csv (flown by an I/O component)
  bool inputs_relative = false;  // --inputs-relative: --controls relative
  double duration_s = 0.0;       // --duration (simulated seconds)
  double rate_hz = 0.0;          // --rate
  std::string out_dir;           // --out DIR: one CSV per topic
  int output_every = 1;          // --output-every N frames
  bool quiet = false;            // --quiet
};

/// Adds every fedsim-fly option to `app`.
void add_fly_options(CLI::App& app, FlyOptions& options);
/// Checks what CLI11 cannot (combinations, finite numbers); throws std::invalid_argument.
void check_fly_options(FlyOptions& options);

}  // namespace fedsim::flight
