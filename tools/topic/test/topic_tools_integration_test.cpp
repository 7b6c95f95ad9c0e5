// Integration tests over loopback (profile fedsim_loopback, one domain per test in 160-169): an
// in-process runtime::Publisher<T> writes, the tools discover, print and record it.
#include "tools/topic/test/test_support.hpp"
#include "tools/topic/raw_type.hpp"
#include "tools/topic/topic_commands.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace fedsim::tools {
namespace {

using namespace std::chrono_literals;

using test::loopback;

/// "RELIABLE TRANSIENT_LOCAL" etc. for a writer's actual QoS (the profiles belong to qos/).
template <class T>
std::string qos_text(const runtime::Publisher<T>& pub) {
  const auto qos = pub.writer()->get_qos();
  std::string text = qos.reliability().kind == eprosima::fastdds::dds::RELIABLE_RELIABILITY_QOS
                         ? "RELIABLE "
                         : "BEST_EFFORT ";
  switch (qos.durability().kind) {
    case eprosima::fastdds::dds::VOLATILE_DURABILITY_QOS: return text + "VOLATILE";
    case eprosima::fastdds::dds::TRANSIENT_LOCAL_DURABILITY_QOS: return text + "TRANSIENT_LOCAL";
    case eprosima::fastdds::dds::TRANSIENT_DURABILITY_QOS: return text + "TRANSIENT";
    default: return text + "PERSISTENT";
  }
}

msg::AircraftState state_of_frame(std::uint64_t frame) {
  msg::AircraftState s;
  s.aircraft_id(0);
  s.stamp().frame(frame);
  s.stamp().sim_time_s(frame * 0.02);
  s.velocity_ned_mps({frame * 0.5, -1.25, 1.0 / 3.0});
  s.gear_count(2);
  s.gear()[1].compression_m(0.25f);
  return s;
}

/// Publishes AircraftState samples (frame 1, 2, ...) every `period` until destroyed.
class PeriodicStatePublisher {
 public:
  PeriodicStatePublisher(std::shared_ptr<runtime::DdsParticipant> dds, const std::string& profile,
                         std::chrono::milliseconds period)
      : pub_(std::move(dds), runtime::topics::aircraft_state, profile) {
    thread_ = std::thread([this, period] {
      while (running_.load()) {
        pub_.publish(state_of_frame(++frame_));
        std::this_thread::sleep_for(period);
      }
    });
  }
  ~PeriodicStatePublisher() {
    running_.store(false);
    thread_.join();
  }
  std::uint64_t frames() const { return frame_.load(); }

 private:
  runtime::Publisher<msg::AircraftState> pub_;
  std::atomic<bool> running_{true};
  std::atomic<std::uint64_t> frame_{0};
  std::thread thread_;
};

std::vector<std::string> read_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("fedsim_topic_tools_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

msg::SimCommand reposition_command() {
  msg::SimCommand cmd;
  cmd.kind(msg::COMMAND_REPOSITION);
  cmd.target("ownship");
  cmd.sequence_number(12);
  cmd.issuer("ios-test");
  cmd.reposition().kind(msg::REPOSITION_RUNWAY_THRESHOLD);
  cmd.reposition().airport("KSFO");
  cmd.reposition().runway("28L");
  cmd.reposition().heading_rad(4.9);
  return cmd;
}

TEST(TopicList, ShowsPublishedTopicsWithTypeCountsAndQos) {
  auto dds = runtime::DdsParticipant::create(loopback(160, "list_test_publisher"));
  runtime::Publisher<msg::AircraftState> state(dds, runtime::topics::aircraft_state, runtime::qos::kState);
  runtime::Publisher<msg::SimCommand> command(dds, runtime::topics::sim_command, runtime::qos::kCommand);
  runtime::Subscription<msg::SimCommand> command_sub(dds, runtime::topics::sim_command, runtime::qos::kCommand);

  ListOptions options;
  options.dds = loopback(160, "fedsim");
  options.wait_s = 1.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_topic_list(options, out, err), 0) << err.str();
  const std::string text = out.str();
  EXPECT_NE(text.find("fedsim/aircraft_state  [fedsim::msg::AircraftState]  1 writer, 0 readers"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("fedsim/sim_command     [fedsim::msg::SimCommand]  1 writer, 1 reader"),
            std::string::npos)
      << text;

  options.verbose = true;
  std::ostringstream verbose;
  ASSERT_EQ(run_topic_list(options, verbose, err), 0) << err.str();
  const std::string v = verbose.str();
  EXPECT_NE(v.find("fedsim/aircraft_state [fedsim::msg::AircraftState]\n  1 writer:\n"
                   "    - list_test_publisher  " + qos_text(state) + " keyed  guid="),
            std::string::npos)
      << v;
  EXPECT_NE(v.find("fedsim/sim_command [fedsim::msg::SimCommand]\n  1 writer:\n"
                   "    - list_test_publisher  " + qos_text(command) + " keyed  guid="),
            std::string::npos)
      << v;
  EXPECT_NE(v.find("  1 reader:\n    - list_test_publisher  "), std::string::npos) << v;
}

TEST(TopicList, RunsThroughTheCli) {
  auto dds = runtime::DdsParticipant::create(loopback(161, "cli_test_publisher"));
  runtime::Publisher<msg::FrameTick> tick(dds, runtime::topics::frame_tick, runtime::qos::kTick);
  CLI::App app{"fedsim"};
  add_topic_commands(app);
  testing::internal::CaptureStdout();
  app.parse(std::vector<std::string>{"0.5", "--wait", "--domain=161", "list", "topic"});
  const std::string text = testing::internal::GetCapturedStdout();
  EXPECT_NE(text.find("fedsim/frame_tick  [fedsim::msg::FrameTick]  1 writer, 0 readers"),
            std::string::npos)
      << text;
}

TEST(TopicList, WorksForTypesOutsideFedsim) {
  // A writer of a type this build has no TypeObject for (raw CDR bytes under a foreign name).
  auto dds = runtime::DdsParticipant::create(loopback(168, "foreign_publisher"));
  auto* topic = dds->topic_for("vendor/opaque", eprosima::fastdds::dds::TypeSupport(
                                                    new RawPubSubType("vendor::Opaque", false, 64)));
  auto* writer = dds->publisher()->create_datawriter_with_profile(topic, "state");
  ASSERT_NE(writer, nullptr);
  std::atomic<bool> running{true};
  std::thread publisher([&] {
    RawSample sample{{0x00, 0x01, 0x00, 0x00, 1, 2, 3, 4}};  // CDR_LE encapsulation + 4 bytes
    while (running.load()) {
      writer->write(&sample);
      std::this_thread::sleep_for(10ms);  // a stream at ~100 Hz (pacing, not waiting)
    }
  });

  ListOptions list;
  list.dds = loopback(168, "fedsim");
  list.wait_s = 1.0;
  std::ostringstream out, err;
  EXPECT_EQ(run_topic_list(list, out, err), 0) << err.str();
  EXPECT_NE(out.str().find("vendor/opaque  [vendor::Opaque]  1 writer, 0 readers"),
            std::string::npos)
      << out.str();

  HzOptions hz;
  hz.dds = loopback(168, "fedsim");
  hz.topic = "vendor/opaque";
  hz.duration_s = 1.0;
  std::ostringstream hz_out;
  EXPECT_EQ(run_topic_hz(hz, hz_out, err), 0) << err.str();
  EXPECT_NE(hz_out.str().find("average rate: "), std::string::npos) << hz_out.str();

  // echo needs the type: a clear error, and exit code 1 through the CLI.
  CLI::App app{"fedsim"};
  add_topic_commands(app);
  testing::internal::CaptureStderr();
  int code = 0;
  try {
    app.parse(std::vector<std::string>{"vendor/opaque", "--domain=168", "echo", "topic"});
  } catch (const CLI::RuntimeError& e) {
    code = e.get_exit_code();
  }
  const std::string echo_err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 1);
  EXPECT_NE(echo_err.find("type 'vendor::Opaque' of topic 'vendor/opaque' is unknown"),
            std::string::npos)
      << echo_err;
  running.store(false);
  publisher.join();
  dds->publisher()->delete_datawriter(writer);
}

TEST(TopicEcho, PrintsTheLatestTransientLocalCommand) {
  auto dds = runtime::DdsParticipant::create(loopback(162, "echo_test_publisher"));
  runtime::Publisher<msg::SimCommand> command(dds, runtime::topics::sim_command, runtime::qos::kCommand);
  ASSERT_TRUE(command.publish(reposition_command()));  // before echo exists: durability shows it

  EchoOptions options;
  options.dds = loopback(162, "fedsim");
  options.topic = msg::TOPIC_SIM_COMMAND;
  options.count = 1;
  options.timeout_s = 5.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_topic_echo(options, out, err), 0) << err.str();
  EXPECT_EQ(out.str().rfind("kind: COMMAND_REPOSITION\ntarget: \"ownship\"\nsequence_number: 12\n"
                            "issuer: \"ios-test\"\nrun_state: RUN_STATE_RUN\nreposition:\n"
                            "  kind: REPOSITION_RUNWAY_THRESHOLD\n  airport: \"KSFO\"\n"
                            "  runway: \"28L\"\n",
                            0),
            0u)
      << out.str();
  EXPECT_NE(out.str().find("  heading_rad: 4.9\n"), std::string::npos) << out.str();
  EXPECT_EQ(out.str().substr(out.str().size() - 4), "---\n");
}

TEST(TopicEcho, PrintsAFieldOfABestEffortStream) {
  auto dds = runtime::DdsParticipant::create(loopback(163, "echo_field_publisher"));
  PeriodicStatePublisher publisher(dds, "state", 10ms);
  EchoOptions options;
  options.dds = loopback(163, "fedsim");
  options.topic = msg::TOPIC_AIRCRAFT_STATE;
  options.count = 2;
  options.field = "velocity_ned_mps";
  options.timeout_s = 5.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_topic_echo(options, out, err), 0) << err.str();
  const std::string text = out.str();
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u) << text;  // 2 x (value, ---)
  for (std::size_t i : {0u, 2u}) {
    EXPECT_EQ(lines[i].front(), '[') << text;
    EXPECT_NE(lines[i].find(", -1.25, 0.3333333333333333]"), std::string::npos) << text;
    EXPECT_EQ(lines[i + 1], "---");
  }

  options.json = true;
  options.field.clear();
  options.count = 1;
  std::ostringstream json;
  ASSERT_EQ(run_topic_echo(options, json, err), 0) << err.str();
  EXPECT_EQ(json.str().rfind("{\"aircraft_id\":0,\"stamp\":{\"frame\":", 0), 0u) << json.str();
}

TEST(TopicEcho, FailsClearlyOnAnUnknownTopicOrField) {
  EchoOptions options;
  options.dds = loopback(164, "fedsim");
  options.topic = "fedsim/no_such_topic";
  options.wait_s = 0.5;
  std::ostringstream out, err;
  EXPECT_EQ(run_topic_echo(options, out, err), 1);
  EXPECT_NE(err.str().find("topic 'fedsim/no_such_topic' not found on domain 164 after 0.5 s"),
            std::string::npos)
      << err.str();

  auto dds = runtime::DdsParticipant::create(loopback(164, "echo_error_publisher"));
  runtime::Publisher<msg::SimCommand> command(dds, runtime::topics::sim_command, runtime::qos::kCommand);
  options.topic = msg::TOPIC_SIM_COMMAND;
  options.field = "reposition.altitude";
  options.wait_s = 3.0;
  std::ostringstream err2;
  EXPECT_EQ(run_topic_echo(options, out, err2), 1);
  EXPECT_NE(err2.str().find("no field 'altitude' in 'reposition'"), std::string::npos)
      << err2.str();
}

TEST(TopicHz, ReportsTheRateOfAKeyedStream) {
  auto dds = runtime::DdsParticipant::create(loopback(165, "hz_test_publisher"));
  PeriodicStatePublisher publisher(dds, "state", 20ms);  // ~50 Hz (sleep granularity: a bit less)
  HzOptions options;
  options.dds = loopback(165, "fedsim");
  options.topic = msg::TOPIC_AIRCRAFT_STATE;
  options.duration_s = 2.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_topic_hz(options, out, err), 0) << err.str();
  const std::string text = out.str();
  const auto last = text.rfind("average rate: ");
  ASSERT_NE(last, std::string::npos) << text;
  const double rate = std::stod(text.substr(last + 14));
  EXPECT_GT(rate, 30.0) << text;
  EXPECT_LT(rate, 55.0) << text;
  EXPECT_NE(text.find("\tmin: 0.0"), std::string::npos) << text;
  EXPECT_NE(text.find(" std dev: "), std::string::npos) << text;
}

TEST(Record, WritesOneCsvPerTopicWithHeaderAndEveryReliableSample) {
  auto dds = runtime::DdsParticipant::create(loopback(166, "record_test_publisher"));
  runtime::Publisher<msg::SimCommand> command(dds, runtime::topics::sim_command, runtime::qos::kCommand);
  ASSERT_TRUE(command.publish(reposition_command()));
  const auto dir = fresh_dir("record");
  std::uint64_t published = 0;
  RecordOptions options;
  options.dds = loopback(166, "fedsim");
  options.topics = {msg::TOPIC_AIRCRAFT_STATE, msg::TOPIC_SIM_COMMAND};
  options.out_dir = dir.string();
  options.duration_s = 1.5;
  std::ostringstream out, err;
  {
    PeriodicStatePublisher publisher(dds, "lockstep_data", 5ms);  // reliable
    ASSERT_EQ(run_record(options, out, err), 0) << err.str();
    published = publisher.frames();
  }
  EXPECT_NE(out.str().find("recording fedsim/aircraft_state [fedsim::msg::AircraftState] "
                           "(1 writer, RELIABLE "),
            std::string::npos)
      << out.str();

  const auto state = read_lines(dir / "fedsim_aircraft_state.csv");
  ASSERT_GT(state.size(), 20u) << out.str() << err.str();
  EXPECT_EQ(state[0].rfind("sim_time_s,aircraft_id,stamp.frame,stamp.sim_time_s,latitude_rad,", 0),
            0u)
      << state[0];
  const auto header = split(state[0]);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(col("velocity_ned_mps[2]"), header.size());
  ASSERT_LT(col("gear[1].compression_m"), header.size());
  std::uint64_t previous = 0;
  for (std::size_t i = 1; i < state.size(); ++i) {
    const auto row = split(state[i]);
    ASSERT_EQ(row.size(), header.size()) << state[i];
    const std::uint64_t frame = std::stoull(row[col("stamp.frame")]);
    if (i > 1) {
      EXPECT_EQ(frame, previous + 1) << "a reliable sample was lost";
    }
    previous = frame;
    EXPECT_EQ(std::stod(row[0]), frame * 0.02);
    EXPECT_EQ(std::stod(row[col("velocity_ned_mps[0]")]), frame * 0.5);
    EXPECT_EQ(row[col("velocity_ned_mps[1]")], "-1.25");
    EXPECT_EQ(std::stod(row[col("velocity_ned_mps[2]")]), 1.0 / 3.0);
    EXPECT_EQ(row[col("gear[1].compression_m")], "0.25");
  }
  EXPECT_LE(previous, published);

  const auto commands = read_lines(dir / "fedsim_sim_command.csv");
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].rfind("receive_time_s,kind,target,sequence_number,issuer,run_state,", 0),
            0u)
      << commands[0];
  const auto row = split(commands[1]);
  EXPECT_GT(std::stod(row[0]), 1.6e9);  // reception time, Unix seconds
  EXPECT_EQ(row[1], "1");               // COMMAND_REPOSITION as an integer
  EXPECT_EQ(row[2], "ownship");
  EXPECT_EQ(row[3], "12");
  std::filesystem::remove_all(dir);
}

TEST(Record, LockstepMemberRecordsEveryFrameBeforeAcknowledging) {
  constexpr int kDomain = 167;
  constexpr std::uint64_t kFrames = 40;
  auto dds = runtime::DdsParticipant::create(loopback(kDomain, "lockstep_test_timing"));
  runtime::Publisher<msg::AircraftState> state(dds, runtime::topics::aircraft_state, runtime::qos::kLockstepData);
  runtime::Publisher<msg::FrameTick> tick(dds, runtime::topics::frame_tick, runtime::qos::kTick);
  std::mutex done_mutex;
  std::condition_variable done_cv;
  std::uint64_t acknowledged = 0;
  runtime::Subscription<msg::FrameDone> done(
      dds, runtime::topics::frame_done, runtime::qos::kFrameDone, [&](const msg::FrameDone& d, const auto&) {
        if (d.federate() != "test_recorder") return;
        std::lock_guard lock(done_mutex);
        acknowledged = std::max<std::uint64_t>(acknowledged, d.frame());
        done_cv.notify_all();
      });

  const auto dir = fresh_dir("lockstep");
  RecordOptions options;
  options.dds = loopback(kDomain, "fedsim");
  options.topics = {msg::TOPIC_AIRCRAFT_STATE};
  options.out_dir = dir.string();
  options.lockstep_member = true;
  options.name = "test_recorder";
  options.max_frames = kFrames;
  options.input_timeout_s = 5.0;  // a missing sample would stall, not be skipped
  options.log_level = "warn";
  std::ostringstream out, err;
  int rc = -1;
  std::thread recorder([&] { rc = run_record(options, out, err); });

  ASSERT_TRUE(tick.wait_for_readers(1, 8s)) << "recorder federate did not appear";
  ASSERT_TRUE(state.wait_for_readers(1, 8s)) << "recorder did not subscribe";
  ASSERT_TRUE(done.wait_for_writers(1, 8s));
  bool all_acknowledged = true;
  for (std::uint64_t frame = 1; frame <= kFrames && all_acknowledged; ++frame) {
    state.publish(state_of_frame(frame - 1));  // the output of the previous frame
    msg::FrameTick t;
    t.frame(frame);
    t.sim_frame(frame);
    t.sim_time_s(frame * 0.02);
    t.dt_s(0.02);
    t.frame_period_s(0.02);
    t.run_state(msg::RUN_STATE_RUN);
    t.mode(msg::TIMING_MODE_LOCKSTEP);
    // Like the timing federate: repeat the tick until it is acknowledged (the first ones may
    // come before the federate's loop accepts ticks).
    all_acknowledged = false;
    for (int attempt = 0; attempt < 10 && !all_acknowledged; ++attempt) {
      tick.publish(t);
      std::unique_lock lock(done_mutex);
      all_acknowledged = done_cv.wait_for(lock, 500ms, [&] { return acknowledged >= frame; });
    }
  }
  recorder.join();
  EXPECT_TRUE(all_acknowledged) << out.str() << err.str();
  EXPECT_EQ(rc, 0) << err.str();

  const auto lines = read_lines(dir / "fedsim_aircraft_state.csv");
  ASSERT_EQ(lines.size(), 1 + kFrames) << out.str() << err.str();  // header + frames 0..N-1
  for (std::uint64_t frame = 0; frame < kFrames; ++frame) {
    EXPECT_EQ(split(lines[1 + frame])[2], std::to_string(frame));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fedsim::tools
