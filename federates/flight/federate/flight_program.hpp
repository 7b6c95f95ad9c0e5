// The flight federate's options and how they build what it flies: one set of model options
// for the federate (fedsim-flight), the batch program (fedsim-fly) and in-process runs.
#pragma once

#include "common/runtime/federate_main.hpp"
#include "flight/federate/flight_component.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace fedsim::flight {

/// Exit code of a start whose trim did not converge.
inline constexpr int kExitTrimFailed = 3;

struct FlightOptions {
  std::string aircraft;            // --aircraft: pack file, or a pack name in data/aircraft
  StartOptions start;              // --ic | --trim ... | --airport/--runway
  std::string earth = "flat";      // --earth flat|wgs84
  std::string integrator = "rk4";  // --integrator (the library's default too)
  int substeps = 1;                // --substeps
  std::uint64_t seed = 1;          // --seed: turbulence seed unless the weather names one
  std::string turbulence;          // --turbulence none|light|moderate|severe ("" = IC file's)
  std::string aero_rates = "air";  // --aero-rates air|inertial
  std::string controls = "absolute";  // --controls absolute|relative
  std::string state_qos;           // --state-qos ("" = the catalogue's)
  int aircraft_id = 0;             // --aircraft-id
  bool autopilot = false;          // --autopilot: host the AFCS (model/afcs)
};

/// Adds every option above to `app`.
void add_flight_options(CLI::App& app, FlightOptions& options);
/// The model options the command line asks for.
AircraftModel::Options model_options(const FlightOptions& options);
/// Loads the pack, builds the model, starts it (IC file or trim), loads the runway table.
/// Throws std::invalid_argument / util::ConfigError for bad input. A trim that does not
/// converge is returned (start.trim->converged false): see require_trimmed.
FlightSetup prepare_flight(const FlightOptions& options);
/// Throws runtime::ProgramError (kExitTrimFailed) with the reason if the start trim failed.
void require_trimmed(const FlightSetup& setup);
/// The flight component, logged as the federate logs it.
std::unique_ptr<FlightComponent> make_flight_component(const std::string& name,
                                                       const FlightOptions& options);

/// fedsim-flight as a program (its own options; the component it runs).
runtime::FederateProgram program();

}  // namespace fedsim::flight
