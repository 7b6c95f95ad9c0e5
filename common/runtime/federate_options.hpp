// Command-line options every federate and tool shares, parsed with CLI11. Any option can also
// come from a TOML/INI file given with --config, and the DDS ones from the environment
// (FEDSIM_DOMAIN, FEDSIM_QOS_FILE, FEDSIM_PARTICIPANT_PROFILE).
#pragma once

#include "common/runtime/dds_participant.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace fedsim::runtime {

struct FederateOptions {
  std::string name;                // unique federate name in the federation
  ParticipantOptions dds;          // domain, QoS file, participant profile
  std::string log_level = "info";  // trace|debug|info|warn|error
  double duration_s = 0.0;         // stop after this many wall-clock seconds (0 = run until told)
  std::uint64_t max_frames = 0;    // stop after stepping this many frames (0 = no limit)
  double input_timeout_s = 1.0;    // lockstep: how long to wait for a missing input sample
  std::string sync_qos_suffix;     // QoS of tick and frame_done: "" best effort, "_reliable"
  std::uint64_t silent_frames = 10;  // a matched writer of an every-frame topic quiet this many
                                     // frames is a fault (0 = never) [frames]
};

/// Adds --name, --domain, --qos-file, --participant-profile, --log-level, --duration,
/// --frames, --sync-qos, --input-timeout, --silent-frames and --config to `app`.
void add_federate_options(CLI::App& app, FederateOptions& options, const std::string& default_name);
/// Adds --sync-qos best_effort|reliable (default best_effort), stored as the profile suffix of
/// tick and frame_done ("" or "_reliable").
void add_sync_qos_option(CLI::App& app, std::string& suffix, const std::string& description);
/// Adds only the DDS options (for tools that are not federates).
void add_dds_options(CLI::App& app, ParticipantOptions& options);

/// The QoS file used when none is given: the source tree's qos/fedsim_qos.xml.
std::string default_qos_file();

}  // namespace fedsim::runtime
