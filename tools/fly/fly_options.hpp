// Command-line options of fedsim-fly: the flight federate's own options (flight_program.hpp,
// one set for both programs) plus the batch run's. A tool (tools/fly): it composes the flight
// and I/O federates' components and the in-process recorder in one process.
#pragma once

#include "flight/federate/flight_program.hpp"

#include "io/model/control_inputs.hpp"
#include "io/model/input_source.hpp"
#include "io/model/stall_entry_pilot.hpp"

#include <CLI/CLI.hpp>

#include <memory>

#include <string>

namespace fedsim::fly {

struct FlyOptions {
  flight::FlightOptions flight;  // --aircraft, start, model and weather options
  std::string inputs;            // --inputs profile.csv (flown by an I/O component)
  bool inputs_relative = false;  // --inputs-relative: --controls relative
  std::string pilot;             // --pilot stall-entry: a closed-loop test pilot
  io::StallEntryParameters stall_entry;  // --entry-rate-kt-s, --pilot-throttle
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

/// The cockpit the I/O component starts from, before the profile or the pilot drives a
/// channel: the start's configuration (flaps, gear lever, speedbrake, brakes, trims, mixture,
/// propeller) and, with absolute controls, its primaries and throttles (relative: zero offsets).
/// Without it an undriven channel would take fedsim-io's resting cockpit (gear DOWN).
io::ControlInputs cockpit_at_start(const flight::AircraftControls& start, bool relative_controls);

/// The input source the options name (a profile, the pilot, or the pilot over a profile); null
/// when neither is given; `pilot` is set to the pilot, if any (to report its stall). Throws for
/// a bad profile (naming file and line).
std::unique_ptr<io::InputSource> make_fly_input_source(const FlyOptions& options,
                                                       const io::StallEntryPilot** pilot = nullptr);

}  // namespace fedsim::fly
