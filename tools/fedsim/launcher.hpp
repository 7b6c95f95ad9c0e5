// `fedsim run`: starts the federates a deployment lists (plus the timing federate), prefixes and
// keeps their logs, reports progress from fedsim/federate_status, stops them all cleanly on
// Ctrl-C, --duration or when the timing federate finishes, and fails if any federate fails.
#pragma once

#include "fedsim/deployment.hpp"

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
};

/// Runs the deployment; returns the process exit code (0 = every federate stopped cleanly).
int run_deployment(const RunOptions& options);

}  // namespace fedsim::launcher
