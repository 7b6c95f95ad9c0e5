// A lockstep input read best effort (the catalogue's "state" profile, which matches writers of
// either kind) gets a second, reliable reader once a reliable writer of its topic is discovered
// (Subscription::read_reliably_too, DdsParticipant::has_reliable_writer): every sample arrives
// once, none is known missing, and a best-effort writer gets no second reader (it would log an
// incompatible reader). Over loopback (domain 97), two participants; about 2 s.
#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"
#include "common/util/wait_until.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <mutex>
#include <thread>

namespace fedsim::runtime {
namespace {

ParticipantOptions options_on(int domain, const std::string& name) {
  ParticipantOptions o;
  o.name = name;
  o.domain_id = domain;
  o.qos_file = default_qos_file();
  return o;
}

TEST(LockstepInputReliability, AReliableWriterGetsARepairReaderAndEverySampleArrivesOnce) {
  auto writer_dds = DdsParticipant::create(options_on(97, "reliability-writer"));
  auto reader_dds = DdsParticipant::create(options_on(97, "reliability-reader"));
  Publisher<msg::AircraftState> reliable(writer_dds, topics::aircraft_state, qos::kLockstepData);
  Publisher<msg::EngineState> best_effort(writer_dds, topics::engine_state, qos::kState);

  std::mutex mutex;
  std::map<std::uint64_t, int> deliveries;  // frame -> times handed on
  Subscription<msg::AircraftState> state(reader_dds, topics::aircraft_state, qos::kState,
                                         [&](const msg::AircraftState& s, const auto&) {
                                           std::lock_guard lock(mutex);
                                           ++deliveries[s.stamp().frame()];
                                         });
  Subscription<msg::EngineState> engines(reader_dds, topics::engine_state, qos::kState);
  ASSERT_TRUE(util::wait_until([&] { return state.matched_writers() == 1 && engines.matched_writers() == 1; }, 10));
  ASSERT_TRUE(util::wait_until([&] { return reader_dds->has_reliable_writer("fedsim/aircraft_state"); }, 10));
  // Negative control: the best-effort writer is known, but not as reliable.
  EXPECT_FALSE(reader_dds->has_reliable_writer("fedsim/engine_state"));

  ASSERT_TRUE(state.read_reliably_too(qos::kLockstepData));
  EXPECT_FALSE(state.read_reliably_too(qos::kLockstepData)) << "only one second reader";
  ASSERT_TRUE(util::wait_until([&] { return state.reads_reliably(); }, 10));
  // Written after both readers matched on both sides: each sample comes twice, is kept once.
  ASSERT_TRUE(util::wait_until([&] { return reliable.matched_readers() >= 2; }, 10));

  msg::AircraftState sample;
  for (std::uint64_t frame = 1; frame <= 40; ++frame) {
    sample.stamp().frame(frame);
    reliable.publish(sample);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // paced as frames are, not a burst
  }
  ASSERT_TRUE(util::wait_until([&] {
    std::lock_guard lock(mutex);
    return deliveries.size() == 40;
  }, 10));
  // Every sample acknowledged by the reliable reader: its copies have been handed on or dropped
  // (the best-effort copies were sent before them).
  ASSERT_TRUE(reliable.wait_for_acknowledgments(std::chrono::seconds(10)));
  {
    std::lock_guard lock(mutex);
    for (const auto& [frame, times] : deliveries) EXPECT_EQ(times, 1) << "frame " << frame;
  }
  EXPECT_EQ(state.received_count(), 40u);
  EXPECT_FALSE(state.missing_samples());
  msg::AircraftState before;
  ASSERT_TRUE(state.latest_before(40, before));
  EXPECT_EQ(before.stamp().frame(), 39u);
  // No reliable reader was made for the best-effort writer's topic: nothing incompatible.
  EXPECT_EQ(best_effort.incompatible_readers(), 0u);
  EXPECT_EQ(reliable.incompatible_readers(), 0u);
}

}  // namespace
}  // namespace fedsim::runtime
