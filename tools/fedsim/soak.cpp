#include "fedsim/soak.hpp"
#include "common/util/build_paths.hpp"

#include "common/runtime/shutdown.hpp"
#include "common/util/child_process.hpp"
#include "common/util/cli_checks.hpp"
#include "fedsim/launcher.hpp"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace fedsim::launcher {

namespace fs = std::filesystem;

namespace {

/// One CSV line split into fields; a quoted field may hold commas and doubled quotes (the
/// recorder quotes string fields).
std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

std::int64_t parse_frame(const std::string& text, const std::string& where) {
  std::size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < 0) {
    throw std::runtime_error(where + ": stamp.frame '" + text + "' is not a frame number");
  }
  return value;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A child of `parent` that the launcher started: its pid and federate name (the --name it was
/// given, else its program's file name).
struct FederateProcess {
  pid_t pid;
  std::string name;
};

std::vector<std::string> proc_cmdline(pid_t pid) {
  const std::string text = read_file("/proc/" + std::to_string(pid) + "/cmdline");
  std::vector<std::string> args;
  std::string arg;
  for (char c : text) {
    if (c == '\0') {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += c;
    }
  }
  return args;
}

std::vector<FederateProcess> children_of(pid_t parent) {
  std::vector<FederateProcess> result;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string dir = entry.path().filename().string();
    if (dir.find_first_not_of("0123456789") != std::string::npos) continue;
    // /proc/<pid>/stat: "pid (comm) state ppid ..."; comm may hold spaces: parse after ')'.
    const std::string stat = read_file(entry.path() / "stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 1));
    std::string state;
    long ppid = -1;
    rest >> state >> ppid;
    if (ppid != parent) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(dir));
    const auto args = proc_cmdline(pid);
    if (args.empty()) continue;
    std::string name = fs::path(args[0]).filename().string();
    for (std::size_t i = 0; i + 1 < args.size(); ++i) {
      if (args[i] == "--name") name = args[i + 1];
    }
    result.push_back({pid, name});
  }
  return result;
}

std::optional<std::int64_t> rss_of(pid_t pid) {
  return parse_vm_rss_kb(read_file("/proc/" + std::to_string(pid) + "/status"));
}

/// The timing federate prints its summary as a JSON line when it stops (federates/timing).
std::optional<nlohmann::json> last_summary_line(const fs::path& log) {
  std::ifstream in(log);
  std::optional<nlohmann::json> found;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.front() != '{') continue;
    auto j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_object() && j.contains("frames")) found = std::move(j);
  }
  return found;
}

void read_recorded_topics(const fs::path& out_dir, SoakResult& result) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out_dir, ec)) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() != ".csv" || file.rfind("fedsim_", 0) != 0) continue;
    std::ifstream in(entry.path());
    try {
      result.topics[file] = count_frame_gaps(in, entry.path().string());
    } catch (const std::exception& e) {
      result.topic_errors.push_back(e.what());
    }
  }
}

}  // namespace

std::optional<std::int64_t> parse_vm_rss_kb(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("VmRSS:", 0) != 0) continue;
    std::istringstream fields(line.substr(6));
    std::int64_t kb = -1;
    std::string unit;
    if (!(fields >> kb >> unit) || kb < 0 || unit != "kB") return std::nullopt;
    return kb;
  }
  return std::nullopt;
}

FrameGaps count_frame_gaps(std::istream& csv, const std::string& origin) {
  std::string line;
  if (!std::getline(csv, line)) throw std::runtime_error(origin + ": empty file (no header)");
  const auto header = split_csv_line(line);
  std::optional<std::size_t> frame_col, instance_col;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "stamp.frame") frame_col = i;
    if (header[i] == "aircraft_id") instance_col = i;
  }
  if (!frame_col) throw std::runtime_error(origin + ": no stamp.frame column");
  FrameGaps gaps;
  std::map<std::string, std::int64_t> last_by_instance;
  for (std::size_t row = 2; std::getline(csv, line); ++row) {
    if (line.empty()) continue;
    const auto fields = split_csv_line(line);
    const std::string where = origin + ":" + std::to_string(row);
    if (fields.size() <= *frame_col) throw std::runtime_error(where + ": too few fields");
    const std::int64_t frame = parse_frame(fields[*frame_col], where);
    const std::string instance =
        instance_col && fields.size() > *instance_col ? fields[*instance_col] : "";
    ++gaps.samples;
    if (gaps.first_frame < 0 || frame < gaps.first_frame) gaps.first_frame = frame;
    gaps.last_frame = std::max(gaps.last_frame, frame);
    auto it = last_by_instance.find(instance);
    if (it == last_by_instance.end()) {
      last_by_instance.emplace(instance, frame);
      continue;
    }
    if (frame <= it->second) {
      ++gaps.repeated;
      continue;
    }
    gaps.lost += static_cast<std::uint64_t>(frame - it->second - 1);
    it->second = frame;
  }
  return gaps;
}

double RssSamples::growth_pct() const {
  if (start_kb <= 0 || end_kb < 0) return 0.0;
  return 100.0 * static_cast<double>(end_kb - start_kb) / static_cast<double>(start_kb);
}

std::vector<std::string> soak_failures(const SoakResult& result, const SoakOptions& options) {
  std::vector<std::string> failures;
  if (result.run_exit != 0) {
    failures.push_back("run_failed: fedsim run exit " + std::to_string(result.run_exit) +
                       " (its log names the federate)");
  }
  if (!result.timing_summary) {
    failures.push_back("no_timing_summary: the timing federate printed no summary");
  } else if (result.timing_summary->value("frames", 0) == 0) {
    failures.push_back("no_frames: the timing federate ticked no frame");
  }
  if (result.timing_summary && result.timing_summary->contains("lost") &&
      !(*result.timing_summary)["lost"].empty()) {
    failures.push_back("federates_lost: " + (*result.timing_summary)["lost"].dump());
  }
  if (result.topics.empty()) failures.push_back("no_recorded_topics: nothing to count gaps in");
  for (const auto& e : result.topic_errors) failures.push_back("unreadable_topic: " + e);
  std::uint64_t lost = 0;
  for (const auto& [file, gaps] : result.topics) lost += gaps.lost;
  if (lost > options.max_lost) {
    failures.push_back("lost_samples: " + std::to_string(lost) + " > " +
                       std::to_string(options.max_lost));
  }
  for (const auto& [name, rss] : result.rss) {
    if (rss.start_kb < 0 || rss.end_kb < 0) {
      failures.push_back("rss_unmeasured: " + name + " (gone before the warm-up ended)");
      continue;
    }
    const double growth = rss.growth_pct();
    if (growth > options.max_rss_growth_pct) {
      char text[160];
      std::snprintf(text, sizeof(text), "rss_growth: %s %+.1f%% > %.1f%%", name.c_str(), growth,
                    options.max_rss_growth_pct);
      failures.push_back(text);
    }
  }
  if (result.rss.empty()) failures.push_back("rss_unmeasured: no federate process found");
  return failures;
}

nlohmann::json soak_report(const SoakResult& result, const SoakOptions& options,
                           const std::vector<std::string>& failures) {
  nlohmann::json j;
  j["soak"] = failures.empty() ? "ok" : "FAILED";
  j["duration_s"] = options.duration_s;
  j["warmup_s"] = options.warmup_s;
  j["measured_s"] = std::round(result.measured_s * 10.0) / 10.0;
  const auto& t = result.timing_summary;
  j["frames"] = t ? t->value("frames", 0) : 0;
  j["overruns"] = t ? t->value("overruns", 0) : 0;
  j["frames_per_s"] = t ? t->value("frames_per_s", 0.0) : 0.0;
  j["period_error_us"] = t && t->contains("period_error_us") ? (*t)["period_error_us"]
                                                              : nlohmann::json::object();
  std::uint64_t lost = 0;
  nlohmann::json topics = nlohmann::json::object();
  for (const auto& [file, g] : result.topics) {
    lost += g.lost;
    topics[file] = {{"samples", g.samples}, {"lost", g.lost}, {"repeated", g.repeated},
                    {"first_frame", g.first_frame}, {"last_frame", g.last_frame}};
  }
  j["lost_samples"] = lost;
  j["topics"] = topics;
  nlohmann::json rss = nlohmann::json::object();
  for (const auto& [name, r] : result.rss) {
    rss[name] = {{"start_kb", r.start_kb}, {"end_kb", r.end_kb}, {"peak_kb", r.peak_kb},
                 {"growth_pct", std::round(r.growth_pct() * 100.0) / 100.0}};
  }
  j["rss"] = rss;
  j["thresholds"] = {{"max_lost", options.max_lost},
                     {"max_rss_growth_pct", options.max_rss_growth_pct}};
  j["run_exit"] = result.run_exit;
  j["failures"] = failures;
  return j;
}

void check_soak_options(const SoakOptions& o) {
  auto finite = [](double v, const char* name, double min) {
    if (!std::isfinite(v) || v < min) {
      char text[160];
      std::snprintf(text, sizeof(text), "%s: %g is not a finite number >= %g", name, v, min);
      throw std::invalid_argument(text);
    }
  };
  finite(o.duration_s, "--duration", 1.0);
  finite(o.warmup_s, "--warmup", 0.0);
  finite(o.sample_period_s, "--sample-period", 0.1);
  finite(o.max_rss_growth_pct, "--max-rss-growth-pct", 0.0);
  if (o.warmup_s + o.sample_period_s > o.duration_s) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "--warmup (%g s) plus one --sample-period (%g s) must be shorter than "
                  "--duration (%g s): nothing would be measured",
                  o.warmup_s, o.sample_period_s, o.duration_s);
    throw std::invalid_argument(text);
  }
}

int run_soak(const SoakOptions& options, std::ostream& out, std::ostream& err) {
  try {
    check_soak_options(options);
  } catch (const std::invalid_argument& e) {
    err << "fedsim soak: " << e.what() << "\n";
    return 2;
  }
  const std::string deployment = options.deployment.empty()
                                     ? fedsim::util::source_dir() + "/deploy/soak.yaml"
                                     : options.deployment;
  if (!fs::is_regular_file(deployment)) {
    err << "fedsim soak: deployment '" << deployment << "' not found\n";
    return 2;
  }
  try {
    load_deployment(deployment);  // its errors now (file:line), not in fedsim run's log
  } catch (const std::exception& e) {
    err << "fedsim soak: " << e.what() << "\n";
    return 2;
  }
  std::error_code ec;
  fs::create_directories(options.out_dir, ec);
  // A previous run's recordings and summary would be counted as this run's.
  for (const auto& entry : fs::directory_iterator(options.out_dir, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.rfind("fedsim_", 0) == 0 && entry.path().extension() == ".csv") fs::remove(entry, ec);
  }
  fs::remove(fs::path(options.out_dir) / "logs" / "timing.log", ec);
  ec.clear();
  fs::create_directories(options.out_dir, ec);
  if (ec) {
    err << "fedsim soak: cannot create " << options.out_dir << ": " << ec.message() << "\n";
    return 2;
  }
  std::vector<std::string> args = {bin_dir() + "/fedsim", "run", deployment, "--mode", "realtime",
                                   "--duration", std::to_string(options.duration_s), "--out",
                                   options.out_dir, "--quiet", "--progress", "0"};
  if (options.domain >= 0) {
    args.insert(args.end(), {"--domain", std::to_string(options.domain)});
  }
  const fs::path run_log = fs::path(options.out_dir) / "soak_run.log";
  runtime::install_shutdown_handler();
  SoakResult result;
  const auto start = std::chrono::steady_clock::now();
  util::ChildProcess run(args, run_log.string());
  err << "fedsim soak: " << options.duration_s << " s realtime (RSS start after a "
      << options.warmup_s << " s warm-up); fedsim run's output in " << run_log.string() << "\n";
  const auto period = std::chrono::milliseconds(static_cast<long long>(options.sample_period_s * 1e3));
  auto next_sample = start + period;
  // Every RSS sample, for a plot of growth over time (a plateau vs a leak).
  std::ofstream rss_csv(fs::path(options.out_dir) / "soak_rss.csv");
  rss_csv << "t_s,federate,rss_kb\n";
  bool interrupted = false;
  while (!run.wait(0.0)) {
    if (runtime::shutdown_requested() && !interrupted) {
      interrupted = true;
      kill(run.pid(), SIGINT);  // fedsim run stops its federates cleanly and reports
    }
    const auto now = std::chrono::steady_clock::now();
    if (now >= next_sample) {
      next_sample += period;
      const double t = std::chrono::duration<double>(now - start).count();
      for (const auto& f : children_of(run.pid())) {
        const auto kb = rss_of(f.pid);
        if (!kb) continue;
        rss_csv << t << "," << f.name << "," << *kb << "\n";
        auto& r = result.rss[f.name];
        if (t >= options.warmup_s && r.start_kb < 0) r.start_kb = *kb;
        if (r.start_kb >= 0) r.end_kb = *kb;
        r.peak_kb = std::max(r.peak_kb, *kb);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  result.measured_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // 128 + signal when a signal ended it, as a shell says
  result.run_exit = run.exit_code() < 0 ? 128 - run.exit_code() : run.exit_code();
  result.timing_summary = last_summary_line(fs::path(options.out_dir) / "logs" / "timing.log");
  read_recorded_topics(options.out_dir, result);
  auto failures = soak_failures(result, options);
  if (interrupted) failures.insert(failures.begin(), "interrupted: stopped before --duration");
  for (const auto& f : failures) err << "fedsim soak: FAILED " << f << "\n";
  out << soak_report(result, options, failures).dump() << "\n";
  out.flush();
  return failures.empty() ? 0 : 1;
}

void add_soak_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SoakOptions>();
  auto* cmd = app.add_subcommand(
      "soak", "run the federation in realtime for a while and check frames, lost samples and "
              "memory (last line: JSON; exit 1 on a failure)");
  cmd->add_option("--duration", options->duration_s, "seconds to run, warm-up included")
      ->required()
      ->check(fedsim::util::FiniteRange(1, 7 * 24 * 3600));
  cmd->add_option("--deployment", options->deployment,
                  "deployment file (default: deploy/soak.yaml, the default federation)");
  cmd->add_option("--warmup", options->warmup_s,
                  "seconds before the RSS start sample (allocators and discovery settle)")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  cmd->add_option("--sample-period", options->sample_period_s, "seconds between RSS samples")
      ->check(fedsim::util::FiniteRange(0.1, 3600))
      ->capture_default_str();
  cmd->add_option("--max-rss-growth-pct", options->max_rss_growth_pct,
                  "fail when a federate's RSS grows more than this from start to end [%]")
      ->check(fedsim::util::FiniteRange(0, 10000))
      ->capture_default_str();
  cmd->add_option("--max-lost", options->max_lost,
                  "fail when more samples than this are lost (frame gaps in recorded topics)")
      ->capture_default_str();
  cmd->add_option("--domain", options->domain, "DDS domain (default: as fedsim run picks it)")
      ->check(fedsim::util::FiniteRange(0, 232));
  cmd->add_option("--out", options->out_dir, "output folder (its old recordings are removed)")
      ->capture_default_str();
  cmd->callback([options, &exit_code] { exit_code = run_soak(*options, std::cout, std::cerr); });
}

}  // namespace fedsim::launcher
