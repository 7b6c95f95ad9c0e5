#include "tools/qtg/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "common/util/child_process.hpp"

namespace fedsim::qtg {
namespace fs = std::filesystem;

namespace {
std::string text(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}
}  // namespace

std::vector<std::string> fly_arguments(const QtgTest& t, const std::string& out_dir) {
  const auto& s = t.start;
  std::vector<std::string> a = {"--aircraft", t.aircraft, "--trim", s.trim, "--heading",
                                text(s.heading_deg), "--flaps", text(s.flaps)};
  if (s.trim == "ground") {
    a.insert(a.end(), {"--throttle", text(s.throttle), "--runway-elevation-m",
                       text(s.runway_elevation_m)});
  } else {
    a.insert(a.end(), {"--alt-ft", text(s.alt_ft)});
    if (s.ktas) a.insert(a.end(), {"--ktas", text(*s.ktas)});
    if (s.kcas) a.insert(a.end(), {"--kcas", text(*s.kcas)});
    if (s.trim == "climb") a.insert(a.end(), {"--gamma-deg", text(s.gamma_deg)});
    if (s.trim == "turn") a.insert(a.end(), {"--bank-deg", text(s.bank_deg)});
    if (s.runway_elevation_m != 0)
      a.insert(a.end(), {"--runway-elevation-m", text(s.runway_elevation_m)});
    if (s.gear_down) a.push_back("--gear-down");
  }
  if (!t.inputs.empty()) {
    a.insert(a.end(), {"--inputs", t.inputs});
    if (t.inputs_relative) a.push_back("--inputs-relative");
  }
  if (t.pilot == "stall_entry") {
    a.insert(a.end(), {"--pilot", "stall-entry", "--entry-rate-kt-s", text(t.pilot_entry_rate_kt_per_s),
                       "--pilot-throttle", text(t.pilot_throttle)});
  }
  a.insert(a.end(), {"--duration", text(t.duration_s), "--rate", text(t.rate_hz), "--out", out_dir,
                     "--quiet"});
  return a;
}

std::vector<std::string> federation_arguments(const QtgTest& t, const std::string& out_dir) {
  std::vector<std::string> a = {"run", t.federation->deployment, "--in-process", "--out", out_dir,
                                "--quiet", "--progress", "0"};
  if (!t.federation->scenario.empty()) a.insert(a.end(), {"--scenario", t.federation->scenario});
  return a;
}

std::set<ChannelSource> sources_needed(const QtgTest& test) {
  std::set<ChannelSource> out = {ChannelSource::aircraft_state};
  for (const auto& c : test.checks) {
    out.insert(channel_source(c.channel));
    if (!c.when_channel.empty()) out.insert(channel_source(c.when_channel));
    if (c.while_condition) out.insert(channel_source(c.while_condition->channel));
  }
  return out;
}

namespace {

/// Why a recorded file is not a whole run of the test ("" when it is).
std::string coverage_problem(const QtgTest& test, const RecordedFile& f) {
  std::ostringstream why;
  const std::vector<double>& t = f.t;
  const std::string& file = f.path;
  if (t.size() < 2) {
    why << file << ": fewer than two samples";
  } else if (t.front() > 1.0) {
    why << file << ": starts at " << t.front() << " s: not the whole run (it must start within 1 s)";
  } else if (t.back() < test.duration_s - 0.5) {
    why << file << ": ends at " << t.back() << " s, before the test's " << test.duration_s
        << " s: not a recording of the whole run";
  } else {
    std::vector<double> dt;
    for (std::size_t i = 1; i < t.size(); ++i) dt.push_back(t[i] - t[i - 1]);
    std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
    const double median = dt[dt.size() / 2];
    if (std::fabs(median * test.rate_hz - 1.0) > 0.01)
      why << file << ": frames " << median << " s apart, the test runs at " << test.rate_hz << " Hz";
  }
  return why.str();
}

}  // namespace

TestResult evaluate_recording(const QtgTest& test, const std::string& dir) {
  const auto start = std::chrono::steady_clock::now();
  TestResult r;
  r.test = test;
  r.out_dir = dir;
  try {
    std::vector<RecordedFile> files;
    const Channels flown = channels_from_recording(dir, sources_needed(test), test.runway, &files);
    for (const auto& f : files)
      if (r.problem.empty()) r.problem = coverage_problem(test, f);
    if (r.problem.empty()) {
      r.ran = true;
      r.checks = evaluate_test(test, flown);
    }
  } catch (const std::exception& e) {
    r.problem = std::string("reading the recording: ") + e.what();
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

TestResult run_test(const QtgTest& test, const Programs& programs, const std::string& out_dir) {
  TestResult r;
  r.test = test;
  r.out_dir = out_dir;
  const auto start = std::chrono::steady_clock::now();
  std::error_code ec;
  fs::remove_all(out_dir, ec);
  fs::create_directories(fs::path(out_dir).parent_path(), ec);
  const bool federation = test.federation.has_value();
  const std::string program = federation ? programs.fedsim : programs.fly;
  const std::string what = federation ? "fedsim run --in-process" : "fedsim-fly";
  std::vector<std::string> argv = {program};
  for (auto& s : federation ? federation_arguments(test, out_dir) : fly_arguments(test, out_dir))
    argv.push_back(s);
  const std::string log = out_dir + ".log";
  {
    util::ChildProcess child(argv, log);
    // a QTG run is seconds; ten minutes means something is stuck
    if (!child.wait(600)) {
      child.kill_hard();
      child.wait(5);
      r.problem = what + " did not finish in 600 s (log: " + log + ")";
      return r;
    }
    if (child.exit_code() != 0) {
      std::string out = child.output();
      if (out.size() > 600) out = "..." + out.substr(out.size() - 600);
      r.problem = child.exit_code() == 127
                      ? "could not run " + program + " (exit 127)"
                      : what + " exited with " + std::to_string(child.exit_code()) + ": " + out;
      return r;
    }
  }
  TestResult evaluated = evaluate_recording(test, out_dir);
  evaluated.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return evaluated;
}

std::string record_regression(const TestResult& result, const Channels& flown, int every) {
  const auto& t = result.test;
  std::vector<std::string> names;
  for (const auto& c : t.checks)
    if (c.measure == Measure::time_history &&
        std::find(names.begin(), names.end(), c.channel) == names.end())
      names.push_back(c.channel);
  if (names.empty() || t.reference.file.empty()) return "";
  const std::string comment =
      "REGRESSION REFERENCE: fedsim's own run, NOT flight data. It detects change in the model;\n"
      "it does not validate it. Written by fedsim-qtg --record-regression from test " +
      t.name + " (" + t.title + ").";
  write_reference_csv(t.reference.file, flown, names, comment, every);
  return t.reference.file;
}

}  // namespace fedsim::qtg
