// The frame clock's decisions with a fake clock and fake acknowledgements (no DDS): lockstep waits
// for every expected member, realtime counts an overrun, a silent member is lost after the
// timeout and rejoins, the join waits for readiness and matches, the run ends where it should.
// Each check has its control (the same case where the event must not happen).
#include "timing/model/timekeeper.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace fedsim::timing {
namespace {

constexpr std::uint64_t kMs = 1'000'000ull;
constexpr std::uint64_t kT0 = 1'000 * kMs;  // a monotonic clock never starts at 0

TimekeeperSettings lockstep(std::vector<std::string> expect) {
  TimekeeperSettings s;
  s.mode = ClockMode::kLockstep;
  s.expect = std::move(expect);
  return s;
}

TimekeeperSettings realtime(std::vector<std::string> expect) {
  TimekeeperSettings s;
  s.mode = ClockMode::kRealtime;
  s.expect = std::move(expect);
  return s;
}

/// A keeper past its join, started at kT0.
Timekeeper started(TimekeeperSettings settings) {
  Timekeeper keeper(std::move(settings));
  keeper.start(kT0);
  return keeper;
}

std::vector<Report> reports_of(Timekeeper& keeper, Report::Kind kind) {
  auto all = keeper.take_reports();
  std::vector<Report> out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out), [&](const Report& r) { return r.kind == kind; });
  return out;
}

TEST(Timekeeper, LockstepWaitsForEveryExpectedMember) {
  Timekeeper keeper = started(lockstep({"a", "b"}));
  Timekeeper::Due due = keeper.wake(kT0);
  ASSERT_TRUE(due.tick);  // the first tick at once
  EXPECT_EQ(keeper.issue_tick(kT0).frame, 0u);

  EXPECT_EQ(keeper.acknowledge("a", 0, kT0 + 1 * kMs), Timekeeper::Ack::kNothing);
  due = keeper.wake(kT0 + 2 * kMs);
  EXPECT_FALSE(due.tick) << "b has not acknowledged";
  EXPECT_FALSE(due.finished);
  EXPECT_EQ(keeper.acknowledge("b", 1, kT0 + 3 * kMs), Timekeeper::Ack::kNothing) << "another frame's";
  EXPECT_EQ(keeper.acknowledge("b", 0, kT0 + 4 * kMs), Timekeeper::Ack::kTickNow);
  EXPECT_EQ(keeper.issue_tick(kT0 + 4 * kMs).frame, 1u);
  EXPECT_EQ(keeper.summary().all_acked.count(), 1u);
}

TEST(Timekeeper, PacedLockstepTicksAtScaledRealTime) {
  TimekeeperSettings s = lockstep({"a"});
  s.scale = 1.0;  // 50 Hz: a tick every 20 ms
  Timekeeper keeper = started(s);
  ASSERT_TRUE(keeper.wake(kT0).tick);
  keeper.issue_tick(kT0);
  EXPECT_EQ(keeper.acknowledge("a", 0, kT0 + 1 * kMs), Timekeeper::Ack::kCompleted);
  Timekeeper::Due due = keeper.wake(kT0 + 2 * kMs);
  EXPECT_FALSE(due.tick) << "paced: not before 20 ms";
  EXPECT_EQ(due.next_ns, kT0 + 20 * kMs);
  EXPECT_TRUE(keeper.wake(kT0 + 20 * kMs).tick);
}

TEST(Timekeeper, LockstepRepeatsATickWhoseAcknowledgementsAreOverdue) {
  Timekeeper keeper = started(lockstep({"a"}));
  keeper.wake(kT0);
  keeper.issue_tick(kT0);
  EXPECT_FALSE(keeper.wake(kT0 + 200 * kMs).resend) << "0.25 s not yet";
  EXPECT_TRUE(keeper.wake(kT0 + 250 * kMs).resend);
  EXPECT_FALSE(keeper.wake(kT0 + 260 * kMs).resend) << "once per 0.25 s";
  EXPECT_EQ(keeper.summary().resent_ticks, 1u);
}

TEST(Timekeeper, RealtimeTicksOnDeadlinesAndCountsAnOverrun) {
  Timekeeper keeper = started(realtime({"a", "b"}));
  Timekeeper::Due due = keeper.wake(kT0);
  EXPECT_FALSE(due.tick) << "the first tick is one period after the start";
  EXPECT_EQ(due.next_ns, kT0 + 20 * kMs);
  due = keeper.wake(kT0 + 20 * kMs);
  ASSERT_TRUE(due.tick);
  keeper.issue_tick(kT0 + 20 * kMs);
  EXPECT_EQ(due.next_ns, kT0 + 40 * kMs);
  keeper.acknowledge("a", 0, kT0 + 25 * kMs);
  keeper.acknowledge("b", 0, kT0 + 30 * kMs);
  // Control: a complete frame at its deadline is no overrun.
  ASSERT_TRUE(keeper.wake(kT0 + 40 * kMs).tick);
  keeper.issue_tick(kT0 + 40 * kMs);
  EXPECT_EQ(keeper.overruns(), 0u);
  keeper.acknowledge("a", 1, kT0 + 45 * kMs);  // b never does
  ASSERT_TRUE(keeper.wake(kT0 + 61 * kMs).tick);
  keeper.issue_tick(kT0 + 61 * kMs);
  EXPECT_EQ(keeper.overruns(), 1u);
  const auto overruns = reports_of(keeper, Report::Kind::kOverrun);
  ASSERT_EQ(overruns.size(), 1u);
  EXPECT_EQ(overruns[0].frame, 1u);
  EXPECT_EQ(overruns[0].detail, "b");
  EXPECT_NEAR(keeper.summary().period_error.max_us(), 1000.0, 20.0) << "1 ms late";
}

TEST(Timekeeper, ASilentMemberIsLostAfterTheTimeoutAndRejoins) {
  TimekeeperSettings s = lockstep({"a", "b"});
  s.ack_timeout_s = 1.0;
  Timekeeper keeper = started(s);
  keeper.status("b", MemberState::kRunning, 42, "", kT0);
  keeper.wake(kT0);
  keeper.issue_tick(kT0);
  keeper.acknowledge("a", 0, kT0 + 1 * kMs);
  keeper.wake(kT0 + 999 * kMs);
  EXPECT_TRUE(reports_of(keeper, Report::Kind::kLost).empty()) << "not before the timeout";

  const Timekeeper::Due due = keeper.wake(kT0 + 1000 * kMs);
  const auto lost = reports_of(keeper, Report::Kind::kLost);
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_EQ(lost[0].federate, "b");
  EXPECT_EQ(lost[0].frame, 0u);
  EXPECT_EQ(lost[0].pid, 42u);
  EXPECT_NE(lost[0].detail.find("no acknowledgement for 1.00 s"), std::string::npos) << lost[0].detail;
  EXPECT_EQ(due.next_ns, kT0 + 1000 * kMs) << "its loss completed the frame: the next tick at once";
  ASSERT_TRUE(keeper.wake(kT0 + 1000 * kMs).tick);
  keeper.issue_tick(kT0 + 1000 * kMs);
  EXPECT_EQ(keeper.acknowledge("a", 1, kT0 + 1001 * kMs), Timekeeper::Ack::kTickNow) << "b is not waited for";
  keeper.issue_tick(kT0 + 1001 * kMs);

  keeper.status("b", MemberState::kRunning, 42, "", kT0 + 1002 * kMs);  // continued (SIGCONT)
  const auto rejoined = reports_of(keeper, Report::Kind::kRejoined);
  ASSERT_EQ(rejoined.size(), 1u);
  EXPECT_EQ(rejoined[0].frame, 3u) << "expected again from the next tick";
  EXPECT_EQ(keeper.acknowledge("a", 2, kT0 + 1003 * kMs), Timekeeper::Ack::kTickNow) << "not in frame 2";
  keeper.issue_tick(kT0 + 1003 * kMs);
  EXPECT_EQ(keeper.acknowledge("a", 3, kT0 + 1004 * kMs), Timekeeper::Ack::kNothing) << "b again from frame 3";
  EXPECT_EQ(keeper.acknowledge("b", 3, kT0 + 1005 * kMs), Timekeeper::Ack::kTickNow);

  const TimingSummary summary = keeper.summary();
  EXPECT_EQ(summary.lost, std::vector<std::string>{"b"});
  EXPECT_EQ(summary.rejoined, std::vector<std::string>{"b"});
  EXPECT_TRUE(summary.still_lost.empty());
  ASSERT_EQ(summary.events.size(), 2u);
}

TEST(Timekeeper, ASilentRealtimeMemberIsTimedFromItsFirstUnacknowledgedTick) {
  TimekeeperSettings s = realtime({"a"});
  s.ack_timeout_s = 0.1;
  Timekeeper keeper = started(s);
  std::uint64_t now = kT0;
  for (int i = 0; i < 4; ++i) {  // ticks at 20, 40, 60, 80 ms: a never answers
    now += 20 * kMs;
    ASSERT_TRUE(keeper.wake(now).tick);
    keeper.issue_tick(now);
  }
  now += 20 * kMs;
  ASSERT_TRUE(keeper.wake(now).tick);
  keeper.issue_tick(now);
  EXPECT_TRUE(reports_of(keeper, Report::Kind::kLost).empty()) << "80 ms since its first unanswered tick";
  now += 20 * kMs;
  keeper.wake(now);  // 100 ms after the first unanswered tick, though the last one is 20 ms old
  EXPECT_EQ(reports_of(keeper, Report::Kind::kLost).size(), 1u);
}

TEST(Timekeeper, AReplacedProcessIsLostAndRejoinedAtOnce) {
  Timekeeper keeper = started(lockstep({"a"}));
  keeper.status("a", MemberState::kRunning, 100, "", kT0);
  keeper.status("a", MemberState::kRunning, 100, "", kT0 + kMs);
  EXPECT_TRUE(keeper.take_reports().empty()) << "the same process";
  keeper.status("a", MemberState::kReady, 200, "", kT0 + 2 * kMs);
  const auto reports = keeper.take_reports();
  ASSERT_EQ(reports.size(), 2u);
  EXPECT_EQ(reports[0].kind, Report::Kind::kLost);
  EXPECT_EQ(reports[0].detail, "its process (pid 100) was replaced");
  EXPECT_EQ(reports[1].kind, Report::Kind::kRejoined);
  EXPECT_EQ(reports[1].detail, "new process pid 200");
}

TEST(Timekeeper, AMemberStoppingOnAShutdownCommandIsNotLost) {
  Timekeeper keeper = started(lockstep({"a", "b"}));
  keeper.status("a", MemberState::kStopping, 1, "shutdown command from fedsim-command", kT0);
  EXPECT_TRUE(keeper.take_reports().empty());
  keeper.status("b", MemberState::kFailed, 2, "step failed: boom", kT0);  // control
  const auto lost = reports_of(keeper, Report::Kind::kLost);
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_EQ(lost[0].detail, "failed: step failed: boom");
}

TEST(Timekeeper, ALapsedLivelinessLosesAMember) {
  Timekeeper keeper = started(lockstep({"a"}));
  keeper.liveliness_lost("stranger", kT0);
  EXPECT_TRUE(keeper.take_reports().empty()) << "not a member";
  keeper.liveliness_lost("a", kT0);
  const auto lost = reports_of(keeper, Report::Kind::kLost);
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_EQ(lost[0].detail, "liveliness lost (process gone or hung)");
}

TEST(Timekeeper, StopOnLostEndsTheRunAsAFailure) {
  TimekeeperSettings s = lockstep({"a"});
  s.stop_on_lost = true;
  Timekeeper keeper = started(s);
  keeper.wake(kT0);
  keeper.issue_tick(kT0);
  keeper.status("a", MemberState::kFailed, 1, "boom", kT0 + kMs);
  EXPECT_TRUE(keeper.wake(kT0 + 2 * kMs).finished);
  EXPECT_EQ(keeper.exit_code(), 1);
  EXPECT_EQ(keeper.stop_reason(), "federate a lost");
}

TEST(Timekeeper, TheRunEndsAfterMaxFramesOnceTheLastIsAcknowledged) {
  TimekeeperSettings s = lockstep({"a"});
  s.max_frames = 2;
  Timekeeper keeper = started(s);
  keeper.wake(kT0);
  keeper.issue_tick(kT0);
  EXPECT_EQ(keeper.acknowledge("a", 0, kT0 + kMs), Timekeeper::Ack::kTickNow);
  keeper.issue_tick(kT0 + kMs);
  EXPECT_EQ(keeper.acknowledge("a", 1, kT0 + 2 * kMs), Timekeeper::Ack::kCompleted) << "no third tick";
  const Timekeeper::Due due = keeper.wake(kT0 + 3 * kMs);
  EXPECT_FALSE(due.tick);
  EXPECT_TRUE(due.finished);
  EXPECT_EQ(keeper.exit_code(), 0);
  EXPECT_EQ(keeper.frames(), 2u);
}

TEST(Timekeeper, RealtimeEndsAtItsDurationAfterTheLastAcknowledgements) {
  TimekeeperSettings s = realtime({"a"});
  s.duration_s = 0.05;
  Timekeeper keeper = started(s);
  ASSERT_TRUE(keeper.wake(kT0 + 20 * kMs).tick);
  keeper.issue_tick(kT0 + 20 * kMs);
  ASSERT_TRUE(keeper.wake(kT0 + 40 * kMs).tick);
  keeper.issue_tick(kT0 + 40 * kMs);
  Timekeeper::Due due = keeper.wake(kT0 + 60 * kMs);
  EXPECT_FALSE(due.tick);
  EXPECT_FALSE(due.finished) << "the last frame's acknowledgements may still come";
  keeper.acknowledge("a", 1, kT0 + 61 * kMs);
  EXPECT_TRUE(keeper.wake(kT0 + 61 * kMs).finished);
}

TEST(Timekeeper, AStopEndsTheRunAndNoTickFollows) {
  Timekeeper keeper = started(lockstep({"a"}));
  keeper.wake(kT0);
  keeper.issue_tick(kT0);
  keeper.stop("shutdown command from ios");
  EXPECT_EQ(keeper.acknowledge("a", 0, kT0 + kMs), Timekeeper::Ack::kCompleted) << "not kTickNow";
  EXPECT_TRUE(keeper.wake(kT0 + 2 * kMs).finished);
  EXPECT_EQ(keeper.stop_reason(), "shutdown command from ios");
}

TEST(Timekeeper, ARunStateRequestTakesEffectAtTheNextTick) {
  Timekeeper keeper = started(lockstep({}));
  keeper.wake(kT0);
  EXPECT_EQ(keeper.issue_tick(kT0).state, RunState::kRun);
  keeper.request(RunState::kFreeze);
  const TickFields frozen = keeper.issue_tick(kT0 + kMs);
  EXPECT_EQ(frozen.state, RunState::kFreeze);
  EXPECT_EQ(frozen.dt_s, 0.0);
}

TEST(Timekeeper, TheJoinWaitsForReadinessAndMatchesThenSettles) {
  TimekeeperSettings s = lockstep({"a", "b"});
  s.settle_s = 0.3;
  s.join_timeout_s = 5.0;
  Timekeeper keeper(s);
  EXPECT_EQ(keeper.join(kT0, 2, 2), Timekeeper::Join::kWaiting) << "nobody ready";
  keeper.status("a", MemberState::kReady, 1, "", kT0);
  keeper.status("b", MemberState::kRunning, 2, "", kT0);
  EXPECT_EQ(keeper.join(kT0 + kMs, 2, 1), Timekeeper::Join::kWaiting) << "one acknowledgement writer missing";
  EXPECT_EQ(keeper.join(kT0 + 2 * kMs, 2, 2), Timekeeper::Join::kSettling);
  EXPECT_EQ(keeper.settle_until_ns(), kT0 + 302 * kMs);
  EXPECT_EQ(keeper.join(kT0 + 302 * kMs, 2, 2), Timekeeper::Join::kReady);
}

TEST(Timekeeper, TheJoinTimesOutNamingWhoIsMissing) {
  TimekeeperSettings s = lockstep({"a", "b"});
  s.join_timeout_s = 1.0;
  Timekeeper keeper(s);
  keeper.status("a", MemberState::kReady, 1, "", kT0);
  EXPECT_EQ(keeper.join(kT0, 2, 2), Timekeeper::Join::kWaiting);
  EXPECT_EQ(keeper.join(kT0 + 1000 * kMs, 2, 2), Timekeeper::Join::kWaiting);
  EXPECT_EQ(keeper.join(kT0 + 1001 * kMs, 2, 2), Timekeeper::Join::kTimedOut);
  EXPECT_EQ(keeper.not_ready(), std::vector<std::string>{"b"});
}

TEST(Timekeeper, BadSettingsAreRefusedByName) {
  TimekeeperSettings s = lockstep({"a"});
  s.rate_hz = std::nan("");
  EXPECT_THROW({ Timekeeper k(s); }, std::invalid_argument);
  s = lockstep({"a"});
  s.ack_timeout_s = 0.0;
  try {
    Timekeeper k(s);
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ack_timeout_s"), std::string::npos) << e.what();
  }
  s = lockstep({"a", "a"});
  EXPECT_THROW({ Timekeeper k(s); }, std::invalid_argument) << "a member listed twice";
  EXPECT_NO_THROW({ Timekeeper k(lockstep({"a"})); });
}

TEST(Timekeeper, TheSummaryJsonListsTheRun) {
  Timekeeper keeper = started(lockstep({"a"}));
  keeper.wake(kT0);
  keeper.issue_tick(kT0);
  keeper.liveliness_lost("a", kT0 + kMs);
  keeper.finish(kT0 + 2000 * kMs);
  keeper.finish(kT0 + 5000 * kMs);  // once only
  const auto j = nlohmann::json::parse(keeper.summary_json("timing", 3));
  EXPECT_EQ(j["federate"], "timing");
  EXPECT_EQ(j["mode"], "lockstep");
  EXPECT_EQ(j["frames"], 1);
  EXPECT_DOUBLE_EQ(j["wall_s"].get<double>(), 2.0);
  EXPECT_EQ(j["lost"], nlohmann::json::array({"a"}));
  EXPECT_EQ(j["still_lost"], nlohmann::json::array({"a"}));
  EXPECT_EQ(j["held_settings"], 3);
  EXPECT_EQ(j["membership"][0]["why"], "liveliness lost (process gone or hung)");
}

}  // namespace
}  // namespace fedsim::timing
