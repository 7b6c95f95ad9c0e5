#include "fedsim/launcher.hpp"

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/federate_options.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/runtime/subscription.hpp"
#include "common/util/config_node.hpp"
#include "common/util/monotonic_clock.hpp"
#include "common/scenario/scenario.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

namespace fs = std::filesystem;

namespace fedsim::launcher {

namespace {

struct Child {
  std::string name;
  std::vector<std::string> argv;
  bool required = true;
  pid_t pid = -1;
  int out_fd = -1;
  std::string partial_line;
  std::ofstream log;
  bool exited = false;
  int status = 0;
  bool sent_term = false;
};

std::string self_dir() {
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "." : exe.parent_path().string();
}

bool is_executable(const fs::path& p) { return fs::is_regular_file(p) && access(p.c_str(), X_OK) == 0; }

std::string resolve_binary(const std::string& binary, const std::string& bin_dir) {
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
  throw util::ConfigError("binary '" + binary + "' not found in " + bin_dir +
                          " or PATH (did the build finish?)");
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

void start_child(Child& child, const std::string& log_path) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    dup2(fds[1], STDOUT_FILENO);
    dup2(fds[1], STDERR_FILENO);
    setpgid(0, 0);                     // Ctrl-C reaches the launcher only; it stops the children
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
  close(fds[1]);
  child.pid = pid;
  child.out_fd = fds[0];
  child.log.open(log_path);
}

class Progress {
 public:
  Progress(const runtime::ParticipantOptions& dds) {
    try {
      auto participant = runtime::DdsParticipant::create(dds);
      sub_ = std::make_unique<runtime::Subscription<msg::FederateStatus>>(
          participant, runtime::topics::federate_status, runtime::qos::kStatus,
          [this](const msg::FederateStatus& s, const auto&) {
            std::lock_guard lock(mutex_);
            latest_[s.federate().to_string()] = s;
          });
      participant_ = participant;
    } catch (const std::exception& e) {
      std::cerr << "fedsim run: progress monitor unavailable: " << e.what() << "\n";
    }
  }
  ~Progress() {
    if (sub_) sub_->close();
  }
  std::string line() {
    static const char* kState[] = {"starting", "ready", "running", "stopping", "FAILED", "LOST"};
    std::lock_guard lock(mutex_);
    std::ostringstream out;
    for (const auto& [name, s] : latest_) {
      out << " " << name << "=" << kState[std::min<int>(s.state(), 5)] << "/" << s.frames_done();
      if (!s.message().to_string().empty() && s.state() != msg::FEDERATE_STOPPING) {
        out << "(" << s.message().to_string() << ")";
      }
    }
    return out.str();
  }

 private:
  std::shared_ptr<runtime::DdsParticipant> participant_;
  std::unique_ptr<runtime::Subscription<msg::FederateStatus>> sub_;
  std::mutex mutex_;
  std::map<std::string, msg::FederateStatus> latest_;
};

void pump_output(std::vector<std::unique_ptr<Child>>& children, int timeout_ms, bool quiet) {
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
    if (!(fds[i].revents & (POLLIN | POLLHUP))) continue;
    Child& c = *owners[i];
    char buf[4096];
    const ssize_t n = read(c.out_fd, buf, sizeof(buf));
    if (n <= 0) {
      if (!c.partial_line.empty()) {
        c.log << c.partial_line << "\n";
        if (!quiet) std::cout << "[" << c.name << "] " << c.partial_line << "\n";
        c.partial_line.clear();
      }
      close(c.out_fd);
      c.out_fd = -1;
      continue;
    }
    c.partial_line.append(buf, static_cast<std::size_t>(n));
    std::size_t nl;
    while ((nl = c.partial_line.find('\n')) != std::string::npos) {
      const std::string line = c.partial_line.substr(0, nl);
      c.partial_line.erase(0, nl + 1);
      c.log << line << "\n";
      if (!quiet) std::cout << "[" << c.name << "] " << line << "\n";
    }
    c.log.flush();
  }
  std::cout.flush();
}

void reap(std::vector<std::unique_ptr<Child>>& children) {
  for (auto& c : children) {
    if (c->exited) continue;
    int status = 0;
    if (waitpid(c->pid, &status, WNOHANG) == c->pid) {
      c->exited = true;
      c->status = status;
    }
  }
}

bool all_exited(const std::vector<std::unique_ptr<Child>>& children) {
  for (const auto& c : children) {
    if (!c->exited || c->out_fd >= 0) return false;
  }
  return true;
}

void terminate(Child& c) {
  if (c.exited || c.sent_term) return;
  c.sent_term = true;
  kill(c.pid, SIGTERM);
}

}  // namespace

int run_after_commands(const Deployment& d, const std::map<std::string, std::string>& vars,
                       const std::string& bin_dir, const std::string& log_dir, bool quiet) {
  int index = 0;
  for (const auto& words : d.after) {
    auto child = std::make_unique<Child>();
    child->name = "after" + std::to_string(++index);
    child->argv.push_back(resolve_binary(substitute(words[0], vars), bin_dir));
    for (std::size_t i = 1; i < words.size(); ++i) child->argv.push_back(substitute(words[i], vars));
    std::vector<std::unique_ptr<Child>> one;
    start_child(*child, log_dir + "/" + child->name + ".log");
    one.push_back(std::move(child));
    while (!all_exited(one)) {
      pump_output(one, 100, quiet);
      reap(one);
    }
    if (!clean_exit(*one[0])) {
      std::cerr << "fedsim run: after-command '" << words[0] << "' failed ("
                << describe_exit(one[0]->status) << ")\n";
      return 1;
    }
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
  return {{"SOURCE_DIR", FEDSIM_SOURCE_DIR},
          {"DATA_DIR", FEDSIM_DATA_DIR},
          {"DEPLOY_DIR", fs::absolute(deployment_path).parent_path().string()},
          {"OUT_DIR", fs::absolute(out_dir).string()},
          {"BIN_DIR", self_dir()}};
}

int run_deployment(const RunOptions& options) {
  if (options.in_process) return run_in_process(options);
  runtime::install_shutdown_handler();
  Deployment d;
  std::vector<std::unique_ptr<Child>> children;
  std::map<std::string, std::string> vars;
  std::string bin_dir = self_dir();
  std::string log_dir;
  runtime::ParticipantOptions dds;
  try {
    d = load_with_scenario(options);
    if (!options.mode.empty()) d.mode = options.mode;
    int domain = d.domain;
    if (const char* env = std::getenv("FEDSIM_DOMAIN"); env && *env) domain = std::atoi(env);
    if (options.domain >= 0) domain = options.domain;
    const std::string out_dir = options.out_dir.empty() ? "out/" + d.name : options.out_dir;
    fs::create_directories(out_dir);
    log_dir = out_dir + "/logs";
    fs::create_directories(log_dir);
    vars = deployment_vars(options.deployment_path, out_dir);
    dds.name = "fedsim-run";
    dds.domain_id = domain;
    dds.qos_file = substitute(d.qos_file, vars);
    dds.participant_profile = d.participant_profile;
    if (!fs::exists(dds.qos_file)) throw util::ConfigError(d.file + ": qos_file not found: " + dds.qos_file);

    auto common_args = [&](const std::string& name) {
      return std::vector<std::string>{"--name", name, "--domain", std::to_string(domain),
                                      "--qos-file", dds.qos_file, "--participant-profile",
                                      dds.participant_profile, "--sync-qos", d.sync_qos};
    };
    std::string expect;
    for (const auto& f : d.federates) {
      auto child = std::make_unique<Child>();
      child->name = f.name;
      child->required = f.required;
      child->argv.push_back(resolve_binary(f.binary, bin_dir));
      for (const auto& a : f.args) child->argv.push_back(substitute(a, vars));
      // After the user's args, so that a subcommand (`fedsim record ...`) comes first.
      if (f.federate_options) {
        for (auto& a : common_args(f.name)) child->argv.push_back(a);
      }
      if (f.lockstep) expect += (expect.empty() ? "" : ",") + f.name;
      children.push_back(std::move(child));
    }
    if (d.has_timing) {
      auto timing = std::make_unique<Child>();
      timing->name = "timing";
      timing->argv.push_back(resolve_binary("fedsim-timing", bin_dir));
      for (auto& a : common_args("timing")) timing->argv.push_back(a);
      for (const std::string& a : {std::string("--mode"), d.mode, std::string("--rate"),
                                   std::to_string(d.rate_hz), std::string("--shutdown-on-exit")}) {
        timing->argv.push_back(a);
      }
      if (!expect.empty()) {
        timing->argv.push_back("--expect");
        timing->argv.push_back(expect);
      }
      for (const auto& a : d.timing_args) timing->argv.push_back(substitute(a, vars));
      children.push_back(std::move(timing));
    }
  } catch (const std::exception& e) {
    std::cerr << "fedsim run: " << e.what() << "\n";
    return 2;
  }

  std::cout << "fedsim run: " << d.name << " mode=" << d.mode << " rate=" << d.rate_hz
            << " Hz domain=" << dds.domain_id << " profile=" << dds.participant_profile
            << " logs=" << log_dir << "\n";
  for (auto& c : children) {
    std::string cmd;
    for (const auto& a : c->argv) cmd += a + " ";
    std::cout << "fedsim run: starting " << c->name << ": " << cmd << "\n";
    start_child(*c, log_dir + "/" + c->name + ".log");
  }
  std::cout.flush();
  Progress progress(dds);

  const std::uint64_t start_ns = util::monotonic_ns();
  std::uint64_t next_progress = start_ns + static_cast<std::uint64_t>(options.progress_period_s * 1e9);
  std::uint64_t stop_since = 0;
  std::string stop_reason;
  bool failed = false;
  auto begin_stop = [&](const std::string& why) {
    if (stop_since) return;
    stop_since = util::monotonic_ns();
    stop_reason = why;
    std::cout << "fedsim run: stopping (" << why << ")\n";
    for (auto& c : children) {
      if (c->name == "timing") terminate(*c);  // no new frames first
    }
  };

  while (!all_exited(children)) {
    pump_output(children, 50, options.quiet);
    reap(children);
    const std::uint64_t now = util::monotonic_ns();
    if (runtime::shutdown_requested()) begin_stop("interrupted");
    if (options.duration_s > 0 && now - start_ns >= options.duration_s * 1e9) begin_stop("duration reached");
    for (auto& c : children) {
      if (!c->exited || stop_since) continue;
      if (c->name == "timing") {
        begin_stop(std::string("timing federate finished (") + describe_exit(c->status) + ")");
      } else if (c->required && !clean_exit(*c)) {
        failed = true;
        begin_stop(c->name + " failed (" + describe_exit(c->status) + ")");
      }
    }
    if (stop_since) {
      const std::uint64_t stopping_ns = util::monotonic_ns() - stop_since;
      // Give the timing federate's SHUTDOWN command a moment, then signal everyone.
      if (stopping_ns > 300'000'000ull) {
        for (auto& c : children) terminate(*c);
      }
      if (stopping_ns > options.stop_grace_s * 1e9 + 3e8) {
        for (auto& c : children) {
          if (!c->exited) {
            std::cerr << "fedsim run: " << c->name << " did not stop within "
                      << options.stop_grace_s << " s: killing it\n";
            kill(c->pid, SIGKILL);
            c->sent_term = false;  // a kill is a failure
            failed = true;
          }
        }
      }
    } else if (options.progress_period_s > 0 && now >= next_progress) {
      next_progress += static_cast<std::uint64_t>(options.progress_period_s * 1e9);
      std::cout << "fedsim run: progress t=" << static_cast<int>((now - start_ns) / 1e9) << "s"
                << progress.line() << "\n";
    }
  }

  std::cout << "fedsim run: all federates stopped (" << stop_reason << ")\n";
  for (const auto& c : children) {
    const bool ok = clean_exit(*c);
    if (!ok && c->required) failed = true;
    std::cout << "  " << (ok ? "ok    " : "FAILED") << " " << c->name << " (" << describe_exit(c->status)
              << ")\n";
  }
  if (!failed && stop_reason != "interrupted" && !d.after.empty()) {
    if (run_after_commands(d, vars, bin_dir, log_dir, options.quiet) != 0) failed = true;
  }
  std::cout << "fedsim run: " << (failed ? "FAILED" : "done") << "; logs in " << log_dir << "\n";
  return failed ? 1 : 0;
}

}  // namespace fedsim::launcher
