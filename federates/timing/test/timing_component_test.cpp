// fedsim-timing's adapter without DDS: its ports bound to a test host that records what it writes
// and hands it samples as the middleware would. The ports it declares (what --print-ports and
// fedsim graph show), a held setting republished once (and not with --no-hold-commands), a
// lockstep run's ticks on the tick port, and a lost member's LOST status.
#include "timing/timing_component.hpp"

#include "common/runtime/topic_catalogue.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace fedsim::timing {
namespace {

constexpr std::uint64_t kMs = 1'000'000ull;
constexpr std::uint64_t kT0 = 1'000 * kMs;

/// Binds the ports in memory: writes are recorded, the matched counts are the test's.
class TestHost final : public runtime::PortBinder {
 public:
  int matched = 0;  // readers of every output, writers of every input
  std::vector<msg::FrameTick> ticks;
  std::vector<msg::FederateStatus> statuses;
  std::vector<msg::SimCommand> commands;

#define FEDSIM_BIND_IN_TEST(Msg)                                     \
  void bind(runtime::Input<msg::Msg>& port) override { bind_input(port); } \
  void bind(runtime::Output<msg::Msg>& port) override { bind_output(port); }
  FEDSIM_PORT_MESSAGE_TYPES(FEDSIM_BIND_IN_TEST)
#undef FEDSIM_BIND_IN_TEST

 private:
  template <class T>
  void bind_input(runtime::Input<T>& port) {
    port.set_writer_count([this] { return matched; });
  }
  template <class T>
  void bind_output(runtime::Output<T>& port) {
    port.set_reader_count([this] { return matched; });
    port.set_sink([this](const T& sample) {
      if constexpr (std::is_same_v<T, msg::FrameTick>) ticks.push_back(sample);
      if constexpr (std::is_same_v<T, msg::FederateStatus>) statuses.push_back(sample);
      if constexpr (std::is_same_v<T, msg::SimCommand>) commands.push_back(sample);
      return true;
    });
  }
};

TimingOptions options(const std::string& mode, std::vector<std::string> expect) {
  TimingOptions o;
  o.common.name = "timing";
  o.mode = mode;
  o.expect = std::move(expect);
  o.settle_s = 0.0;
  return o;
}

void bind(TimingComponent& timing, TestHost& host) {
  for (const auto& port : timing.ports()) port->bind(host);
}

msg::SimCommand weather(std::uint32_t sequence) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_WEATHER);
  c.issuer("fedsim-command");
  c.sequence_number(sequence);
  return c;
}

msg::FrameDone ack(const std::string& federate, std::uint64_t frame) {
  msg::FrameDone a;
  a.federate(federate);
  a.frame(frame);
  return a;
}

msg::FederateStatus status(const std::string& federate, msg::FederateState state, std::uint32_t pid) {
  msg::FederateStatus s;
  s.federate(federate);
  s.state(state);
  s.pid(pid);
  return s;
}

TEST(TimingComponent, DeclaresTheBackbonePortsItDrives) {
  TimingOptions o = options("lockstep", {"flight"});
  o.common.sync_qos_suffix = std::string(runtime::qos::kReliableSuffix);
  const TimingComponent timing(o);
  const auto ports = nlohmann::json::parse(runtime::ports_json(timing));
  EXPECT_EQ(ports["federate"], "timing");
  std::vector<std::string> seen;
  for (const auto& p : ports["ports"]) {
    seen.push_back(p["direction"].get<std::string>() + " " + p["topic"].get<std::string>() + " " +
                   p["qos"].get<std::string>());
  }
  EXPECT_EQ(seen, (std::vector<std::string>{"write fedsim/frame_tick tick_reliable",
                                            "write fedsim/federate_status status",
                                            "write fedsim/sim_command command",
                                            "read fedsim/frame_done frame_done_reliable",
                                            "read fedsim/federate_status status",
                                            "read fedsim/sim_command command"}));
}

TEST(TimingComponent, AHeldSettingIsRepublishedOnce) {
  TimingComponent timing(options("lockstep", {}));
  TestHost host;
  bind(timing, host);
  timing.on_command_sample(weather(7));
  ASSERT_EQ(host.commands.size(), 1u) << "republished for late joiners";
  EXPECT_EQ(host.commands[0], weather(7)) << "unchanged: same issuer, sequence number and payload";
  timing.on_command_sample(host.commands[0]);  // its own copy coming back
  EXPECT_EQ(host.commands.size(), 1u);
  msg::SimCommand reposition;
  reposition.kind(msg::COMMAND_REPOSITION);
  timing.on_command_sample(reposition);
  EXPECT_EQ(host.commands.size(), 1u) << "an event is not held";
  timing.on_command_sample(weather(8));
  EXPECT_EQ(host.commands.size(), 2u) << "a new setting replaces the held one";
  EXPECT_NE(timing.summary_json().find("\"held_settings\":1"), std::string::npos) << timing.summary_json();
}

TEST(TimingComponent, NoHoldCommandsRepublishesNothing) {
  TimingOptions o = options("lockstep", {});
  o.hold_commands = false;
  TimingComponent timing(o);
  TestHost host;
  bind(timing, host);
  timing.on_command_sample(weather(7));
  EXPECT_TRUE(host.commands.empty());
}

TEST(TimingComponent, ALockstepRunTicksOnTheTickPortUntilItsFrames) {
  TimingOptions o = options("lockstep", {"flight"});
  o.common.max_frames = 2;
  o.shutdown_on_exit = true;
  TimingComponent timing(o);
  TestHost host;
  bind(timing, host);
  EXPECT_EQ(timing.drive(kT0), kT0 + 20 * kMs) << "flight not ready: look again in 20 ms";
  EXPECT_TRUE(host.ticks.empty());
  timing.on_status(status("flight", msg::FEDERATE_READY, 11), kT0);
  host.matched = 1;
  ASSERT_TRUE(timing.drive(kT0 + kMs).has_value());
  ASSERT_EQ(host.ticks.size(), 1u);
  EXPECT_EQ(host.ticks[0].frame(), 0u);
  EXPECT_EQ(host.ticks[0].mode(), msg::TIMING_MODE_LOCKSTEP);
  EXPECT_EQ(host.ticks[0].run_state(), msg::RUN_STATE_RUN);
  EXPECT_TRUE(timing.progress().running);

  timing.on_ack(ack("flight", 0), runtime::WriterId{1}, kT0 + 2 * kMs);
  ASSERT_EQ(host.ticks.size(), 2u) << "the next tick on the acknowledgement";
  EXPECT_EQ(host.ticks[1].frame(), 1u);
  EXPECT_DOUBLE_EQ(host.ticks[1].sim_time_s(), 0.02);
  timing.on_ack(ack("flight", 1), runtime::WriterId{1}, kT0 + 3 * kMs);
  EXPECT_EQ(host.ticks.size(), 2u) << "--frames 2";
  EXPECT_FALSE(timing.drive(kT0 + 4 * kMs).has_value()) << "the run is over";
  EXPECT_EQ(timing.progress().frames, 2u);
  timing.on_stop();
  ASSERT_EQ(host.commands.size(), 1u);
  EXPECT_EQ(host.commands[0].kind(), msg::COMMAND_SHUTDOWN);
  EXPECT_EQ(host.commands[0].issuer().to_string(), "timing");
}

TEST(TimingComponent, ALostMemberGetsALostStatusAndANote) {
  TimingOptions o = options("lockstep", {"flight", "nav"});
  TimingComponent timing(o);
  TestHost host;
  host.matched = 2;
  bind(timing, host);
  timing.on_status(status("flight", msg::FEDERATE_RUNNING, 11), kT0);
  timing.on_status(status("nav", msg::FEDERATE_RUNNING, 12), kT0);
  timing.drive(kT0);
  ASSERT_EQ(host.ticks.size(), 1u);
  timing.on_ack(ack("flight", 0), runtime::WriterId{1}, kT0 + kMs);
  timing.on_ack(ack("nav", 0), runtime::WriterId{2}, kT0 + kMs);
  ASSERT_EQ(host.ticks.size(), 2u);
  EXPECT_TRUE(host.statuses.empty());
  timing.on_writer_lost(runtime::WriterId{2}, kT0 + 2 * kMs);  // nav's process is gone
  ASSERT_EQ(host.ticks.size(), 2u) << "flight has not acknowledged frame 1 yet";
  timing.drive(kT0 + 3 * kMs);
  ASSERT_EQ(host.statuses.size(), 1u);
  EXPECT_EQ(host.statuses[0].federate().to_string(), "nav");
  EXPECT_EQ(host.statuses[0].state(), msg::FEDERATE_LOST);
  EXPECT_EQ(host.statuses[0].pid(), 12u);
  const auto notes = timing.take_notes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "lost nav at frame 1: liveliness lost (process gone or hung)");
  timing.on_ack(ack("flight", 1), runtime::WriterId{1}, kT0 + 4 * kMs);
  EXPECT_EQ(host.ticks.size(), 3u) << "nav is no longer waited for";
}

}  // namespace
}  // namespace fedsim::timing
