#include "fedsim/launcher.hpp"
#include "fedsim/members.hpp"
#include "common/util/build_paths.hpp"

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/federate_options.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/runtime/subscription.hpp"
#include "common/util/config_node.hpp"
#include "common/util/monotonic_clock.hpp"
#include "common/scenario/scenario.hpp"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace fedsim::launcher {

namespace {

struct Child {
  std::string name;
  std::vector<std::string> argv;
  bool required = true;
  bool lockstep = false;         // in the timing federate's --expect list
  bool timing = false;           // the timing federate itself
  pid_t pid = -1;                // also its process group id (see start_child)
  int out_fd = -1;
  std::string partial_line;
  std::ofstream log;
  bool exited = false;
  int status = 0;
  bool sent_term = false;        // it was alive when we sent SIGTERM (its death by it is clean)
  bool group_signalled = false;  // its process group got our SIGTERM
  bool group_gone = false;       // no process of its group is left
  bool restart_on_failure = false;  // deployment: restart: on-failure
  int max_restarts = 0;
  std::vector<std::string> crashes;  // how each restarted process ended, in order
  std::string log_path;

  /// Exited, and nothing it started still writes to its output.
  bool finished() const { return exited && out_fd < 0; }
};

using Children = std::vector<std::unique_ptr<Child>>;

/// stderr, after what stdout holds so far: the two stay in order in a log or a pipe.
std::ostream& warn() {
  std::cout.flush();
  return std::cerr << "fedsim run: ";
}

std::string self_dir() {
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "." : exe.parent_path().string();
}

bool is_executable(const fs::path& p) { return fs::is_regular_file(p) && access(p.c_str(), X_OK) == 0; }

std::string resolve_binary(const std::string& binary, const std::string& bin_dir,
                           const std::string& hint = " (did the build finish?)") {
  if (binary.find('/') != std::string::npos) {
    if (is_executable(binary)) return binary;
    throw util::ConfigError("binary not found or not executable: " + binary);
  }
  if (is_executable(fs::path(bin_dir) / binary)) return (fs::path(bin_dir) / binary).string();
  if (const char* path = std::getenv("PATH")) {
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
      if (!dir.empty() && is_executable(fs::path(dir) / binary)) return (fs::path(dir) / binary).string();
    }
  }
  throw util::ConfigError("binary '" + binary + "' not found in " + bin_dir + " or PATH" + hint);
}

std::string describe_exit(int status) {
  if (WIFEXITED(status)) return "exit " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return std::string("killed by ") + strsignal(WTERMSIG(status));
  return "unknown";
}

/// A child stopped cleanly: exit 0, or terminated by the SIGTERM we sent.
bool clean_exit(const Child& c) {
  if (WIFEXITED(c.status)) return WEXITSTATUS(c.status) == 0;
  return c.sent_term && WIFSIGNALED(c.status) && WTERMSIG(c.status) == SIGTERM;
}

void start_child(Child& child, const std::string& log_path, bool append_log = false) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    dup2(fds[1], STDOUT_FILENO);
    dup2(fds[1], STDERR_FILENO);
    // Its own process group: Ctrl-C reaches the launcher only (it stops the children), and the
    // launcher's signals reach everything the federate started (a script's children too).
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // and if the launcher dies, they stop too
    sigset_t all;
    sigemptyset(&all);
    sigprocmask(SIG_SETMASK, &all, nullptr);  // the launcher blocks SIGINT/SIGTERM; undo that
    std::vector<char*> argv;
    for (auto& a : child.argv) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    std::fprintf(stderr, "cannot execute %s: %s\n", argv[0], std::strerror(errno));
    _exit(127);
  }
  setpgid(pid, pid);  // here too, so that a signal sent at once already finds the group
  close(fds[1]);
  child.pid = pid;
  child.out_fd = fds[0];
  child.log_path = log_path;
  if (!child.log.is_open()) child.log.open(log_path, append_log ? std::ios::app : std::ios::trunc);
}

/// Signals every process of the child's group: SIGKILL to the direct child alone left a
/// script's children running and holding the output pipe, and the run never ended.
void signal_group(Child& c, int sig) {
  if (c.group_gone) return;
  if (kill(-c.pid, sig) != 0 && errno == ESRCH) c.group_gone = true;
}

void terminate(Child& c) {
  if (c.group_signalled || c.finished()) return;
  c.group_signalled = true;
  c.sent_term = !c.exited;
  signal_group(c, SIGTERM);
}

void emit_line(Child& c, const std::string& line, bool quiet) {
  c.log << line << "\n";
  if (!quiet) std::cout << "[" << c.name << "] " << line << "\n";
}

/// Stops reading the child's output (at its end, or when we give up on it).
void close_output(Child& c, bool quiet) {
  if (c.out_fd < 0) return;
  if (!c.partial_line.empty()) emit_line(c, c.partial_line, quiet);
  c.partial_line.clear();
  c.log.flush();
  close(c.out_fd);
  c.out_fd = -1;
}

void read_output(Child& c, bool quiet) {
  char buf[4096];
  const ssize_t n = read(c.out_fd, buf, sizeof(buf));
  if (n < 0 && (errno == EINTR || errno == EAGAIN)) return;
  if (n <= 0) {
    close_output(c, quiet);
    return;
  }
  c.partial_line.append(buf, static_cast<std::size_t>(n));
  std::size_t nl;
  while ((nl = c.partial_line.find('\n')) != std::string::npos) {
    emit_line(c, c.partial_line.substr(0, nl), quiet);
    c.partial_line.erase(0, nl + 1);
  }
  c.log.flush();
}

void pump_output(Children& children, int timeout_ms, bool quiet) {
  std::vector<pollfd> fds;
  std::vector<Child*> owners;
  for (auto& c : children) {
    if (c->out_fd >= 0) {
      fds.push_back({c->out_fd, POLLIN, 0});
      owners.push_back(c.get());
    }
  }
  if (fds.empty()) {
    usleep(static_cast<useconds_t>(timeout_ms) * 1000);
    return;
  }
  if (poll(fds.data(), fds.size(), timeout_ms) <= 0) return;
  for (std::size_t i = 0; i < fds.size(); ++i) {
    if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) read_output(*owners[i], quiet);
  }
  std::cout.flush();
}

/// Reads what a dead child's processes left in its pipe, for at most ~1 s.
void drain_output(Child& c, bool quiet) {
  for (int i = 0; i < 20 && c.out_fd >= 0; ++i) {
    pollfd fd{c.out_fd, POLLIN, 0};
    if (poll(&fd, 1, 50) <= 0) continue;
    read_output(c, quiet);
  }
  close_output(c, quiet);
}

/// restart: on-failure. A federate that crashed (an error exit, or a signal the launcher did not
/// send) is started again with the same command line, at most max_restarts times over the run;
/// what its process started goes with it (SIGKILL to its group). True if it was restarted.
bool restart_crashed(Child& c, bool quiet) {
  if (!c.restart_on_failure || clean_exit(c)) return false;
  const std::string how = describe_exit(c.status);
  if (static_cast<int>(c.crashes.size()) >= c.max_restarts) {
    warn() << c.name << " crashed (" << how << ") and was restarted " << c.crashes.size()
           << " time(s) already (max_restarts " << c.max_restarts << "): not restarting it\n";
    return false;
  }
  c.crashes.push_back(how);
  signal_group(c, SIGKILL);
  drain_output(c, quiet);
  const std::string line = c.name + " crashed (" + how + "): restarting it (restart " +
                           std::to_string(c.crashes.size()) + " of at most " +
                           std::to_string(c.max_restarts) + ")";
  std::cout << "fedsim run: " << line << std::endl;
  c.log << "---- fedsim run: " << line << " ----" << std::endl;
  const int crashed_status = c.status;
  c.exited = false;
  c.status = 0;
  c.sent_term = c.group_signalled = c.group_gone = false;
  try {
    start_child(c, c.log_path, true);
  } catch (const std::exception& e) {  // no pipe or no fork: the crash stands, reported
    warn() << c.name << ": restart failed: " << e.what() << "\n";
    c.crashes.pop_back();
    c.exited = true;
    c.status = crashed_status;
    return false;
  }
  return true;
}

void reap(Children& children) {
  for (auto& c : children) {
    if (c->exited) continue;
    int status = 0;
    if (waitpid(c->pid, &status, WNOHANG) == c->pid) {
      c->exited = true;
      c->status = status;
    }
  }
}

bool all_finished(const Children& children) {
  for (const auto& c : children) {
    if (!c->finished()) return false;
  }
  return true;
}

/// Watches fedsim/federate_status: the progress line, and who ever ran.
class Progress {
 public:
  Progress(const runtime::ParticipantOptions& dds) {
    try {
      auto participant = runtime::DdsParticipant::create(dds);
      sub_ = std::make_unique<runtime::Subscription<msg::FederateStatus>>(
          participant, runtime::topics::federate_status, runtime::qos::kStatus,
          [this](const msg::FederateStatus& s, const auto&) { note(s); });
      participant_ = participant;
    } catch (const std::exception& e) {
      warn() << "progress monitor unavailable: " << e.what() << "\n";
    }
  }
  ~Progress() {
    if (sub_) sub_->close();
  }
  /// False if the monitor could not subscribe: then nobody can be said not to have run.
  bool available() const { return sub_ != nullptr; }
  /// Reported its state at all (a fedsim federate; a plain program never does).
  bool reported(const std::string& name) {
    std::lock_guard lock(mutex_);
    return latest_.count(name) != 0;
  }
  /// Reported RUNNING or a stepped frame (the timing federate: a ticked one).
  bool ran(const std::string& name) {
    std::lock_guard lock(mutex_);
    return ran_.count(name) != 0;
  }
  /// One progress line: the timing federate's frame (and simulated time at `rate_hz`), how
  /// many members run, the ones that do not by state, then each member's note or fault (the
  /// flight federate's phase of flight, distance to go and modes).
  std::string line(double rate_hz) {
    static const char* kState[] = {"starting", "ready", "running", "stopping", "FAILED", "LOST"};
    std::lock_guard lock(mutex_);
    std::ostringstream out;
    std::uint64_t frame = 0;
    int running = 0;
    std::string others, notes;
    for (const auto& [name, s] : latest_) {
      frame = std::max<std::uint64_t>(frame, s.frames_done());
      if (s.state() == msg::FEDERATE_RUNNING) {
        ++running;
      } else {
        others += " " + name + "=" + kState[std::min<int>(s.state(), 5)];
      }
      const std::string message = s.message().to_string();
      if (!message.empty() && s.state() != msg::FEDERATE_STOPPING) notes += "\n    " + name + ": " + message;
    }
    out << " frame " << frame;
    if (rate_hz > 0) out << " (" << std::fixed << std::setprecision(1) << frame / rate_hz << " s simulated)";
    out << ", " << running << " running" << others << notes;
    return out.str();
  }

 private:
  void note(const msg::FederateStatus& s) {
    const std::string name = s.federate().to_string();
    std::lock_guard lock(mutex_);
    latest_[name] = s;
    if (s.state() == msg::FEDERATE_RUNNING || s.frames_done() > 0) ran_.insert(name);
  }

  std::shared_ptr<runtime::DdsParticipant> participant_;
  std::unique_ptr<runtime::Subscription<msg::FederateStatus>> sub_;
  std::mutex mutex_;
  std::map<std::string, msg::FederateStatus> latest_;
  std::set<std::string> ran_;
};

/// The stop sequence: the timing federate first (no new frames), every federate's process
/// group 0.3 s later (time for the timing federate's SHUTDOWN command), SIGKILL to every group
/// still there after --stop-grace, and 1 s after that the output of a process that left its
/// group (setsid) is no longer waited for: nothing of ours can stop it.
class Stopper {
 public:
  Stopper(Children& children, double grace_s, bool quiet)
      : children_(children), grace_s_(grace_s), quiet_(quiet) {}

  bool stopping() const { return since_ns_ != 0; }
  const std::string& reason() const { return reason_; }

  void begin(const std::string& why) {
    if (stopping()) return;
    since_ns_ = util::monotonic_ns();
    reason_ = why;
    std::cout << "fedsim run: stopping (" << why << ")\n";
    for (auto& c : children_) {
      if (c->timing) terminate(*c);
    }
  }

  /// Moves the sequence on; a federate that had to be killed is a failure.
  void step(bool& failed) {
    if (!stopping()) return;
    const double t = (util::monotonic_ns() - since_ns_) * 1e-9;
    if (phase_ == 0 && t > 0.3) {
      for (auto& c : children_) terminate(*c);
      phase_ = 1;
    }
    if (phase_ == 1 && t > grace_s_ + 0.3) {
      kill_groups(failed);
      phase_ = 2;
    }
    if (phase_ == 2 && t > grace_s_ + 1.3) {
      abandon_output();
      phase_ = 3;
    }
  }

 private:
  void kill_groups(bool& failed) {
    for (auto& c : children_) {
      if (c->finished()) continue;
      if (!c->exited) {
        warn() << c->name << " did not stop within " << grace_s_ << " s: killing it\n";
        c->sent_term = false;  // a kill is a failure
        failed = true;
        signal_group(*c, SIGKILL);
        continue;
      }
      signal_group(*c, SIGKILL);
      if (!c->group_gone) {
        warn() << c->name << " exited but processes it started did not stop: killed them\n";
      }
    }
  }

  void abandon_output() {
    for (auto& c : children_) {
      if (!c->exited || c->out_fd < 0) continue;
      warn() << c->name << ": a process outside its process group still holds its output: "
                                "no longer reading it\n";
      close_output(*c, quiet_);
    }
  }

  Children& children_;
  double grace_s_;
  bool quiet_;
  std::uint64_t since_ns_ = 0;
  std::string reason_;
  int phase_ = 0;
};

/// Who never ran. The timing federate exits 0 when it is stopped while still waiting for its
/// federates (a --duration shorter than its --join-timeout), so exit statuses alone report a
/// federation that never started as a success. A lockstep member must have run; any other
/// required federate that reports its state, too (a plain program never reports one).
/// In lockstep, frames ticked are proof enough for every member: no frame passes without each
/// one's acknowledgement (a short run may end before a member's RUNNING status is seen).
std::vector<std::string> never_ran(const Children& children, Progress& progress, bool lockstep) {
  std::vector<std::string> out;
  if (!progress.available()) return out;
  bool ticked = false;
  for (const auto& c : children) ticked |= c->timing && progress.ran(c->name);
  for (const auto& c : children) {
    if (progress.ran(c->name)) continue;
    if (lockstep && ticked && c->lockstep) continue;
    if (c->timing) {
      out.push_back("timing (no frame ticked)");
    } else if (c->required && (c->lockstep || progress.reported(c->name))) {
      out.push_back(c->name + " (never reported RUNNING)");
    }
  }
  return out;
}

/// The timing federate's losses and rejoins, from its summary; false if any federate was lost
/// (a loss is a failure of the run, even when the federate came back).
bool report_membership(const std::string& summary_path) {
  std::ifstream in(summary_path);
  if (!in) return true;  // the timing federate did not finish (its own exit says why)
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    warn() << "timing summary " << summary_path << " unreadable: " << e.what() << "\n";
    return true;
  }
  const auto events = j.value("membership", nlohmann::json::array());
  for (const auto& e : events) {
    std::cout << "fedsim run: " << e.value("event", "?") << " " << e.value("federate", "?")
              << " at frame " << e.value("frame", 0ull) << " (t=" << e.value("t_s", 0.0) << " s"
              << (e.contains("why") ? ": " + e.value("why", "") : std::string()) << ")\n";
  }
  const auto still_lost = j.value("still_lost", std::vector<std::string>{});
  if (!still_lost.empty()) {
    std::string names;
    for (const auto& n : still_lost) names += (names.empty() ? "" : ", ") + n;
    std::cout << "fedsim run: lost and not back at the end: " << names << "\n";
  }
  return j.value("lost", std::vector<std::string>{}).empty();
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

/// An interrupted run exits as a shell reports a process killed by the signal (130 for Ctrl-C).
int interrupted_exit_code() {
  const int sig = runtime::shutdown_signal();
  return 128 + (sig != 0 ? sig : SIGINT);
}

std::string signal_name() { return runtime::shutdown_signal() == SIGTERM ? "SIGTERM" : "SIGINT"; }

/// FEDSIM_DOMAIN, checked as --domain is: "abc" is an error, not domain 0.
int domain_from_env(int fallback) {
  const char* env = std::getenv("FEDSIM_DOMAIN");
  if (!env || !*env) return fallback;
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(env, &end, 10);
  if (*end != '\0' || errno != 0 || value < 0 || value > 232) {
    throw util::ConfigError(std::string("FEDSIM_DOMAIN: '") + env + "' is not a DDS domain id (0..232)");
  }
  return static_cast<int>(value);
}

/// An after-step's argv, its program resolved; throws util::ConfigError naming the program.
std::vector<std::string> after_argv(const AfterStep& step, const std::map<std::string, std::string>& vars,
                                    const std::string& bin_dir) {
  std::vector<std::string> argv{resolve_binary(substitute(step.argv[0], vars), bin_dir, "")};
  for (std::size_t i = 1; i < step.argv.size(); ++i) argv.push_back(substitute(step.argv[i], vars));
  return argv;
}

/// Says at once, not only after the run, that an after-step's program is missing.
void warn_missing_after_programs(const Deployment& d, const std::map<std::string, std::string>& vars,
                                 const std::string& bin_dir) {
  for (const auto& step : d.after) {
    try {
      after_argv(step, vars, bin_dir);
    } catch (const std::exception& e) {
      warn() << "warning: after-command '" << step.argv[0] << "' will fail: " << e.what() << "\n";
    }
  }
}

/// An after-step as `fedsim run` names it: its number (its log is logs/after<number>.log) and its
/// program with the plain words that follow it: "2 (fedsim image montage)", "1 (gnuplot)".
std::string after_step_label(int number, const AfterStep& step) {
  std::string words = step.argv[0];
  for (std::size_t i = 1; i < step.argv.size() && i <= 2; ++i) {
    const std::string& w = step.argv[i];
    const bool plain = !w.empty() && std::all_of(w.begin(), w.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || c == '-' || c == '_';
    }) && w[0] != '-';
    if (!plain) break;
    words += " " + w;
  }
  return std::to_string(number) + " (" + words + ")";
}

/// The kernel stamps a file with a clock that may lag ours by a tick (a few ms): a file written
/// right after the run started must not look older than it.
constexpr auto kFileStampSlack = std::chrono::milliseconds(100);

/// Why this run cannot give an after-step what it needs ("" = it can): the whole run it judges
/// was cut short, or a file it needs was not written by this run (never made, or left in the
/// same folder by an earlier run: drawing that would present the earlier run as this one).
std::string unmet_needs(const AfterStep& step, const std::map<std::string, std::string>& vars,
                        const RunEnd& end) {
  if (step.whole_run && !end.cut_short.empty()) return "it judges the whole run, which " + end.cut_short;
  std::vector<std::string> missing;
  std::vector<std::string> stale;
  for (const auto& need : step.needs) {
    const std::string file = substitute(need, vars);
    std::error_code error;
    const auto written = fs::last_write_time(file, error);
    if (error) {
      missing.push_back(file);
    } else if (written < end.started - kFileStampSlack) {
      stale.push_back(file);
    }
  }
  std::string why;
  if (!missing.empty()) why = "this run did not make " + join(missing);
  if (!stale.empty()) {
    why += (why.empty() ? "" : "; ") + std::string("left from an earlier run, not this one: ") + join(stale);
  }
  return why;
}

/// Runs one after-command to its end; true if it stopped cleanly.
bool run_one_after_command(Children& one, const std::string& log_path, bool quiet) {
  Child& child = *one.front();
  start_child(child, log_path);
  std::uint64_t exited_at = 0;
  while (!all_finished(one)) {
    pump_output(one, 100, quiet);
    reap(one);
    if (runtime::shutdown_requested()) terminate(child);
    if (child.exited && !exited_at) exited_at = util::monotonic_ns();
    // Processes it started that hold its output open do not keep the run waiting.
    if (exited_at && util::monotonic_ns() - exited_at > 2'000'000'000ull) {
      signal_group(child, SIGKILL);
      close_output(child, quiet);
    }
  }
  return clean_exit(child);
}

/// Everything `fedsim run` starts, and where.
struct Plan {
  Deployment d;
  Children children;
  std::map<std::string, std::string> vars;
  std::string bin_dir;
  std::string log_dir;
  runtime::ParticipantOptions dds;
  std::string timing_summary;  // the timing federate's --summary-json
};

/// --name and the DDS settings every fedsim federate takes.
std::vector<std::string> common_args(const std::string& name, const Plan& p) {
  return {"--name", name, "--domain", std::to_string(p.dds.domain_id), "--qos-file",
          p.dds.qos_file, "--participant-profile", p.dds.participant_profile, "--sync-qos",
          p.d.sync_qos};
}

std::unique_ptr<Child> federate_child(const FederateSpec& f, const Plan& p) {
  auto child = std::make_unique<Child>();
  child->name = f.name;
  child->required = f.required;
  child->lockstep = f.lockstep;
  child->restart_on_failure = f.restart_on_failure;
  child->max_restarts = f.max_restarts;
  child->argv.push_back(resolve_binary(f.binary, p.bin_dir));
  for (const auto& a : f.args) child->argv.push_back(substitute(a, p.vars));
  // After the user's args, so that a subcommand (`fedsim record ...`) comes first.
  if (f.federate_options) {
    for (auto& a : common_args(f.name, p)) child->argv.push_back(a);
  }
  return child;
}

std::unique_ptr<Child> timing_child(Plan& p) {
  auto timing = std::make_unique<Child>();
  timing->timing = true;
  const FederateSpec spec = timing_spec(p.d);
  timing->name = spec.name;
  timing->argv.push_back(resolve_binary(spec.binary, p.bin_dir));
  for (auto& a : common_args(spec.name, p)) timing->argv.push_back(a);
  for (const auto& a : spec.args) timing->argv.push_back(substitute(a, p.vars));
  // Its summary (losses and rejoins) is read back for the run's own; unless the deployment
  // names the file, it goes next to the logs.
  const auto given = std::find(timing->argv.begin(), timing->argv.end(), "--summary-json");
  if (given == timing->argv.end()) {
    timing->argv.push_back("--summary-json");
    timing->argv.push_back(p.timing_summary);
  } else if (given + 1 != timing->argv.end()) {
    p.timing_summary = *(given + 1);
  }
  return timing;
}

/// Loads the deployment and builds every command line; throws on any error in them.
void plan_run(const RunOptions& options, Plan& p) {
  p.bin_dir = self_dir();
  p.d = load_with_scenario(options);
  if (!options.mode.empty()) p.d.mode = options.mode;
  const int domain = options.domain >= 0 ? options.domain : domain_from_env(p.d.domain);
  const std::string out_dir = options.out_dir.empty() ? "out/" + p.d.name : options.out_dir;
  p.log_dir = out_dir + "/logs";
  fs::create_directories(p.log_dir);
  p.timing_summary = p.log_dir + "/timing_summary.json";
  p.vars = deployment_vars(options.deployment_path, out_dir);
  p.dds.name = "fedsim-run";
  p.dds.domain_id = domain;
  p.dds.qos_file = substitute(p.d.qos_file, p.vars);
  p.dds.participant_profile = p.d.participant_profile;
  if (!fs::exists(p.dds.qos_file)) {
    throw util::ConfigError(p.d.file + ": qos_file not found: " + p.dds.qos_file);
  }
  for (const auto& f : p.d.federates) p.children.push_back(federate_child(f, p));
  if (p.d.has_timing) p.children.push_back(timing_child(p));
  std::error_code ec;
  fs::remove(p.timing_summary, ec);  // a previous run's must not be read as this one's
}

void start_all(Plan& p) {
  std::cout << "fedsim run: " << p.d.name << " mode=" << p.d.mode << " rate=" << p.d.rate_hz
            << " Hz domain=" << p.dds.domain_id << " profile=" << p.dds.participant_profile
            << " logs=" << p.log_dir << "\n";
  for (auto& c : p.children) {
    std::string cmd;
    for (const auto& a : c->argv) cmd += a + " ";
    std::cout << "fedsim run: starting " << c->name << ": " << cmd << "\n";
    start_child(*c, p.log_dir + "/" + c->name + ".log");
  }
  std::cout.flush();
}

/// Before any stop: the timing federate's end stops the run; so does a required federate's
/// failure.
void check_exits(Children& children, Stopper& stopper, bool& failed, bool quiet) {
  for (auto& c : children) {
    if (!c->exited || stopper.stopping()) continue;
    if (c->timing) {
      stopper.begin(std::string("timing federate finished (") + describe_exit(c->status) + ")");
    } else if (restart_crashed(*c, quiet)) {
      continue;
    } else if (c->required && !clean_exit(*c)) {
      failed = true;
      stopper.begin(c->name + " failed (" + describe_exit(c->status) + ")");
    }
  }
}

/// The stop reason of a run that --duration cut short (the after-steps that judge a whole run
/// are skipped).
const std::string kDurationReached = "duration reached";

/// Runs the federation until every federate stopped; returns the stop reason.
std::string supervise(Children& children, const RunOptions& options, Progress& progress, double rate_hz,
                      bool& failed) {
  Stopper stopper(children, options.stop_grace_s, options.quiet);
  const std::uint64_t start_ns = util::monotonic_ns();
  const auto period_ns = static_cast<std::uint64_t>(options.progress_period_s * 1e9);
  std::uint64_t next_progress = start_ns + period_ns;
  while (!all_finished(children)) {
    pump_output(children, 50, options.quiet);
    reap(children);
    const std::uint64_t now = util::monotonic_ns();
    if (runtime::shutdown_requested()) stopper.begin("interrupted");
    if (options.duration_s > 0 && now - start_ns >= options.duration_s * 1e9) {
      stopper.begin(kDurationReached);
    }
    check_exits(children, stopper, failed, options.quiet);
    stopper.step(failed);
    if (!stopper.stopping() && period_ns > 0 && now >= next_progress) {
      next_progress += period_ns;
      std::cout << "fedsim run: progress t=" << static_cast<int>((now - start_ns) / 1e9) << "s"
                << progress.line(rate_hz) << "\n";
    }
  }
  return stopper.reason();
}

}  // namespace

int run_after_commands(const Deployment& d, const std::map<std::string, std::string>& vars,
                       const std::string& bin_dir, const std::string& log_dir, bool quiet,
                       const RunEnd& end) {
  int index = 0;
  std::vector<std::string> skipped;
  for (const auto& step : d.after) {
    if (runtime::shutdown_requested()) return 1;
    const std::string label = after_step_label(++index, step);
    if (const std::string why = unmet_needs(step, vars, end); !why.empty()) {
      std::cout << "fedsim run: after-step " << label << " skipped: " << why << "\n";
      skipped.push_back(label);
      continue;
    }
    Children one;
    one.push_back(std::make_unique<Child>());
    Child& child = *one.front();
    child.name = "after" + std::to_string(index);
    try {
      child.argv = after_argv(step, vars, bin_dir);
    } catch (const std::exception& e) {  // a missing program fails the run, not the launcher
      warn() << "after-command '" << step.argv[0] << "' cannot run: " << e.what() << "\n";
      return 1;
    }
    if (!run_one_after_command(one, log_dir + "/" + child.name + ".log", quiet)) {
      warn() << "after-command '" << step.argv[0] << "' failed (" << describe_exit(child.status)
             << ")\n";
      return 1;
    }
  }
  if (!skipped.empty()) {
    std::cout << "fedsim run: " << skipped.size() << " of " << d.after.size()
              << " after-steps skipped, not failed: " << join(skipped) << "\n";
  }
  return 0;
}

std::string bin_dir() { return self_dir(); }

Deployment load_with_scenario(const RunOptions& options) {
  Deployment d = load_deployment(options.deployment_path);
  if (options.scenario.empty()) return d;
  scenario::Scenario::load_file(options.scenario);  // its errors now, before anything starts
  for (const auto& f : d.federates) {
    if (f.name == "scenario") {
      throw util::ConfigError(d.file + ": a federate is already named 'scenario'; --scenario adds one");
    }
  }
  FederateSpec spec;
  spec.name = "scenario";
  spec.binary = "fedsim-scenario";
  spec.args = {"--file", fs::absolute(options.scenario).string()};
  d.federates.push_back(spec);
  return d;
}

std::map<std::string, std::string> deployment_vars(const std::string& deployment_path,
                                                   const std::string& out_dir) {
  return {{"SOURCE_DIR", util::source_dir()},
          {"DATA_DIR", util::data_dir()},
          {"DEPLOY_DIR", fs::absolute(deployment_path).parent_path().string()},
          {"OUT_DIR", fs::absolute(out_dir).string()},
          {"BIN_DIR", self_dir()}};
}

int run_deployment(const RunOptions& options) {
  if (options.in_process) {
    const int rc = run_in_process(options);
    if (!runtime::shutdown_requested()) return rc;
    std::cout << "fedsim run: interrupted (" << signal_name() << ")\n";
    return interrupted_exit_code();
  }
  runtime::install_shutdown_handler();
  Plan p;
  try {
    plan_run(options, p);
  } catch (const std::exception& e) {
    warn() << e.what() << "\n";
    return 2;
  }
  warn_missing_after_programs(p.d, p.vars, p.bin_dir);
  const auto started = fs::file_time_type::clock::now();
  start_all(p);
  Progress progress(p.dds);
  bool failed = false;
  const std::string reason = supervise(p.children, options, progress, p.d.rate_hz, failed);

  std::cout << "fedsim run: all federates stopped (" << reason << ")\n";
  for (const auto& c : p.children) {
    const bool ok = clean_exit(*c);
    if (!ok && c->required) failed = true;
    std::cout << "  " << (ok ? "ok    " : "FAILED") << " " << c->name << " (" << describe_exit(c->status)
              << ")";
    if (!c->crashes.empty()) {
      std::cout << "; CRASHED and restarted " << c->crashes.size() << " time(s) (max_restarts "
                << c->max_restarts << "): " << join(c->crashes);
    }
    std::cout << "\n";
  }
  std::vector<std::string> restarted;
  for (const auto& c : p.children) {
    if (!c->crashes.empty()) restarted.push_back(c->name + " x" + std::to_string(c->crashes.size()));
  }
  if (!restarted.empty()) {
    std::cout << "fedsim run: restarted after a crash: " << join(restarted) << "\n";
    failed = true;
  }
  if (!report_membership(p.timing_summary)) failed = true;
  if (const auto idle = never_ran(p.children, progress, p.d.mode == "lockstep"); !idle.empty()) {
    std::cout << "fedsim run: never ran: " << join(idle) << "\n";
    failed = true;
  }
  // An interrupted run gets no after-commands: their input is incomplete.
  if (!failed && !runtime::shutdown_requested() && !p.d.after.empty()) {
    RunEnd end{started, ""};
    if (reason == kDurationReached) {
      std::ostringstream why;
      why << "--duration stopped after " << options.duration_s << " s";
      end.cut_short = why.str();
    }
    if (run_after_commands(p.d, p.vars, p.bin_dir, p.log_dir, options.quiet, end) != 0) failed = true;
  }
  if (runtime::shutdown_requested()) {
    std::cout << "fedsim run: interrupted (" << signal_name() << ")" << (failed ? "; FAILED" : "")
              << "; logs in " << p.log_dir << "\n";
    return interrupted_exit_code();
  }
  std::cout << "fedsim run: " << (failed ? "FAILED" : "done") << "; logs in " << p.log_dir << "\n";
  return failed ? 1 : 0;
}

}  // namespace fedsim::launcher
