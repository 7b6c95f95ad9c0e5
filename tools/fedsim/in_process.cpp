// `fedsim run --in-process`: the deployment's federates as components in one process.
#include "fedsim/in_process.hpp"

#include "common/runtime/composition.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/util/config_node.hpp"
#include "fedsim/launcher.hpp"
#include "flight/federate/flight_program.hpp"
#include "io/io_component.hpp"
#include "control_loading/control_loading_component.hpp"
#include "displays/displays_component.hpp"
#include "motion/motion_component.hpp"
#include "nav/nav_component.hpp"
#include "synthetic/synthetic_component.hpp"
#include "visual/visual_component.hpp"
#include "scenario/scenario_component.hpp"
#include "topic/in_process_recorder.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace fedsim::launcher {

const std::map<std::string, runtime::FederateProgram (*)()>& component_programs() {
  static const std::map<std::string, runtime::FederateProgram (*)()> programs = {
      {"fedsim-io", &io::program},
      {"fedsim-flight", &flight::program},
      {"fedsim-nav", &nav::program},
      {"fedsim-motion", &motion::program},
      {"fedsim-control-loading", &control_loading::program},
      {"fedsim-synthetic", &synthetic::program},
      {"fedsim-visual", &visual::program},
      {"fedsim-displays", &displays::program},
      {"fedsim-scenario", &scenario::program},
  };
  return programs;
}

namespace {

/// CLI11 parses a vector of arguments given in reverse order.
void parse_args(CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  app.parse(reversed);
}

struct RecorderSpec {
  std::vector<std::string> topics;
  std::string out_dir;
};

/// The arguments of a `fedsim record ...` member (the options that matter in-process; the
/// others, DDS and progress, are accepted and have no effect here).
RecorderSpec parse_recorder(const std::string& name, const std::vector<std::string>& args) {
  if (args.empty() || args.front() != "record") {
    throw util::ConfigError("federate '" + name + "': fedsim " +
                            (args.empty() ? std::string() : args.front()) +
                            " cannot run in-process (only fedsim record)");
  }
  RecorderSpec spec;
  std::string topics;
  CLI::App app{"record"};
  app.allow_extras();
  app.add_option("--topics", topics)->required();
  app.add_option("--out", spec.out_dir)->required();
  parse_args(app, std::vector<std::string>(args.begin() + 1, args.end()));
  std::stringstream in(topics);
  for (std::string t; std::getline(in, t, ',');) {
    if (!t.empty()) spec.topics.push_back(t);
  }
  return spec;
}

std::uint64_t frames_of(const Deployment& d, const std::vector<std::string>& timing_args) {
  std::uint64_t frames = 0;
  std::string start = "run";
  CLI::App app{"timing"};
  app.allow_extras();
  app.add_option("--frames", frames);
  app.add_option("--start", start);
  parse_args(app, timing_args);
  if (frames == 0) {
    throw util::ConfigError(d.file + ": timing: args: an in-process run needs --frames N");
  }
  if (start != "run") throw util::ConfigError(d.file + ": timing: args: --start " + start +
                                              " is not supported in-process");
  return frames;
}

}  // namespace

int run_in_process(const RunOptions& options) {
  runtime::install_shutdown_handler();
  const auto files_since = fs::file_time_type::clock::now();  // what an after-step needs is newer
  Deployment d;
  std::map<std::string, std::string> vars;
  std::string out_dir;
  std::vector<std::unique_ptr<runtime::Component>> components;
  std::vector<RecorderSpec> recorders;
  std::uint64_t frames = 0;
  try {
    d = load_with_scenario(options);
    out_dir = options.out_dir.empty() ? "out/" + d.name : options.out_dir;
    fs::create_directories(out_dir + "/logs");
    vars = deployment_vars(options.deployment_path, out_dir);
    std::vector<std::string> timing_args;
    for (const auto& a : d.timing_args) timing_args.push_back(substitute(a, vars));
    frames = frames_of(d, timing_args);
    for (const FederateSpec& f : d.federates) {
      std::vector<std::string> args;
      for (const auto& a : f.args) args.push_back(substitute(a, vars));
      const std::string binary = fs::path(f.binary).filename().string();
      if (binary == "fedsim") {
        recorders.push_back(parse_recorder(f.name, args));
        continue;
      }
      if (binary == "fedsim-ios") {
        // The instructor station is a page on a live federation: nothing to step in-process.
        std::cout << "fedsim run --in-process: " << f.name << " (fedsim-ios) needs a live federation; not run\n";
        continue;
      }
      const auto it = component_programs().find(binary);
      if (it == component_programs().end()) {
        throw util::ConfigError(d.file + ": federate '" + f.name + "': " + binary +
                                " is not a component program and cannot run in-process");
      }
      runtime::FederateProgram program = it->second();
      runtime::FederateOptions common;
      CLI::App app{program.program};
      runtime::add_federate_options(app, common, f.name);
      program.add_options(app);
      try {
        parse_args(app, args);
      } catch (const CLI::ParseError& e) {
        throw util::ConfigError(d.file + ": federate '" + f.name + "': " + e.what());
      }
      common.name = f.name;
      components.push_back(program.make_component(common));
    }
  } catch (const runtime::ProgramError& e) {
    std::cerr << "fedsim run: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "fedsim run: " << e.what() << "\n";
    return 2;
  }

  runtime::Composition composition({d.rate_hz, false});
  for (auto& c : components) composition.add(*c);
  // What a member writes on fedsim/sim_command (a scenario's commands) goes to everyone, as over DDS.
  composition.on_written(runtime::topics::sim_command, std::function<void(const msg::SimCommand&)>(
                                                           [&composition](const msg::SimCommand& c) { composition.command(c); }));
  std::vector<std::unique_ptr<tools::InProcessRecorder>> recording;
  try {
    for (const RecorderSpec& r : recorders) {
      recording.push_back(std::make_unique<tools::InProcessRecorder>(composition, r.topics, r.out_dir));
    }
  } catch (const std::exception& e) {
    std::cerr << "fedsim run: " << e.what() << "\n";
    return 2;
  }
  for (const auto& topic : composition.unwritten_topics()) {
    std::cout << "fedsim run: note: " << topic << " is read but no federate writes it\n";
  }
  std::cout << "fedsim run: " << d.name << " in-process, lockstep, " << frames << " frames at "
            << d.rate_hz << " Hz, " << components.size() << " components\n";
  const auto start = std::chrono::steady_clock::now();
  auto next_progress = start + std::chrono::duration<double>(options.progress_period_s);
  bool failed = false;
  std::uint64_t done = 0;
  try {
    done = composition.run(frames, [&](const runtime::FrameContext& frame) {
      for (auto& r : recording) r->drain();
      if (runtime::shutdown_requested()) {
        msg::SimCommand stop;
        stop.kind(msg::COMMAND_SHUTDOWN);
        composition.command(stop);
      }
      if (options.progress_period_s > 0 && std::chrono::steady_clock::now() >= next_progress) {
        next_progress += std::chrono::duration<double>(options.progress_period_s);
        std::cout << "fedsim run: progress frame " << frame.frame + 1 << " of " << frames
                  << ", sim " << frame.sim_time_s << " s\n";
      }
    });
    composition.stop();
    for (auto& r : recording) r->close();
  } catch (const std::exception& e) {
    std::cerr << "fedsim run: frame " << composition.last_frame().frame << " failed: " << e.what()
              << "\n";
    failed = true;
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "fedsim run: " << done << " frames in " << wall_s << " s ("
            << (wall_s > 0 ? done / wall_s : 0.0) << " frames/s)\n";
  for (const auto& c : components) {
    for (const auto& f : c->faults()) {
      std::cout << "  FAULT  " << c->name() << " " << f.kind << " x" << f.count << ": " << f.last
                << "\n";
      failed = true;
    }
  }
  for (const auto& r : recording) {
    for (const auto& rec : r->recorded()) {
      std::cout << "  recorded " << rec.topic << ": " << rec.samples << " samples -> "
                << rec.file.string() << "\n";
    }
  }
  // Fewer frames than asked: Ctrl-C / SIGTERM (interrupted: no plots, exit 130), or a member's
  // SHUTDOWN command (a scenario's stop: the run is over as it says, and the plots are drawn).
  const bool interrupted = runtime::shutdown_requested();
  if (interrupted) {
    std::cout << "fedsim run: interrupted after " << done << " frames\n";
  } else if (done < frames) {
    std::cout << "fedsim run: stopped after " << done << " frames by a shutdown command (a scenario's stop)\n";
  }
  if (!failed && !interrupted && !d.after.empty()) {
    // In-process runs have no --duration: the run always reaches its own end.
    const RunEnd end{files_since, ""};
    if (run_after_commands(d, vars, bin_dir(), out_dir + "/logs", options.quiet, end) != 0) failed = true;
  }
  std::cout << "fedsim run: " << (failed ? "FAILED" : interrupted ? "interrupted" : "done") << "\n";
  return failed ? 1 : interrupted ? 130 : 0;
}

}  // namespace fedsim::launcher
