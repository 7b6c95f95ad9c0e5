// `fedsim run --in-process`: the deployment's federates as components in one process.
#include "fedsim/launcher.hpp"

#include "common/runtime/composition.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/util/config_node.hpp"
#include "fedsim/launcher.hpp"
#include "fedsim/members.hpp"
#include "timing/timing_component.hpp"
#include "topic/in_process_recorder.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace fedsim::launcher {

namespace {

/// A `fedsim record` member in-process: its topics and folder (the DDS options have no effect).
RecorderSpec recorder_in_process(const Deployment& d, const Member& m) {
  const auto spec = recorder_of(m);
  if (!spec) {
    throw util::ConfigError(d.file + ": federate '" + m.spec->name + "': fedsim " +
                            (m.args.empty() ? std::string() : m.args.front()) +
                            " cannot run in-process (only fedsim record)");
  }
  if (spec->topics.empty() || spec->out_dir.empty()) {
    throw util::ConfigError(d.file + ": federate '" + m.spec->name + "': fedsim record needs --topics and --out");
  }
  return *spec;
}

/// The frame clock's settings for the composition, from the timing member's own options.
const timing::TimingOptions& clock_of(const Deployment& d, const runtime::Component* timing) {
  const auto* clock = dynamic_cast<const timing::TimingComponent*>(timing);
  if (!clock || clock->options().common.max_frames == 0) {
    throw util::ConfigError(d.file + ": timing: args: an in-process run needs --frames N");
  }
  return clock->options();
}

}  // namespace

int run_in_process(const RunOptions& options) {
  runtime::install_shutdown_handler();
  const auto files_since = fs::file_time_type::clock::now();  // what an after-step needs is newer
  Deployment d;
  std::map<std::string, std::string> vars;
  std::string out_dir;
  std::vector<std::unique_ptr<runtime::Component>> components;
  std::vector<bool> required;  // of each component
  std::vector<RecorderSpec> recorders;
  std::unique_ptr<runtime::Component> timing;
  try {
    d = load_with_scenario(options);
    out_dir = options.out_dir.empty() ? "out/" + d.name : options.out_dir;
    fs::create_directories(out_dir + "/logs");
    vars = deployment_vars(options.deployment_path, out_dir);
    const Members members(d, vars);
    for (const Member& m : members.all()) {
      if (m.binary == "fedsim") {
        recorders.push_back(recorder_in_process(d, m));
        continue;
      }
      auto component = build_component(d, m);
      if (!component) {
        throw util::ConfigError(d.file + ": federate '" + m.spec->name + "': " + m.binary +
                                " is not a component program and cannot run in-process");
      }
      if (m.is_timing) {  // the composition is the frame clock: it takes the clock's settings
        timing = std::move(component);
        continue;
      }
      components.push_back(std::move(component));
      required.push_back(m.spec->required);
    }
    clock_of(d, timing.get());
  } catch (const runtime::ProgramError& e) {
    std::cerr << "fedsim run: " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << "fedsim run: " << e.what() << "\n";
    return 2;
  }
  const timing::TimingOptions& clock = clock_of(d, timing.get());
  const std::uint64_t frames = clock.common.max_frames;

  runtime::Composition composition({clock.rate_hz, clock.start == "freeze"});
  for (std::size_t i = 0; i < components.size(); ++i) {
    try {
      composition.add(*components[i]);  // starts it: the station opens its page
    } catch (const std::exception& e) {
      std::cerr << "fedsim run: " << components[i]->name() << " cannot start: " << e.what() << "\n";
      if (required[i]) return 2;
      std::cout << "fedsim run: " << components[i]->name() << " is not required: running without it\n";
      components[i].reset();
    }
  }
  std::erase(components, nullptr);
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
  std::string monitored;
  for (const auto& topic : composition.unwritten_monitored_topics()) monitored += (monitored.empty() ? "" : ", ") + topic;
  if (!monitored.empty()) std::cout << "fedsim run: note: monitored, but no federate writes them here: " << monitored << "\n";
  std::cout << "fedsim run: " << d.name << " in-process, lockstep, " << frames << " frames at "
            << clock.rate_hz << " Hz, " << components.size() << " components\n";
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
