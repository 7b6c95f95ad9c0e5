// Crash and rejoin, over DDS with real processes: the flight federate killed in the middle of a
// lockstep run under `fedsim run` comes back (restart: on-failure), is taken back into the frame
// and gets the weather and the failure sent earlier by `fedsim command` processes that have
// long exited (the timing federate holds them). Negative controls: with --no-hold-commands the
// restarted flight federate gets neither; with restart: no the run ends failed. And a
// federate stopped with SIGSTOP in a realtime run is reported lost within the stated time
// (--ack-timeout of its first unacknowledged tick; before the fix: never), and rejoined after
// SIGCONT. Each test has its own DDS domain (211-215); about 50 s in all, each under 13 s.
#include "common/runtime/dds_participant.hpp"
#include "common/util/build_paths.hpp"
#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"
#include "common/runtime/topic_catalogue.hpp"
#include "common/util/child_process.hpp"
#include "common/util/monotonic_clock.hpp"
#include "common/util/wait_until.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <thread>

namespace fedsim::testing {
namespace {

using util::ChildProcess;
using util::read_file;

std::string bin(const std::string& name) { return fedsim::util::bin_dir() + "/" + name; }

/// Everything said on fedsim/federate_status: each federate's latest status, and every message.
class StatusWatch {
 public:
  explicit StatusWatch(int domain) {
    runtime::ParticipantOptions o;
    o.name = "rejoin-test";
    o.domain_id = domain;
    o.qos_file = runtime::default_qos_file();
    dds_ = runtime::DdsParticipant::create(o);
    sub_ = std::make_unique<runtime::Subscription<msg::FederateStatus>>(
        dds_, runtime::topics::federate_status, runtime::qos::kStatus,
        [this](const msg::FederateStatus& s, const auto&) {
          std::lock_guard lock(mutex_);
          latest_[s.federate().to_string()] = s;
          if (!s.message().to_string().empty()) {
            messages_.push_back(s.federate().to_string() + ": " + s.message().to_string());
          }
        });
    commands_ = std::make_unique<runtime::Publisher<msg::SimCommand>>(
        dds_, runtime::topics::sim_command, runtime::qos::kCommand);
  }
  ~StatusWatch() { sub_->close(); }

  /// Waits (at most timeout_s) until `done` holds; false on timeout.
  bool wait_until(double timeout_s, const std::function<bool()>& done) {
    return util::wait_until(done, timeout_s, std::chrono::milliseconds(20));
  }
  bool running(const std::string& name, std::uint32_t not_pid = 0) {
    std::lock_guard lock(mutex_);
    const auto it = latest_.find(name);
    return it != latest_.end() && it->second.state() == msg::FEDERATE_RUNNING &&
           it->second.pid() != not_pid && it->second.pid() != 0;
  }
  msg::FederateStatus latest(const std::string& name) {
    std::lock_guard lock(mutex_);
    return latest_[name];
  }
  bool said(const std::string& needle) {
    std::lock_guard lock(mutex_);
    for (const auto& m : messages_) {
      if (m.find(needle) != std::string::npos) return true;
    }
    return false;
  }
  std::string all_messages() {
    std::lock_guard lock(mutex_);
    std::string out;
    for (const auto& m : messages_) out += m + "\n";
    return out;
  }
  void shutdown() {
    msg::SimCommand c;
    c.kind(msg::COMMAND_SHUTDOWN);
    c.issuer("rejoin-test");
    commands_->publish(c);
  }

 private:
  std::shared_ptr<runtime::DdsParticipant> dds_;
  std::unique_ptr<runtime::Subscription<msg::FederateStatus>> sub_;
  std::unique_ptr<runtime::Publisher<msg::SimCommand>> commands_;
  std::mutex mutex_;
  std::map<std::string, msg::FederateStatus> latest_;
  std::vector<std::string> messages_;
};

struct RunCase {
  int domain;
  bool hold_commands = true;
  bool restart = true;
  std::string mode = "lockstep";
};

struct RunResult {
  std::string run_output;
  int run_exit = 0;
  std::string flight_log;      // every flight process's log, restarts appended
  std::string after_restart;   // the part written after the restart marker ("" if none)
  nlohmann::json timing_summary;
  bool restarted_running = false;
};

/// `fedsim run` of the timing and flight federates (lockstep, paced at real time); sends a
/// weather and an engine failure with `fedsim command`, kills the flight federate, waits for it
/// to come back (or not), and ends the run with a SHUTDOWN command.
RunResult crash_and_rejoin(const RunCase& rc) {
  const std::string dir = util::temp_dir("rejoin" + std::to_string(rc.domain));
  std::ofstream(dir + "/rejoin.yaml")
      << "name: rejoin\nmode: " << rc.mode << "\nrate_hz: 50\n"
      << "qos_file: " << runtime::default_qos_file() << "\n"
      << "timing: {args: [--scale, \"1\", --ack-timeout, \"3\""
      << (rc.hold_commands ? "" : ", --no-hold-commands") << "]}\n"
      << "federates:\n"
      << "  - name: flight\n    binary: fedsim-flight\n"
      << "    args: [--aircraft, \"${DATA_DIR}/aircraft/c172.yaml\", --trim, level, --alt-ft, \"4000\","
      << " --ktas, \"100\", --heading, \"90\", --lat, \"37.6\", --lon, \"-122.3\"]\n"
      << (rc.restart ? "    restart: on-failure\n" : "");
  StatusWatch watch(rc.domain);
  ChildProcess run({bin("fedsim"), "run", dir + "/rejoin.yaml", "--domain", std::to_string(rc.domain),
                    "--out", dir + "/out", "--duration", "40", "--progress", "0"},
                   dir + "/run.log");
  RunResult r;
  const std::string flight_log = dir + "/out/logs/flight.log";
  EXPECT_TRUE(watch.wait_until(20, [&] { return watch.running("flight") && watch.running("timing"); }))
      << read_file(dir + "/run.log");
  const std::string domain = std::to_string(rc.domain);
  ChildProcess weather({bin("fedsim"), "command", "weather", "--wind-from", "270", "--wind-kt", "25",
                        "--domain", domain}, dir + "/weather.log");
  EXPECT_TRUE(weather.wait(20));
  ChildProcess failure({bin("fedsim"), "command", "fail", "engine1", "--domain", domain}, dir + "/fail.log");
  EXPECT_TRUE(failure.wait(20));
  EXPECT_EQ(failure.exit_code(), 0) << read_file(dir + "/fail.log");
  EXPECT_EQ(weather.exit_code(), 0) << read_file(dir + "/weather.log");
  EXPECT_TRUE(watch.wait_until(10, [&] {
    const std::string log = read_file(flight_log);
    return log.find("weather set") != std::string::npos && log.find("engine1 failed") != std::string::npos;
  })) << read_file(flight_log);
  const std::uint32_t old_pid = watch.latest("flight").pid();
  ::kill(static_cast<pid_t>(old_pid), SIGKILL);
  bool run_ended = false;
  r.restarted_running = watch.wait_until(15, [&] {
    run_ended = run_ended || !run.running();
    return run_ended || (watch.running("flight", old_pid) && watch.latest("flight").frames_done() > 25);
  }) && !run_ended;
  if (r.restarted_running) {
    watch.wait_until(5, [&] { return watch.said("rejoined flight"); });
    watch.shutdown();
  }
  EXPECT_TRUE(run.wait(30)) << read_file(dir + "/run.log");
  r.run_exit = run.exit_code();
  r.run_output = read_file(dir + "/run.log");
  r.flight_log = read_file(flight_log);
  const auto marker = r.flight_log.find("---- fedsim run: flight crashed");
  if (marker != std::string::npos) r.after_restart = r.flight_log.substr(marker);
  std::ifstream summary(dir + "/out/logs/timing_summary.json");
  if (summary) summary >> r.timing_summary;
  return r;
}

std::vector<std::string> strings(const nlohmann::json& j, const char* key) {
  return j.contains(key) ? j[key].get<std::vector<std::string>>() : std::vector<std::string>{};
}

TEST(CrashAndRejoin, RestartedFlightRejoinsLockstepWithTheHeldWeatherAndFailure) {
  const RunResult r = crash_and_rejoin({211, true, true});
  ASSERT_TRUE(r.restarted_running) << r.run_output;
  EXPECT_NE(r.run_output.find("flight crashed (killed by Killed): restarting it (restart 1 of at most 3)"),
            std::string::npos) << r.run_output;
  // The new process got the settings from the holder: the commands' senders had exited.
  EXPECT_NE(r.after_restart.find("weather set"), std::string::npos) << r.after_restart;
  EXPECT_NE(r.after_restart.find("engine1 failed"), std::string::npos) << r.after_restart;
  // Taken back into lockstep: lost once, rejoined, and frames went on after its return.
  EXPECT_EQ(strings(r.timing_summary, "lost"), std::vector<std::string>{"flight"}) << r.timing_summary;
  EXPECT_EQ(strings(r.timing_summary, "rejoined"), std::vector<std::string>{"flight"});
  EXPECT_TRUE(strings(r.timing_summary, "still_lost").empty());
  ASSERT_EQ(r.timing_summary["membership"].size(), 2u);
  EXPECT_GT(r.timing_summary["frames"].get<std::uint64_t>(),
            r.timing_summary["membership"][1]["frame"].get<std::uint64_t>() + 25);
  EXPECT_NE(r.run_output.find("fedsim run: rejoined flight at frame"), std::string::npos);
  // A crash is a failure of the run, even with the federate back.
  EXPECT_NE(r.run_output.find("restarted after a crash: flight x1"), std::string::npos);
  EXPECT_EQ(r.run_exit, 1);
}

// Realtime: the restarted federate is reported back (the ticks never waited for it) and gets the
// held settings as well.
TEST(CrashAndRejoin, RestartedFlightRejoinsARealtimeRunWithTheHeldSettings) {
  const RunResult r = crash_and_rejoin({215, true, true, "realtime"});
  ASSERT_TRUE(r.restarted_running) << r.run_output;
  EXPECT_NE(r.after_restart.find("weather set"), std::string::npos) << r.after_restart;
  EXPECT_NE(r.after_restart.find("engine1 failed"), std::string::npos) << r.after_restart;
  EXPECT_EQ(strings(r.timing_summary, "lost"), std::vector<std::string>{"flight"}) << r.timing_summary;
  EXPECT_EQ(strings(r.timing_summary, "rejoined"), std::vector<std::string>{"flight"});
  EXPECT_EQ(r.run_exit, 1);
}

// Negative control: without the holder the restarted federate rejoins but gets no setting.
TEST(CrashAndRejoin, WithoutTheHolderTheRestartedFlightGetsNoSetting) {
  const RunResult r = crash_and_rejoin({212, false, true});
  ASSERT_TRUE(r.restarted_running) << r.run_output;
  ASSERT_FALSE(r.after_restart.empty()) << r.flight_log;
  EXPECT_EQ(r.after_restart.find("weather set"), std::string::npos) << r.after_restart;
  EXPECT_EQ(r.after_restart.find("engine1 failed"), std::string::npos) << r.after_restart;
  EXPECT_EQ(strings(r.timing_summary, "rejoined"), std::vector<std::string>{"flight"});
}

// Negative control: without restart: on-failure the crash ends the run, failed.
TEST(CrashAndRejoin, WithoutRestartTheCrashEndsTheRun) {
  const RunResult r = crash_and_rejoin({213, true, false});
  EXPECT_FALSE(r.restarted_running);
  EXPECT_EQ(r.run_output.find("restarting it"), std::string::npos) << r.run_output;
  EXPECT_NE(r.run_output.find("flight failed (killed by Killed)"), std::string::npos) << r.run_output;
  EXPECT_EQ(r.run_exit, 1);
}

// Realtime: ticks go out every frame whatever the acknowledgements; a stopped federate must
// still be reported lost, within --ack-timeout (3 s here) of its first unacknowledged tick. (The
// 1.5 s liveliness lease of its frame_done writer never lapsed for a stopped process here: the
// acknowledgement age is the bound.) The control: nothing is lost while it runs.
TEST(CrashAndRejoin, StoppedFederateIsReportedLostInRealtimeAndRejoinsWhenContinued) {
  const int domain = 214;
  const std::string dir = util::temp_dir("sigstop");
  const std::vector<std::string> dds = {"--domain", std::to_string(domain), "--qos-file",
                                        runtime::default_qos_file()};
  StatusWatch watch(domain);
  std::vector<std::string> s_argv{bin("fedsim-synthetic"), "--name", "s"};
  s_argv.insert(s_argv.end(), dds.begin(), dds.end());
  ChildProcess s(s_argv, dir + "/s.log");
  std::vector<std::string> t_argv{bin("fedsim-timing"), "--name", "timing", "--mode", "realtime",
                                  "--rate", "50", "--expect", "s", "--ack-timeout", "3",
                                  "--summary-json", dir + "/summary.json"};
  t_argv.insert(t_argv.end(), dds.begin(), dds.end());
  ChildProcess timing(t_argv, dir + "/timing.log");
  ASSERT_TRUE(watch.wait_until(20, [&] { return watch.running("s") && watch.latest("timing").frames_done() > 50; }))
      << timing.output();
  EXPECT_FALSE(watch.said("lost")) << watch.all_messages();  // control: a live federate is not lost
  ::kill(s.pid(), SIGSTOP);
  const std::uint64_t stopped_ns = util::monotonic_ns();
  const bool reported = watch.wait_until(10, [&] { return watch.said("lost s at frame"); });
  const double delay_s = (util::monotonic_ns() - stopped_ns) * 1e-9;
  // Its own instance says LOST, looked at while it is still stopped: once continued, its own
  // RUNNING status may come first (and the LOST sample may trail the message by a moment).
  const bool instance_lost = watch.wait_until(5, [&] { return watch.latest("s").state() == msg::FEDERATE_LOST; });
  ::kill(s.pid(), SIGCONT);
  ASSERT_TRUE(reported) << watch.all_messages() << timing.output();
  std::printf("SIGSTOP -> reported lost after %.2f s (%s)\n", delay_s,
              watch.said("liveliness") ? "liveliness" : "acknowledgement age");
  EXPECT_LT(delay_s, 3.0 + 1.0);  // the stated bound (--ack-timeout) plus a second for delivery
  EXPECT_TRUE(instance_lost) << "state " << watch.latest("s").state();
  EXPECT_TRUE(watch.wait_until(10, [&] { return watch.said("rejoined s"); })) << watch.all_messages();
  timing.terminate();
  ASSERT_TRUE(timing.wait(10));
  nlohmann::json summary;
  std::ifstream(dir + "/summary.json") >> summary;
  EXPECT_EQ(strings(summary, "lost"), std::vector<std::string>{"s"}) << summary;
  EXPECT_EQ(strings(summary, "rejoined"), std::vector<std::string>{"s"});
  EXPECT_TRUE(strings(summary, "still_lost").empty());
  s.terminate();
  s.wait(5);
}

}  // namespace
}  // namespace fedsim::testing
