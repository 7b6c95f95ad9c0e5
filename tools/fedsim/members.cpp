#include "fedsim/members.hpp"

#include "common/util/config_node.hpp"
#include "control_loading/control_loading_component.hpp"
#include "displays/displays_component.hpp"
#include "flight/federate/flight_program.hpp"
#include "io/io_component.hpp"
#include "ios/ios_station.hpp"
#include "motion/motion_component.hpp"
#include "nav/nav_component.hpp"
#include "scenario/scenario_component.hpp"
#include "synthetic/synthetic_component.hpp"
#include "timing/timing_component.hpp"
#include "visual/visual_component.hpp"

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace fedsim::launcher {

const std::map<std::string, runtime::FederateProgram (*)()>& component_programs() {
  static const std::map<std::string, runtime::FederateProgram (*)()> programs = {
      {"fedsim-timing", &timing::program},
      {"fedsim-io", &io::program},
      {"fedsim-flight", &flight::program},
      {"fedsim-nav", &nav::program},
      {"fedsim-motion", &motion::program},
      {"fedsim-control-loading", &control_loading::program},
      {"fedsim-synthetic", &synthetic::program},
      {"fedsim-visual", &visual::program},
      {"fedsim-displays", &displays::program},
      {"fedsim-scenario", &scenario::program},
      {"fedsim-ios", &ios::program},
  };
  return programs;
}

FederateSpec timing_spec(const Deployment& d) {
  FederateSpec spec;
  spec.name = "timing";
  spec.binary = "fedsim-timing";
  spec.lockstep = false;  // it makes the frames
  spec.args = {"--mode", d.mode, "--rate", std::to_string(d.rate_hz), "--shutdown-on-exit"};
  // Names are [A-Za-z0-9_-] (deployment.cpp): no comma splits one.
  std::string expect;
  for (const auto& f : d.federates) {
    if (f.lockstep) expect += (expect.empty() ? "" : ",") + f.name;
  }
  if (!expect.empty()) {
    spec.args.push_back("--expect");
    spec.args.push_back(expect);
  }
  spec.args.insert(spec.args.end(), d.timing_args.begin(), d.timing_args.end());
  return spec;
}

Members::Members(const Deployment& d, const std::map<std::string, std::string>& vars) : timing_(timing_spec(d)) {
  auto add = [&](const FederateSpec& spec, bool is_timing) {
    Member m{&spec, fs::path(spec.binary).filename().string(), {}, is_timing};
    for (const auto& a : spec.args) m.args.push_back(substitute(a, vars));
    members_.push_back(std::move(m));
  };
  for (const FederateSpec& f : d.federates) add(f, false);
  if (d.has_timing) add(timing_, true);
}

namespace {
/// CLI11 parses a vector of arguments given in reverse order.
void parse_args(CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  app.parse(reversed);
}
}  // namespace

std::unique_ptr<runtime::Component> build_component(const Deployment& d, const Member& member) {
  const auto it = component_programs().find(member.binary);
  if (it == component_programs().end()) return nullptr;
  const runtime::FederateProgram program = it->second();
  runtime::FederateOptions common;
  CLI::App app{program.program};
  runtime::add_federate_options(app, common, member.spec->name);
  program.add_options(app);
  // The sync QoS `fedsim run` gives every federate: after the member's own arguments (before
  // them for the timing member), as on its command line.
  std::vector<std::string> args = member.args;
  if (member.spec->federate_options) {
    const std::vector<std::string> sync{"--sync-qos", d.sync_qos};
    args.insert(member.is_timing ? args.begin() : args.end(), sync.begin(), sync.end());
  }
  try {
    parse_args(app, args);
  } catch (const CLI::ParseError& e) {
    throw util::ConfigError(d.file + ": federate '" + member.spec->name + "': " + e.what());
  }
  common.name = member.spec->name;
  return program.make_component(common);
}

std::optional<RecorderSpec> recorder_of(const Member& member) {
  if (member.binary != "fedsim" || member.args.empty() || member.args.front() != "record") return std::nullopt;
  RecorderSpec spec;
  std::string topics;
  CLI::App app{"record"};
  app.allow_extras();
  app.add_option("--topics", topics);
  app.add_option("--out", spec.out_dir);
  parse_args(app, std::vector<std::string>(member.args.begin() + 1, member.args.end()));
  std::stringstream in(topics);
  for (std::string t; std::getline(in, t, ',');) {
    if (!t.empty()) spec.topics.push_back(t);
  }
  return spec;
}

}  // namespace fedsim::launcher
