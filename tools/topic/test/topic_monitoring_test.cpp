// `fedsim topic info` and `fedsim topic bw` over loopback (profile fedsim_loopback, domains 170,
// 176, 182 and 183: not the replay tests' 171-175, which ctest -j runs beside these): an in-process runtime::Publisher writes, the tools discover and measure it.
#include "tools/topic/test/test_support.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace fedsim::tools {
namespace {

using namespace std::chrono_literals;

using test::loopback;

TEST(TopicInfo, ShowsTheWritersAndReadersQosParticipantAndLocators) {
  auto dds = runtime::DdsParticipant::create(loopback(170, "info_test_io"));
  runtime::Publisher<msg::PilotControls> controls(dds, runtime::topics::pilot_controls,
                                                  runtime::qos::kPilotControls);
  runtime::Subscription<msg::AircraftState> state(dds, runtime::topics::aircraft_state,
                                                  runtime::qos::kState);
  InfoOptions options;
  options.dds = loopback(170, "fedsim");
  options.topic = "fedsim/pilot_controls";
  options.wait_s = 1.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_topic_info(options, out, err), 0) << err.str();
  const std::string text = out.str();
  EXPECT_NE(text.find("topic: fedsim/pilot_controls\ntype: fedsim::msg::PilotControls\n"
                      "writers: 1\n  - participant: info_test_io\n"),
            std::string::npos)
      << text;
  // The profile's QoS (qos/fedsim_qos.xml: pilot_controls), as discovery announced it.
  EXPECT_NE(text.find("    reliability: RELIABLE\n    durability: TRANSIENT_LOCAL\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("    ownership: EXCLUSIVE, strength 10\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    unicast locators: UDPv4:[127.0.0.1]:"), std::string::npos) << text;
  EXPECT_NE(text.find("readers: 0\n"), std::string::npos) << text;

  // The reader side of another topic; and an absent topic fails, naming it (negative control).
  options.topic = "fedsim/aircraft_state";
  std::ostringstream reader_text;
  ASSERT_EQ(run_topic_info(options, reader_text, err), 0) << err.str();
  EXPECT_NE(reader_text.str().find("writers: 0\nreaders: 1\n  - participant: info_test_io\n"),
            std::string::npos)
      << reader_text.str();
  EXPECT_NE(reader_text.str().find("    reliability: BEST_EFFORT\n"), std::string::npos)
      << reader_text.str();
  options.topic = "fedsim/no_such_topic";
  options.wait_s = 0.3;
  std::ostringstream none_out, none_err;
  EXPECT_EQ(run_topic_info(options, none_out, none_err), 1);
  EXPECT_NE(none_err.str().find("topic 'fedsim/no_such_topic' not found on domain 170"),
            std::string::npos)
      << none_err.str();
}

TEST(TopicBw, MeasuresBytesAndSamplesPerSecondOfAStream) {
  auto dds = runtime::DdsParticipant::create(loopback(176, "bw_test_publisher"));
  runtime::Publisher<msg::AircraftState> pub(dds, runtime::topics::aircraft_state,
                                             runtime::qos::kState);
  std::atomic<bool> running{true};
  std::thread writer([&] {
    msg::AircraftState s;
    for (std::uint64_t frame = 1; running.load(); ++frame) {
      s.stamp().frame(frame);
      pub.publish(s);
      std::this_thread::sleep_for(20ms);  // ~50 Hz (sleep granularity: a bit less)
    }
  });
  BwOptions options;
  options.dds = loopback(176, "fedsim");
  options.topic = "fedsim/aircraft_state";
  options.duration_s = 2.0;
  std::ostringstream out, err;
  const int code = run_topic_bw(options, out, err);
  running.store(false);
  writer.join();
  ASSERT_EQ(code, 0) << err.str();
  const std::string text = out.str();
  const auto last = text.rfind(" samples (");
  ASSERT_NE(last, std::string::npos) << text;
  const double rate = std::stod(text.substr(last + 10));
  EXPECT_GT(rate, 25.0) << text;
  EXPECT_LT(rate, 55.0) << text;
  // AircraftState is a fixed-size type: every sample the same size, well over 100 bytes.
  const auto mean = text.rfind("sample size mean: ");
  ASSERT_NE(mean, std::string::npos) << text;
  EXPECT_GT(std::stod(text.substr(mean + 18)), 100.0) << text;
  EXPECT_NE(text.find("KB/s from "), std::string::npos) << text;
}

TEST(Record, TwoTopicsOfOneTypeOnOneParticipant) {
  // fedsim/pilot_controls and fedsim/applied_controls are both PilotControls: the recorder's
  // second reader failed ("already has a compiled type support"), and with it the default
  // deployment. Both are recorded now (domain 183).
  auto dds = runtime::DdsParticipant::create(loopback(183, "two_topics_writer"));
  runtime::Publisher<msg::PilotControls> controls(dds, runtime::topics::pilot_controls,
                                                  runtime::qos::kPilotControls);
  runtime::Publisher<msg::PilotControls> applied(dds, runtime::topics::applied_controls,
                                                 runtime::qos::kLockstepData);
  std::atomic<bool> running{true};
  std::thread writer([&] {
    msg::PilotControls c;
    for (std::uint64_t frame = 1; running.load(); ++frame) {
      c.stamp().frame(frame);
      controls.publish(c);
      applied.publish(c);
      std::this_thread::sleep_for(20ms);  // a stream at ~50 Hz (pacing, not waiting)
    }
  });
  const auto out_dir = std::filesystem::temp_directory_path() /
                       ("fedsim_two_topics_record_" + std::to_string(::getpid()));  // runs at once apart
  std::filesystem::remove_all(out_dir);
  RecordOptions options;
  options.dds = loopback(183, "fedsim");
  options.topics = {"fedsim/pilot_controls", "fedsim/applied_controls"};
  options.out_dir = out_dir.string();
  options.duration_s = 1.5;
  options.wait_s = 2.0;
  options.progress_period_s = 0;
  std::ostringstream out, err;
  const int code = run_record(options, out, err);
  running.store(false);
  writer.join();
  ASSERT_EQ(code, 0) << err.str();
  for (const char* file : {"fedsim_pilot_controls.csv", "fedsim_applied_controls.csv"}) {
    std::ifstream csv(out_dir / file);
    std::size_t lines = 0;
    for (std::string line; std::getline(csv, line);) ++lines;
    EXPECT_GT(lines, 10u) << file << "\n" << out.str() << err.str();  // header + samples
  }
  std::filesystem::remove_all(out_dir);
}

/// Cyclone DDS's ddsperf (Debian's cyclonedds-tools), publishing its keyed KeyedSeq topic
/// DDSPerfRDataKS at 100 Hz on loopback; stopped (SIGTERM) when this goes.
class CycloneDdsperfPublisher {
 public:
  explicit CycloneDdsperfPublisher(int domain) {
    // Loopback only; Cyclone's default participant index is "none" (random ports), which
    // fedsim's unicast-only loopback discovery (initial peer 127.0.0.1, ports of indices 0-4)
    // never reaches: "auto" plus the loopback peer makes both sides find each other.
    setenv("CYCLONEDDS_URI",
           "<General><Interfaces><NetworkInterface address=\"127.0.0.1\" multicast=\"true\"/>"
           "</Interfaces></General><Discovery><ParticipantIndex>auto</ParticipantIndex>"
           "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>",
           1);
    const std::string domain_text = std::to_string(domain);
    std::vector<std::string> args = {"ddsperf", "-i", domain_text, "-D", "30", "pub", "100Hz"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    if (posix_spawnp(&pid_, "ddsperf", &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    unsetenv("CYCLONEDDS_URI");
  }
  ~CycloneDdsperfPublisher() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
  }
  bool started() const { return pid_ > 0; }

 private:
  pid_t pid_ = -1;
};

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

TEST(TopicHz, SurvivesAKeyedForeignTypeWrittenWithoutKeyHashes) {
  // Issue 11: `fedsim topic hz` on a keyed topic of a type fedsim does not know, written by
  // Cyclone DDS (which sends no key hash), aborted in a Fast DDS assertion (exit 134): the raw
  // type's getKey failed. Now it reports the rate, and bw the sizes (domain 182).
  if (!on_path("ddsperf")) GTEST_SKIP() << "ddsperf (cyclonedds-tools) not installed";
  CycloneDdsperfPublisher cyclone(182);
  ASSERT_TRUE(cyclone.started());
  HzOptions hz;
  hz.dds = loopback(182, "fedsim");
  hz.topic = "DDSPerfRDataKS";
  hz.wait_s = 10.0;
  hz.duration_s = 2.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_topic_hz(hz, out, err), 0) << err.str();
  EXPECT_NE(out.str().find("average rate: "), std::string::npos) << out.str() << err.str();

  BwOptions bw;
  bw.dds = loopback(182, "fedsim");
  bw.topic = "DDSPerfRDataKS";
  bw.wait_s = 5.0;
  bw.duration_s = 2.0;
  std::ostringstream bw_out;
  ASSERT_EQ(run_topic_bw(bw, bw_out, err), 0) << err.str();
  EXPECT_NE(bw_out.str().find(" samples/s)\n\tsample size mean: "), std::string::npos)
      << bw_out.str() << err.str();
}

}  // namespace
}  // namespace fedsim::tools
