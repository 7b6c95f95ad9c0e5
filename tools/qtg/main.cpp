// fedsim-qtg: runs the Qualification Test Guide (data/qtg by default) and writes one report.
// Every test is flown by fedsim-fly, or (a federation test) by `fedsim run DEPLOYMENT
// --in-process` (child processes, arguments built from the validated test file), compared with
// its reference within Part 60 tolerances or its limits; exit 0 only if all passed. With
// --recording DIR the named tests are evaluated on a `fedsim run`'s recording instead of flown.
// Usage and format: docs/qtg.md, data/qtg/README.md.
#include <unistd.h>
#include "common/util/build_paths.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iomanip>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "common/util/child_process.hpp"
#include "common/util/config_node.hpp"
#include "tools/qtg/report.hpp"
#include "tools/qtg/runner.hpp"

namespace fs = std::filesystem;
using namespace fedsim::qtg;

namespace {

std::string own_folder() {
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "." : exe.parent_path().string();
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buf;
}

/// The chromium binary on PATH, or "".
std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    const char* path = std::getenv("PATH");
    std::string p = path ? path : "";
    std::size_t start = 0;
    while (start <= p.size()) {
      const auto end = p.find(':', start);
      const std::string dir = p.substr(start, end == std::string::npos ? std::string::npos : end - start);
      const fs::path candidate = fs::path(dir) / name;
      if (!dir.empty() && access(candidate.c_str(), X_OK) == 0) return candidate.string();
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  return "";
}

/// Prints the HTML to PDF with headless chromium; false (with a message) if it could not.
bool print_pdf(const std::string& chromium, const std::string& html, const std::string& pdf) {
  const std::string log = pdf + ".chromium.log";
  fedsim::util::ChildProcess c({chromium, "--headless", "--no-sandbox", "--disable-gpu",
                                "--no-pdf-header-footer", "--print-to-pdf=" + pdf,
                                "file://" + fs::absolute(html).string()},
                               log);
  if (!c.wait(120)) {
    c.kill_hard();
    c.wait(5);
    std::cerr << "qtg: chromium did not print the PDF in 120 s (log " << log << ")\n";
    return false;
  }
  if (c.exit_code() != 0 || !fs::exists(pdf)) {
    std::cerr << "qtg: chromium failed (exit " << c.exit_code() << ", log " << log << ")\n";
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fedsim-qtg: fly the Qualification Test Guide and write its report"};
  std::string out_dir = "out/qtg";
  std::string tests_dir = fedsim::util::source_dir() + "/data/qtg";
  std::vector<std::string> only;
  std::string fly = own_folder() + "/fedsim-fly";
  std::string fedsim = own_folder() + "/fedsim";
  std::string recording;
  std::string pdf_mode = "auto";
  bool record = false;
  int record_every = 1;
  app.add_option("--out", out_dir, "report folder (created): qtg_report.html, .pdf, runs/");
  app.add_option("--tests", tests_dir, "folder of test files (*.yaml, searched recursively)");
  app.add_option("--only", only, "run only the test(s) of this name (file stem); repeatable");
  app.add_option("--fly", fly, "the fedsim-fly program")->check(CLI::ExistingFile);
  app.add_option("--fedsim", fedsim, "the fedsim program (runs the federation tests in-process)")
      ->check(CLI::ExistingFile);
  app.add_option("--recording", recording,
                 "evaluate the --only test(s) on this recording (a fedsim run's --out folder: "
                 "fedsim_aircraft_state.csv, ...) instead of flying them")
      ->check(CLI::ExistingDirectory);
  app.add_option("--pdf", pdf_mode, "print the report to PDF with headless chromium")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_flag("--record-regression", record,
               "write the time-history reference of every regression test from this run "
               "(then review and commit it: it is fedsim's own output, not flight data)");
  app.add_option("--record-every", record_every, "record every Nth frame")->check(CLI::Range(1, 1000));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);  // prints the help or the problem
    return rc == 0 ? 0 : 2;      // a bad option (a missing --recording folder) is exit 2
  }
  if (!recording.empty() && only.empty()) {
    std::cerr << "qtg: --recording needs --only NAME (the test whose run it recorded)\n";
    return 2;
  }
  if (!recording.empty() && record) {
    std::cerr << "qtg: --record-regression flies the tests; it does not go with --recording\n";
    return 2;
  }

  const auto t0 = std::chrono::steady_clock::now();
  std::vector<QtgTest> tests;
  int load_errors = 0;
  std::vector<TestResult> results;
  try {
    // profiles, then deployments and scenarios named from the source tree (deploy/..., data/...)
    const std::vector<std::string> search = {tests_dir + "/profiles",
                                             fedsim::util::source_dir() + "/data/qtg/profiles",
                                             fedsim::util::source_dir() + "/data/profiles",
                                             fedsim::util::source_dir()};
    for (const auto& path : find_tests(tests_dir)) {
      const std::string stem = fs::path(path).stem().string();
      if (!only.empty() && std::find(only.begin(), only.end(), stem) == only.end()) continue;
      try {
        tests.push_back(load_test(path, search));
      } catch (const std::exception& e) {
        // a bad test file is a failed test, by name, in the report and the exit status
        std::cerr << "qtg: " << e.what() << '\n';
        TestResult bad;
        bad.test.name = stem;
        bad.test.path = path;
        bad.test.title = "(test file invalid)";
        bad.problem = e.what();
        results.push_back(bad);
        ++load_errors;
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "qtg: " << e.what() << '\n';
    return 2;
  }
  for (const auto& name : only) {
    const bool found = std::any_of(tests.begin(), tests.end(), [&](auto& t) { return t.name == name; }) ||
                       std::any_of(results.begin(), results.end(), [&](auto& r) { return r.test.name == name; });
    if (!found) {
      std::cerr << "qtg: --only " << name << ": no such test in " << tests_dir << '\n';
      return 2;
    }
  }
  if (tests.empty() && results.empty()) {
    std::cerr << "qtg: no tests in " << tests_dir << '\n';
    return 2;
  }
  fs::create_directories(recording.empty() ? out_dir + "/runs" : out_dir);
  const std::size_t total = tests.size();
  for (std::size_t i = 0; i < total; ++i) {
    const auto& t = tests[i];
    std::cerr << "qtg: [" << i + 1 << '/' << total << "] " << t.name << " (" << t.aircraft << ", "
              << t.duration_s << " s" << (recording.empty() ? "" : ", from the recording " + recording)
              << ") ..." << std::flush;
    TestResult r;
    if (recording.empty()) {
      r = run_test(t, {fly, fedsim}, out_dir + "/runs/" + t.name);
    } else {
      r = evaluate_recording(t, recording);
      r.from_recording = true;
    }
    std::cerr << (r.passed() ? " PASS" : " FAIL") << " (" << std::fixed << std::setprecision(2)
              << r.wall_s << " s)" << std::defaultfloat << std::setprecision(6) << '\n';
    if (!r.ran) std::cerr << "qtg:   " << r.problem << '\n';
    for (const auto& c : r.checks) {
      if (c.passed) continue;
      std::cerr << "qtg:   " << c.check.name << ": ";
      if (!c.problem.empty()) {
        std::cerr << c.problem << '\n';
      } else if (c.check.is_limit()) {
        const std::string unit = measure_unit(c.check) == "1" ? "" : " " + measure_unit(c.check);
        std::cerr << "measured " << *c.measured << unit << " at " << c.worst_time_s << " s, outside ";
        if (c.check.limit_min) std::cerr << *c.check.limit_min << " .. ";
        else std::cerr << "at most ";
        std::cerr << *c.check.limit_max << unit << " by " << c.worst_excursion << unit << '\n';
      } else {
        std::cerr << "worst excursion " << c.worst_excursion << " at " << c.worst_time_s << " s ("
                  << 100 * c.worst_ratio << " % of tolerance)\n";
      }
    }
    if (record && r.ran) {
      if (t.reference.kind == "regression") {
        const auto flown = channels_from_state_csv(r.out_dir + "/fedsim_aircraft_state.csv");
        const auto file = record_regression(r, flown, record_every);
        if (!file.empty()) std::cerr << "qtg:   recorded regression reference " << file << '\n';
      }
      // the values to paste into regression reference_value fields, after review
      for (const auto& c : r.checks)
        if (c.measured)
          std::cerr << "qtg:   measured " << c.check.name << " = " << std::setprecision(6)
                    << *c.measured << '\n';
    }
    results.push_back(std::move(r));
  }
  std::stable_sort(results.begin(), results.end(),
                   [](const TestResult& a, const TestResult& b) { return a.test.path < b.test.path; });

  ReportInfo info;
  info.generated_utc = utc_now();
  info.tests_dir = tests_dir;
  info.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string html = out_dir + "/qtg_report.html";
  {
    std::ofstream f(html);
    f << html_report(results, info);
    if (!f) {
      std::cerr << "qtg: cannot write " << html << '\n';
      return 1;
    }
  }
  int passed = 0;
  for (const auto& r : results) passed += r.passed();
  std::cerr << "qtg: " << passed << " of " << results.size() << " tests passed; report " << html
            << '\n';
  bool pdf_ok = true;
  if (pdf_mode != "off") {
    const std::string chromium = find_chromium();
    if (chromium.empty()) {
      std::cerr << "qtg: no chromium on PATH: no PDF (deploy/install-deps.sh installs it)\n";
      pdf_ok = pdf_mode == "auto";
    } else if (print_pdf(chromium, html, out_dir + "/qtg_report.pdf")) {
      std::cerr << "qtg: PDF " << out_dir << "/qtg_report.pdf\n";
    } else {
      pdf_ok = false;
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << "qtg: total " << std::fixed << std::setprecision(1) << wall << " s\n";
  return (passed == static_cast<int>(results.size()) && load_errors == 0 && pdf_ok) ? 0 : 1;
}
