// fedsim-synthetic: a federate that does a configurable amount of busy work per frame and
// publishes a navigation-state-sized sample, for benchmarks and integration tests of the
// runtime. Optionally subscribes to the pilot controls as a lockstep input and records every
// frame it saw (for the lockstep tests).
//
// Subscribes: fedsim/frame_tick, fedsim/sim_command (runtime); fedsim/pilot_controls if --input.
// Publishes:  fedsim/navigation_state ("state") if --publish, fedsim/frame_done (runtime).
#include "common/runtime/federate.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/util/monotonic_clock.hpp"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>

using namespace fedsim;

namespace {
void busy_wait_us(double us) {
  const std::uint64_t until = util::monotonic_ns() + static_cast<std::uint64_t>(us * 1000.0);
  while (util::monotonic_ns() < until) {
  }
}
}  // namespace

int main(int argc, char** argv) {
  runtime::install_shutdown_handler();
  runtime::FederateOptions common;
  double work_us = 0.0;
  bool publish = false;
  bool input = false;
  std::string trace_file;
  CLI::App app{"fedsim-synthetic: a load-generating federate for benchmarks and tests"};
  runtime::add_federate_options(app, common, "synthetic");
  app.add_option("--work-us", work_us, "busy work per frame [us]");
  app.add_flag("--publish", publish, "publish a navigation-state sample every frame");
  app.add_flag("--input", input, "take fedsim/pilot_controls as a lockstep input");
  app.add_option("--trace", trace_file,
                 "write one CSV line per frame: frame,sim_frame,sim_time_s,state,reset_count,"
                 "input_frame,elevator");
  CLI11_PARSE(app, argc, argv);

  try {
    runtime::Federate federate(common);
    runtime::Publisher<msg::NavigationState>* state_pub = nullptr;
    if (publish) {
      state_pub = &federate.publish<msg::NavigationState>(msg::TOPIC_NAVIGATION_STATE, "state");
    }
    runtime::Subscription<msg::PilotControls>* controls_sub = nullptr;
    if (input) {
      controls_sub = &federate.subscribe<msg::PilotControls>(msg::TOPIC_PILOT_CONTROLS,
                                                              "lockstep_data", true);
    }
    std::ofstream trace;
    if (!trace_file.empty()) {
      trace.open(trace_file);
      if (!trace) throw std::runtime_error("cannot write " + trace_file);
      trace << "frame,sim_frame,sim_time_s,state,reset_count,input_frame,elevator\n";
    }
    msg::NavigationState nav;
    msg::PilotControls controls;
    federate.on_stop([&] { trace.flush(); });
    return federate.run([&](const runtime::FrameContext& ctx) {
      if (work_us > 0) busy_wait_us(work_us);
      if (state_pub) {
        nav.stamp(ctx.stamp());
        state_pub->publish(nav);
      }
      if (trace.is_open()) {
        long long input_frame = -1;
        float elevator = 0.0f;
        if (controls_sub && controls_sub->latest_before(ctx.frame, controls)) {
          input_frame = static_cast<long long>(controls.stamp().frame());
          elevator = controls.elevator();
        }
        trace << ctx.frame << ',' << ctx.sim_frame << ',' << ctx.sim_time_s << ','
              << static_cast<int>(ctx.run_state) << ',' << ctx.reset_count << ',' << input_frame
              << ',' << elevator << '\n';
        trace.flush();  // tests watch the file grow
      }
    });
  } catch (const std::exception& e) {
    std::cerr << "fedsim-synthetic: " << e.what() << "\n";
    return 2;
  }
}
