// fedsim-timing: the federation's frame clock. See timing_federate.hpp.
#include "common/runtime/shutdown.hpp"
#include "common/util/cli_checks.hpp"
#include "timing/timing_federate.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  fedsim::runtime::install_shutdown_handler();
  fedsim::timing::TimingOptions options;
  CLI::App app{"fedsim-timing: publishes the frame tick (realtime or lockstep)"};
  fedsim::runtime::add_federate_options(app, options.common, "timing");
  app.add_option("--rate", options.rate_hz, "frame rate [Hz]")
      ->check(fedsim::util::FiniteRange(1.0, 10000.0))
      ->capture_default_str();
  app.add_option("--mode", options.mode, "realtime | lockstep")
      ->check(CLI::IsMember({"realtime", "lockstep"}))
      ->capture_default_str();
  app.add_option("--scale", options.scale,
                 "lockstep pacing: 0 = as fast as possible, 1 = real time, 2 = twice real time")
      ->check(fedsim::util::kFiniteNonNegative);
  app.add_option("--expect", options.expect, "federates that must acknowledge every frame")
      ->delimiter(',');
  app.add_option("--start", options.start, "state of the first frame: run | freeze")
      ->check(CLI::IsMember({"run", "freeze"}))
      ->capture_default_str();
  app.add_option("--ack-timeout", options.ack_timeout_s,
                 "declare a federate lost after this many seconds without acknowledging")
      ->check(fedsim::util::kFinitePositive)
      ->capture_default_str();
  app.add_option("--resend-after", options.resend_after_s,
                 "lockstep: repeat a tick whose acknowledgements are this many seconds overdue")
      ->check(fedsim::util::kFinitePositive)
      ->capture_default_str();
  app.add_option("--join-timeout", options.join_timeout_s,
                 "seconds to wait for the expected federates to be ready")
      ->check(fedsim::util::kFinitePositive)
      ->capture_default_str();
  app.add_option("--settle", options.settle_s,
                 "seconds to let discovery finish once every federate is ready")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  app.add_flag("--stop-on-lost", options.stop_on_lost, "stop when a federate is lost");
  app.add_flag("--shutdown-on-exit", options.shutdown_on_exit,
               "tell every federate to stop when the timing federate stops");
  app.add_option("--summary-json", options.summary_json, "write the run summary JSON here");
  bool no_hold = false;
  app.add_flag("--no-hold-commands", no_hold,
               "do not keep the latest settings (weather, failures...) for federates that join late");
  CLI11_PARSE(app, argc, argv);
  options.hold_commands = !no_hold;
  try {
    fedsim::timing::TimingFederate timing(options);
    return timing.run();
  } catch (const std::exception& e) {
    std::cerr << "fedsim-timing: " << e.what() << "\n";
    return 2;
  }
}
