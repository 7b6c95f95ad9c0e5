#include "tools/qtg/runner.hpp"

#include <chrono>
#include <algorithm>
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
  }
  if (!t.inputs.empty()) {
    a.insert(a.end(), {"--inputs", t.inputs});
    if (t.inputs_relative) a.push_back("--inputs-relative");
  }
  a.insert(a.end(), {"--duration", text(t.duration_s), "--rate", text(t.rate_hz), "--out", out_dir,
                     "--quiet"});
  return a;
}

TestResult run_test(const QtgTest& test, const std::string& fly_program, const std::string& out_dir) {
  TestResult r;
  r.test = test;
  r.out_dir = out_dir;
  const auto start = std::chrono::steady_clock::now();
  std::error_code ec;
  fs::remove_all(out_dir, ec);
  fs::create_directories(fs::path(out_dir).parent_path(), ec);
  std::vector<std::string> argv = {fly_program};
  for (auto& s : fly_arguments(test, out_dir)) argv.push_back(s);
  const std::string log = out_dir + ".log";
  {
    util::ChildProcess fly(argv, log);
    // a QTG run is seconds; ten minutes means something is stuck
    if (!fly.wait(600)) {
      fly.kill_hard();
      fly.wait(5);
      r.problem = "fedsim-fly did not finish in 600 s (log: " + log + ")";
      return r;
    }
    if (fly.exit_code() != 0) {
      std::string out = fly.output();
      if (out.size() > 600) out = "..." + out.substr(out.size() - 600);
      r.problem = fly.exit_code() == 127
                      ? "could not run " + fly_program + " (exit 127)"
                      : "fedsim-fly exited with " + std::to_string(fly.exit_code()) + ": " + out;
      return r;
    }
  }
  try {
    const Channels flown = channels_from_state_csv(out_dir + "/fedsim_aircraft_state.csv");
    r.ran = true;
    r.checks = evaluate_test(test, flown);
  } catch (const std::exception& e) {
    r.problem = std::string("reading the recording: ") + e.what();
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
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
