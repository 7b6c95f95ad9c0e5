#include "timing/model/ack_tracker.hpp"
#include "timing/model/loss_watch.hpp"

#include <gtest/gtest.h>

namespace fedsim::timing {
namespace {

constexpr std::uint64_t kMs = 1'000'000;
constexpr std::uint64_t kTimeout = 1000 * kMs;

// Realtime at 50 Hz: a tick every 20 ms whatever the acknowledgements. The federate that stops
// acknowledging is overdue one timeout after the first tick it missed, although the latest tick
// is always 20 ms old (the bug: the age was measured from the latest tick, so never).
TEST(LossWatch, RealtimeSilenceIsMeasuredFromTheFirstUnacknowledgedTick) {
  LossWatch w(kTimeout);
  std::uint64_t t = 0;
  for (int frame = 0; frame < 50; ++frame, t += 20 * kMs) {
    w.tick_published({"io", "flight"}, t);
    w.acknowledged("io");
    w.acknowledged("flight");
  }
  const std::uint64_t first_missed = t;
  for (; t < first_missed + 2000 * kMs; t += 20 * kMs) {
    w.tick_published({"io", "flight"}, t);
    w.acknowledged("io");  // flight stopped
    const auto overdue = w.overdue(t);
    if (t - first_missed < kTimeout) {
      ASSERT_TRUE(overdue.empty()) << "at " << (t - first_missed) / kMs << " ms";
    } else {
      ASSERT_EQ(overdue, std::vector<std::string>{"flight"}) << "at " << (t - first_missed) / kMs;
    }
  }
  EXPECT_EQ(w.age_ns("flight", first_missed + 500 * kMs), 500 * kMs);
  EXPECT_EQ(w.age_ns("io", t), 0u);
}

// Paced lockstep: the wait between a completed frame and the next tick is nobody's silence.
TEST(LossWatch, LockstepIdleTimeBetweenTicksDoesNotCount) {
  LossWatch w(kTimeout);
  w.tick_published({"a"}, 0);
  w.acknowledged("a");
  w.tick_published({"a"}, 5000 * kMs);  // next tick 5 s later (slow pacing)
  EXPECT_TRUE(w.overdue(5500 * kMs).empty());
  EXPECT_EQ(w.overdue(6000 * kMs), std::vector<std::string>{"a"});
}

TEST(LossWatch, ARepeatedTickDoesNotRestartTheClock) {
  LossWatch w(kTimeout);
  w.tick_published({"a"}, 0);
  w.tick_published({"a"}, 600 * kMs);  // the same federate still owes the first one
  EXPECT_EQ(w.overdue(1000 * kMs), std::vector<std::string>{"a"});
}

TEST(LossWatch, LossAndRejoinAreRecordedInOrder) {
  LossWatch w(kTimeout);
  w.tick_published({"flight"}, 0);
  ASSERT_EQ(w.overdue(kTimeout).size(), 1u);
  w.record_lost("flight", 42, 1.0, "no acknowledgement");
  EXPECT_TRUE(w.is_lost("flight"));
  EXPECT_TRUE(w.overdue(10 * kTimeout).empty());  // reported once
  EXPECT_FALSE(w.record_rejoined("io", 43, 1.1));  // never lost
  EXPECT_TRUE(w.record_rejoined("flight", 60, 2.0));
  EXPECT_FALSE(w.record_rejoined("flight", 61, 2.1));  // already back
  EXPECT_FALSE(w.is_lost("flight"));
  EXPECT_EQ(w.lost(), std::vector<std::string>{"flight"});
  EXPECT_EQ(w.rejoined(), std::vector<std::string>{"flight"});
  EXPECT_TRUE(w.still_lost().empty());
  ASSERT_EQ(w.events().size(), 2u);
  EXPECT_EQ(w.events()[0].frame, 42u);
  EXPECT_EQ(w.events()[1].frame, 60u);
  // Back, it is watched again from its first tick.
  w.tick_published({"flight"}, 3 * kTimeout);
  EXPECT_EQ(w.overdue(4 * kTimeout), std::vector<std::string>{"flight"});
  w.record_lost("flight", 99, 4.0, "again");
  EXPECT_EQ(w.lost(), (std::vector<std::string>{"flight", "flight"}));
  EXPECT_EQ(w.still_lost(), std::vector<std::string>{"flight"});
}

TEST(LossWatch, ANewPidMeansTheProcessWasReplaced) {
  LossWatch w(kTimeout);
  EXPECT_FALSE(w.process_replaced("flight", 100));  // first seen
  EXPECT_FALSE(w.process_replaced("flight", 100));
  EXPECT_FALSE(w.process_replaced("flight", 0));    // unknown pid: no news
  EXPECT_TRUE(w.process_replaced("flight", 200));
  EXPECT_EQ(w.pid_of("flight"), 200u);
}

TEST(AckTracker, AReadmittedFederateIsExpectedFromTheNextFrameOnly) {
  AckTracker t({"io", "flight"});
  t.start_frame(10);
  EXPECT_FALSE(t.remove("flight"));
  EXPECT_FALSE(t.readmit("nav"));     // unknown
  EXPECT_FALSE(t.readmit("io"));      // still expected
  EXPECT_TRUE(t.readmit("flight"));
  EXPECT_FALSE(t.readmit("flight"));  // already coming back
  EXPECT_FALSE(t.expects("flight"));  // not in the frame in progress
  EXPECT_FALSE(t.acknowledge("flight", 10));
  EXPECT_TRUE(t.acknowledge("io", 10));  // frame 10 completes without it
  t.start_frame(11);
  EXPECT_TRUE(t.expects("flight"));
  EXPECT_FALSE(t.acknowledge("io", 11));
  EXPECT_TRUE(t.acknowledge("flight", 11));  // frame 11 waits for it
}

TEST(AckTracker, RemovingAReadmittedFederateCancelsItsReturn) {
  AckTracker t({"a", "b"});
  t.start_frame(1);
  t.remove("b");
  t.readmit("b");
  t.remove("b");  // lost again before its first frame back
  t.start_frame(2);
  EXPECT_FALSE(t.expects("b"));
  EXPECT_TRUE(t.acknowledge("a", 2));
}

}  // namespace
}  // namespace fedsim::timing
