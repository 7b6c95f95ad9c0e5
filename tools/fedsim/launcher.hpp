// `fedsim run`: starts the federates a deployment lists (plus the timing federate), prefixes and
// keeps their logs, reports progress from fedsim/federate_status, stops them all cleanly on
// Ctrl-C, --duration or when the timing federate finishes, and fails if any federate fails.
#pragma once

#include "fedsim/deployment.hpp"

#include <filesystem>
#include <map>
#include <string>

namespace fedsim::launcher {

struct RunOptions {
  std::string deployment_path;
  std::string mode;              // "" = as the deployment says
  double duration_s = 0.0;       // 0 = until the timing federate stops or Ctrl-C
  int domain = -1;               // -1 = FEDSIM_DOMAIN, else the deployment's, else 0
  std::string out_dir;           // "" = out/<deployment name>
  double stop_grace_s = 5.0;     // SIGTERM -> SIGKILL
  double progress_period_s = 2.0;
  bool quiet = false;            // do not echo federate output (it still goes to the log files)
  bool in_process = false;       // compose the federates in this process (no DDS, lockstep)
  std::string scenario;          // a scenario file run by a fedsim-scenario member ("" = none)
};

/// Runs the deployment; returns the process exit code: 0 = the federation ran (the timing
/// federate ticked, every required federate reported RUNNING) and every federate stopped
/// cleanly; 1 = a failure (named on the output), including a federate the timing federate
/// reported lost (its summary's losses and rejoins are printed) and one restarted after a crash
/// (restart: on-failure keeps the run going, but a crash is still a failure); 2 = a bad
/// deployment or option; 128 + the
/// signal (130 for Ctrl-C) when interrupted. Each federate runs in its own process group,
/// which the stop signals reach whole.
int run_deployment(const RunOptions& options);

/// Runs the deployment's federates as components in this process (runtime::Composition), in
/// lockstep for the timing arguments' --frames, recording as its `fedsim record` member asks;
/// then its after-commands. Every federate must be a component program (fedsim/members.hpp).
int run_in_process(const RunOptions& options);

/// Loads the deployment and, with options.scenario, adds the fedsim-scenario member that runs
/// it (the file checked first: a bad one throws util::ConfigError naming file and line).
Deployment load_with_scenario(const RunOptions& options);

/// The ${...} variables of a deployment's arguments.
std::map<std::string, std::string> deployment_vars(const std::string& deployment_path,
                                                   const std::string& out_dir);
/// Where the fedsim binaries are (this program's folder).
std::string bin_dir();
/// What the after-steps need to know of the run that just stopped.
struct RunEnd {
  std::filesystem::file_time_type started;  // a needed file older than this is an earlier run's
  std::string cut_short;                    // why it stopped before its own end ("" = it did not)
};

/// Runs the deployment's after-steps in order; 1 if one ran and failed (named on stderr). A step
/// whose needs this run did not meet (deployment.hpp: `needs`, `whole_run`) is skipped and named,
/// with the file it lacked or why the run was cut short; a skip is not a failure.
int run_after_commands(const Deployment& d, const std::map<std::string, std::string>& vars,
                       const std::string& bin_dir, const std::string& log_dir, bool quiet,
                       const RunEnd& end);

}  // namespace fedsim::launcher
