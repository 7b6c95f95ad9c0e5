// fedsim: the command-line front door. `fedsim run` starts a federation from a deployment file;
// `fedsim command ...` sends instructor commands; `fedsim graph` draws a deployment's data flow;
// `fedsim topic list|echo|hz|bw|info` and `fedsim record` monitor and record live topics;
// `fedsim soak` runs the federation in realtime for a while and checks it stays healthy; `fedsim
// latency` measures the transport delay from a control step to each output; `fedsim nav
// find|near` looks up the navigation database; `fedsim io calibrate` calibrates an inceptor;
// `fedsim image montage` puts channel pictures side by side; `fedsim qtg` runs the test guide.
#include "fedsim/command_cli.hpp"
#include "common/util/cli_checks.hpp"
#include "fedsim/graph.hpp"
#include "fedsim/image_cli.hpp"
#include "fedsim/io_cli.hpp"
#include "fedsim/latency.hpp"
#include "fedsim/launcher.hpp"
#include "fedsim/nav_cli.hpp"
#include "fedsim/soak.hpp"
#include "topic/topic_commands.hpp"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
  // `fedsim qtg ...` is the Qualification Test Guide program beside this one (tools/qtg,
  // docs/qtg.md), run with the same arguments: its options stay in one place.
  if (argc >= 2 && std::string(argv[1]) == "qtg") {
    const auto qtg = std::filesystem::read_symlink("/proc/self/exe").parent_path() / "fedsim-qtg";
    argv[1] = const_cast<char*>(qtg.c_str());
    execv(qtg.c_str(), argv + 1);
    std::cerr << "fedsim qtg: cannot run " << qtg << '\n';
    return 2;
  }
  CLI::App app{"fedsim: a DDS-federated engineering flight simulator"};
  app.require_subcommand(1);

  fedsim::launcher::RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "start the federation a deployment file lists");
  run_cmd->add_option("deployment", run.deployment_path, "deployment file (YAML)")->required();
  run_cmd->add_option("--mode", run.mode, "override the deployment: realtime | lockstep")
      ->check(CLI::IsMember({"realtime", "lockstep"}));
  run_cmd->add_option("--duration", run.duration_s, "stop everything after this many seconds")
      ->check(fedsim::util::kFiniteNonNegative);
  run_cmd->add_option("--domain", run.domain, "DDS domain (default: FEDSIM_DOMAIN, the file, 0)")
      ->check(fedsim::util::FiniteRange(0, 232));
  run_cmd->add_option("--out", run.out_dir, "output folder (default out/<deployment name>)");
  run_cmd->add_option("--stop-grace", run.stop_grace_s, "seconds between SIGTERM and SIGKILL")
      ->check(fedsim::util::FiniteRange(0, 3600))
      ->capture_default_str();
  run_cmd->add_option("--progress", run.progress_period_s, "seconds between progress lines (0 = off)")
      ->check(fedsim::util::FiniteRange(0, 3600))
      ->capture_default_str();
  run_cmd->add_flag("--quiet", run.quiet, "do not echo federate output (logs are still kept)");
  run_cmd->add_option("--scenario", run.scenario,
                      "run this instructor scenario file too (a fedsim-scenario member; data/scenarios has examples)");
  run_cmd->add_flag("--in-process", run.in_process,
                    "compose the federates in this process: no DDS, lockstep, --frames from the "
                    "timing arguments; byte-identical to the DDS lockstep run");
  int exit_code = 0;
  run_cmd->callback([&] { exit_code = fedsim::launcher::run_deployment(run); });

  fedsim::launcher::add_command_commands(app, exit_code);
  fedsim::launcher::add_graph_command(app, exit_code);
  fedsim::tools::add_topic_commands(app);
  fedsim::launcher::add_nav_commands(app, exit_code, std::cout, std::cerr);
  fedsim::launcher::add_io_commands(app, exit_code);
  fedsim::launcher::add_image_commands(app, exit_code);
  fedsim::launcher::add_soak_command(app, exit_code);
  fedsim::launcher::add_latency_command(app, exit_code);
  // listed for --help only: `fedsim qtg` is handed to fedsim-qtg above, before parsing
  app.add_subcommand("qtg", "run the Qualification Test Guide (fedsim-qtg, docs/qtg.md)");
  CLI11_PARSE(app, argc, argv);
  return exit_code;
}
