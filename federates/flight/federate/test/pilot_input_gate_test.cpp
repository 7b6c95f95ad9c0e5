// The pilot-controls gate alone (no DDS): each kind of refused sample, the last good input kept
// (in relative mode: the trim kept), a second writer warned of once, the hold after silence.
// Each refusal has a negative control: the same sample made good is flown.
#include "flight/federate/pilot_input_gate.hpp"
#include "flight/federate/flight_adapter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fedsim::flight {
namespace {

msg::PilotControls sample(std::uint64_t stamp_frame, float elevator, std::uint16_t aircraft = 0) {
  msg::PilotControls s;
  s.aircraft_id(aircraft);
  s.stamp().frame(stamp_frame);
  s.elevator(elevator);
  for (auto& m : s.mixture()) m = 1.0f;
  for (auto& p : s.propeller()) p = 1.0f;
  return s;
}

constexpr std::uint64_t kFrame = 1000;

TEST(PilotInputGate, AGoodSampleIsFlown) {
  PilotInputGate gate;
  EXPECT_EQ(gate.last_good(), nullptr);
  EXPECT_FALSE(gate.offer(sample(kFrame - 1, 0.25f), kFrame));
  ASSERT_NE(gate.last_good(), nullptr);
  EXPECT_FLOAT_EQ(gate.last_good()->elevator(), 0.25f);
  EXPECT_EQ(gate.accepted(), 1u);
  EXPECT_EQ(gate.rejected_total(), 0u);
}

struct Refusal {
  const char* name;
  msg::PilotControls bad;
  InputRejection kind;
};

TEST(PilotInputGate, EachKindOfBadSampleIsRefusedCountedAndKeepsTheLastGoodInput) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<Refusal> cases = {
      {"aircraft 7", sample(kFrame - 1, 0.5f, 7), InputRejection::kOtherAircraft},
      {"NaN elevator", sample(kFrame - 1, nan), InputRejection::kNotFinite},
      {"+Inf elevator", sample(kFrame - 1, inf), InputRejection::kNotFinite},
      {"-Inf elevator", sample(kFrame - 1, -inf), InputRejection::kNotFinite},
      {"1e30 elevator", sample(kFrame - 1, 1e30f), InputRejection::kOutOfRange},
      {"elevator 1.5", sample(kFrame - 1, 1.5f), InputRejection::kOutOfRange},
      {"stamp 2^62", sample(std::uint64_t{1} << 62, 0.5f), InputRejection::kBadStamp},
      {"stamp after the frame", sample(kFrame + 1, 0.5f), InputRejection::kBadStamp},
      {"stamp 51 frames old", sample(kFrame - 51, 0.5f), InputRejection::kBadStamp},
  };
  msg::PilotControls throttle_nan = sample(kFrame - 1, 0.5f);
  throttle_nan.throttle()[3] = nan;
  cases.push_back({"NaN throttle of engine 4", throttle_nan, InputRejection::kNotFinite});
  msg::PilotControls negative_flaps = sample(kFrame - 1, 0.5f);
  negative_flaps.flaps(-0.1f);
  cases.push_back({"flaps -0.1", negative_flaps, InputRejection::kOutOfRange});

  for (const auto& c : cases) {
    PilotInputGate gate;
    ASSERT_FALSE(gate.offer(sample(kFrame - 2, -0.2f), kFrame - 1)) << c.name;
    const auto problem = gate.offer(c.bad, kFrame);
    ASSERT_TRUE(problem) << c.name;
    EXPECT_EQ(problem->kind, c.kind) << c.name << ": " << problem->message;
    EXPECT_EQ(gate.rejected(c.kind), 1u) << c.name;
    EXPECT_EQ(gate.rejected_total(), 1u) << c.name;
    EXPECT_FLOAT_EQ(gate.last_good()->elevator(), -0.2f) << c.name << ": the last good input stays";
  }
  // Negative controls: the edges of what is plausible are flown.
  PilotInputGate gate;
  EXPECT_FALSE(gate.offer(sample(kFrame - 50, 1.0f), kFrame)) << "50 frames old is still plausible";
  EXPECT_FALSE(gate.offer(sample(kFrame, -1.0f), kFrame)) << "stamped the frame that reads it";
  EXPECT_FLOAT_EQ(gate.last_good()->elevator(), -1.0f);
  PilotInputGate other_aircraft(PilotInputLimits{7});
  EXPECT_FALSE(other_aircraft.offer(sample(kFrame - 1, 0.5f, 7), kFrame)) << "aircraft 7 flies its own";
}

TEST(PilotInputGate, TheMessageNamesTheFieldAndTheValue) {
  PilotInputGate gate;
  msg::PilotControls s = sample(kFrame - 1, 0.0f);
  s.rudder(1e30f);
  const auto problem = gate.offer(s, kFrame);
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->message.find("rudder = 1e+30 is outside [-1, 1]"), std::string::npos) << problem->message;
  EXPECT_STREQ(fault_kind(problem->kind), "controls_out_of_range");
}

// Relative mode flies the deltas about the trim: a refused NaN sample must leave the aircraft on
// its trim plus the last good delta, never on a zeroed elevator (issue 11).
TEST(PilotInputGate, InRelativeModeARefusedSampleKeepsTheTrim) {
  AircraftControls trim;
  trim.elevator = -0.12;
  trim.set_throttle(0.63);
  PilotInputGate gate;
  msg::PilotControls delta = sample(kFrame - 1, 0.05f);
  delta.throttle()[0] = 0.02f;
  ASSERT_FALSE(gate.offer(delta, kFrame));
  const AircraftControls before = controls_from_message(*gate.last_good(), ControlsMode::kRelative, trim);
  EXPECT_NEAR(before.elevator, -0.07, 1e-6);
  EXPECT_NEAR(before.throttle[0], 0.65, 1e-6);

  msg::PilotControls bad = sample(kFrame, std::numeric_limits<float>::quiet_NaN());
  ASSERT_TRUE(gate.offer(bad, kFrame + 1));
  const AircraftControls after = controls_from_message(*gate.last_good(), ControlsMode::kRelative, trim);
  EXPECT_EQ(after, before);
  // Negative control: the NaN, had it been flown, would have lost the trim (the model's clamp
  // makes NaN neutral).
  const AircraftControls flown_nan = controls_from_message(bad, ControlsMode::kRelative, trim);
  EXPECT_NE(flown_nan.elevator, before.elevator);
}

TEST(PilotInputGate, ASecondWriterIsReportedOnceUntilItGoes) {
  PilotInputGate gate;
  EXPECT_EQ(gate.writers_matched(-1), PilotInputGate::WriterEvent::kNone);  // in-process: unknown
  EXPECT_EQ(gate.writers_matched(1), PilotInputGate::WriterEvent::kNone);
  EXPECT_EQ(gate.writers_matched(2), PilotInputGate::WriterEvent::kSecondWriter);
  EXPECT_EQ(gate.writers_matched(2), PilotInputGate::WriterEvent::kNone);
  EXPECT_EQ(gate.writers_matched(3), PilotInputGate::WriterEvent::kNone);
  EXPECT_EQ(gate.writers_matched(1), PilotInputGate::WriterEvent::kSingleWriterAgain);
  EXPECT_EQ(gate.writers_matched(2), PilotInputGate::WriterEvent::kSecondWriter);
  EXPECT_EQ(gate.second_writer_events(), 2u);
}

TEST(PilotInputGate, SilenceHoldsTheLastGoodInputAndCountsTheFrames) {
  PilotInputLimits limits;
  limits.hold_after_frames = 3;
  PilotInputGate gate(limits);
  EXPECT_EQ(gate.frame(1, false), PilotInputGate::HoldEvent::kNone) << "nothing to hold yet";
  ASSERT_FALSE(gate.offer(sample(1, 0.3f), 2));
  EXPECT_EQ(gate.frame(2, true), PilotInputGate::HoldEvent::kNone);
  EXPECT_EQ(gate.frame(3, false), PilotInputGate::HoldEvent::kNone);
  EXPECT_EQ(gate.frame(4, false), PilotInputGate::HoldEvent::kNone);
  EXPECT_EQ(gate.frame(5, false), PilotInputGate::HoldEvent::kNone);
  EXPECT_EQ(gate.frame(6, false), PilotInputGate::HoldEvent::kHoldStarted);
  EXPECT_EQ(gate.frame(7, false), PilotInputGate::HoldEvent::kNone);
  EXPECT_TRUE(gate.holding());
  EXPECT_EQ(gate.held_frames(), 2u);
  EXPECT_FLOAT_EQ(gate.last_good()->elevator(), 0.3f);
  EXPECT_EQ(gate.frame(8, true), PilotInputGate::HoldEvent::kHoldEnded);
  EXPECT_FALSE(gate.holding());
  EXPECT_EQ(gate.held_frames(), 2u);
}

// The screen where samples arrive: another aircraft's sample and one stamped far ahead never
// reach the port; this aircraft's, stamped up to 50 frames ahead, do (negative controls).
TEST(PilotInputScreen, KeepsOtherAircraftAndFarFutureStampsFromThePort) {
  PilotInputScreen screen(PilotInputLimits{});
  EXPECT_TRUE(screen.accept(sample(std::uint64_t{1} << 62, 0.1f))) << "before a first frame: a late joiner's stamps pass";
  screen.frame_started(kFrame);
  EXPECT_TRUE(screen.accept(sample(kFrame - 1, 0.1f)));
  EXPECT_TRUE(screen.accept(sample(kFrame + 50, 0.1f)));
  EXPECT_FALSE(screen.accept(sample(kFrame + 51, 0.1f)));
  EXPECT_FALSE(screen.accept(sample(std::uint64_t{1} << 62, 0.1f)));
  EXPECT_FALSE(screen.accept(sample(kFrame - 1, 0.1f, 7)));
  EXPECT_EQ(screen.future_stamps(), 2u);
  EXPECT_EQ(screen.last_future_stamp(), std::uint64_t{1} << 62);
  EXPECT_EQ(screen.other_aircraft(), 1u);
  EXPECT_EQ(screen.last_other_aircraft_id(), 7);
}

}  // namespace
}  // namespace fedsim::flight
