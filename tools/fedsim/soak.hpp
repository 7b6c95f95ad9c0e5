// `fedsim soak`: runs a whole federation in realtime (through `fedsim run`, as a user would) for
// a set time and checks it stays healthy: frames and overruns from the timing federate's summary,
// samples lost (frame-stamp gaps in every topic the recorder wrote), each federate's resident
// memory (VmRSS) after a warm-up and at the end. Its last output line is one JSON object; the exit
// status is 1 when a threshold is exceeded or the run failed (each failure named), 2 on bad input.
//
//   fedsim soak --duration 180 [--deployment deploy/soak.yaml] [--warmup 60]
//               [--max-rss-growth-pct 5] [--max-lost 0] [--domain D] [--out DIR]
// It also writes DIR/soak_rss.csv (every RSS sample) and DIR/soak_run.log (fedsim run's output).
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace fedsim::launcher {

struct SoakOptions {
  std::string deployment;           // "" = ${SOURCE_DIR}/deploy/soak.yaml
  double duration_s = 0.0;          // whole run, warm-up included
  double warmup_s = 60.0;           // RSS "start" is sampled at this time (allocators settle)
  double sample_period_s = 5.0;     // RSS sampling period
  double max_rss_growth_pct = 5.0;  // per federate, start -> end
  std::uint64_t max_lost = 0;       // samples lost over all recorded topics
  int domain = -1;                  // -1 = as `fedsim run` picks it
  std::string out_dir = "out/soak";
};

/// VmRSS in kB from the text of /proc/<pid>/status; nullopt if absent or malformed.
std::optional<std::int64_t> parse_vm_rss_kb(const std::string& proc_status_text);

/// Frame-stamp continuity of one recorded topic (a recorder CSV with a `stamp.frame` column),
/// per instance (`aircraft_id` when the topic has one). Frames before an instance's first sample
/// are not counted (it joined then); each frame missing between two samples is one lost sample;
/// a frame stamp that did not increase is counted as repeated (not lost).
struct FrameGaps {
  std::uint64_t samples = 0;
  std::uint64_t lost = 0;
  std::uint64_t repeated = 0;
  std::int64_t first_frame = -1;
  std::int64_t last_frame = -1;
};
/// Throws std::runtime_error naming `origin` when the CSV has no `stamp.frame` column or a row's
/// frame is not a number.
FrameGaps count_frame_gaps(std::istream& csv, const std::string& origin);

/// One federate's resident memory: at the first sample after the warm-up and at the last one.
struct RssSamples {
  std::int64_t start_kb = -1;  // -1 = not sampled (the federate was gone before the warm-up ended)
  std::int64_t end_kb = -1;
  std::int64_t peak_kb = -1;
  double growth_pct() const;
};

struct SoakResult {
  int run_exit = -1;                              // `fedsim run`'s exit status
  std::optional<nlohmann::json> timing_summary;   // the timing federate's summary line
  std::map<std::string, FrameGaps> topics;        // recorder CSV file -> gaps
  std::vector<std::string> topic_errors;          // CSVs that could not be read
  std::map<std::string, RssSamples> rss;          // federate name -> RSS
  double measured_s = 0.0;                        // wall time the federation ran
};

/// Every threshold the result exceeds, by name ("lost_samples: 3 > 0", "rss_growth: flight
/// +7.2% > 5%", "run_failed: exit 1", ...); empty = healthy.
std::vector<std::string> soak_failures(const SoakResult& result, const SoakOptions& options);

/// The one-line JSON report: frames, overruns, period error, lost samples (total and per topic),
/// RSS per federate at start and end, failures.
nlohmann::json soak_report(const SoakResult& result, const SoakOptions& options,
                           const std::vector<std::string>& failures);

/// Checks the options (finite, warm-up shorter than the run); throws std::invalid_argument.
void check_soak_options(const SoakOptions& options);

/// Runs the soak; returns the exit status (0 healthy, 1 failed, 2 bad options or deployment).
int run_soak(const SoakOptions& options, std::ostream& out, std::ostream& err);

/// Registers `fedsim soak` on the app; its result goes to exit_code.
void add_soak_command(CLI::App& app, int& exit_code);

}  // namespace fedsim::launcher
