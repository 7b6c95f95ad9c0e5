// fedsim-fly: the flight model in batch mode - the single-federate case of the in-process
// composition. The flight component (and, with --inputs, an I/O component flying a scripted
// profile) run frame by frame with the federation's frame rule, no DDS and no wall clock in
// the loop; every sample is recorded to DIR/<topic>.csv exactly as `fedsim record` records a
// federation, so a batch run and a federated run share their files and columns.
//
// Frame 0 is frozen (the start state at t = 0); frames 1..N fly one period each. As in the
// federation, controls sampled in frame k act in frame k+1.
//
// Exit codes: 0 done; 2 bad input (unknown pack or option, bad profile or IC file: nothing is
// written); 3 the trim did not converge (its JSON and the reason are printed, nothing written);
// 1 a failure while running or faults counted (the output folder is kept for inspection).
#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"
#include "io/io_component.hpp"
#include "io/model/input_profile.hpp"
#include "tools/fly/fly_options.hpp"
#include "tools/topic/in_process_recorder.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

using namespace fedsim;
using namespace fedsim::flight;
using namespace fedsim::fly;

namespace {
constexpr int kRunFailed = 1;
constexpr double kProgressIntervalS = 2.0;  // wall-clock seconds between progress reports

struct Prepared {
  FlightSetup setup;  // moved into the flight component once the trim is known good
  std::unique_ptr<FlightComponent> flight;
  std::unique_ptr<io::InputSource> source;  // the profile and/or the pilot, if any
  const io::StallEntryPilot* pilot = nullptr;  // owned by `source`, then by `io`
  std::unique_ptr<io::IoComponent> io;
};

/// Reads and checks everything the run needs; throws for bad input (before anything is written).
Prepared prepare(FlyOptions& o) {
  check_fly_options(o);
  Prepared p;
  p.source = make_fly_input_source(o, &p.pilot);  // a bad profile fails here, before the trim
  p.setup = prepare_flight(o.flight);
  return p;
}

/// The test pilot's verdict: when and at what speed it identified the stall, and by what.
void report_the_stall(const io::StallEntryPilot& pilot) {
  if (pilot.phase() == io::StallEntryPhase::kStalled) {
    std::fprintf(stderr, "fedsim-fly: stall entry: stall identified at %.2f s, %.1f KCAS (%s); recovery flown\n",
                 pilot.stall_time_s(), pilot.stall_cas_mps() * units::kMpsToKt, pilot.stall_indication().c_str());
  } else {
    std::fprintf(stderr, "fedsim-fly: stall entry: no stall identified by the end of the run (phase %s)\n",
                 io::to_string(pilot.phase()));
  }
}

int fly_run(const FlyOptions& o, Prepared& p) {
  const auto frames = static_cast<std::uint64_t>(std::llround(o.duration_s * o.rate_hz));
  runtime::Composition composition({o.rate_hz, /*start_frozen=*/true});
  if (p.io) composition.add(*p.io);
  composition.add(*p.flight);
  std::vector<std::string> topics = {runtime::topics::aircraft_state.name(),
                                     runtime::topics::engine_state.name()};
  if (p.io) topics.push_back(runtime::topics::pilot_controls.name());
  tools::InProcessRecorder recorder(composition, topics, o.out_dir,
                                    static_cast<std::uint64_t>(o.output_every));
  const auto start = std::chrono::steady_clock::now();
  auto last_report = start;
  composition.step_frame();  // frame 0, frozen: the start state
  msg::SimCommand run;
  run.kind(msg::COMMAND_RUN_STATE);
  run.run_state(msg::RUN_STATE_RUN);
  composition.command(run);
  composition.run(frames, [&](const runtime::FrameContext& frame) {
    recorder.drain();
    if (o.quiet) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_report > std::chrono::duration<double>(kProgressIntervalS)) {
      last_report = now;
      const double simulated_s = frame.sim_time_s + frame.dt_s;
      std::fprintf(stderr, "fedsim-fly: %.1f of %.1f s simulated (%.0f %%)\n", simulated_s,
                   o.duration_s, 100.0 * simulated_s / std::max(o.duration_s, 1e-9));
    }
  });
  composition.stop();
  recorder.close();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet) {
    std::fprintf(stderr, "fedsim-fly: %.1f s flown in %.2f s (%.0fx real time) -> %s\n",
                 o.duration_s, wall_s, o.duration_s / std::max(wall_s, 1e-9), o.out_dir.c_str());
  }
  if (p.pilot) report_the_stall(*p.pilot);
  if (composition.fault_count() > 0) {
    for (const runtime::Component* c : {static_cast<runtime::Component*>(p.flight.get()),
                                        static_cast<runtime::Component*>(p.io.get())}) {
      if (!c) continue;
      for (const auto& f : c->faults()) {
        std::fprintf(stderr, "fedsim-fly: FAULT %s %s x%llu: %s\n", c->name().c_str(),
                     f.kind.c_str(), static_cast<unsigned long long>(f.count), f.last.c_str());
      }
    }
    return kRunFailed;
  }
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  FlyOptions options;
  CLI::App app{"fedsim-fly: fly an aircraft pack in batch mode and record every frame (CSV)"};
  add_fly_options(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : runtime::kExitBadInput;  // --help is not an error
  }

  Prepared prepared;
  try {
    prepared = prepare(options);
  } catch (const runtime::ProgramError& e) {
    std::cerr << "fedsim-fly: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "fedsim-fly: " << e.what() << "\n";
    return runtime::kExitBadInput;
  }
  try {
    if (prepared.setup.start.trim) std::cout << trim_json(*prepared.setup.start.trim) << std::endl;
    require_trimmed(prepared.setup);
    if (prepared.source) {
      // The I/O component starts from the start's cockpit, so an undriven channel keeps it.
      prepared.io = std::make_unique<io::IoComponent>(
          "io", std::move(prepared.source), options.flight.aircraft_id, std::string_view{}, false,
          cockpit_at_start(prepared.setup.start.controls, options.flight.controls == "relative"));
    }
    prepared.flight = std::make_unique<FlightComponent>("flight", std::move(prepared.setup),
                                                        options.flight.state_qos);
  } catch (const runtime::ProgramError& e) {
    std::cerr << "fedsim-fly: " << e.what() << "\n";
    return e.exit_code();
  }
  try {
    return fly_run(options, prepared);
  } catch (const std::exception& e) {
    std::cerr << "fedsim-fly: " << e.what() << "\n";
    return kRunFailed;
  }
}
