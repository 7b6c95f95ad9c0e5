// The motion federate's adapter in the in-process composition (no DDS): it engages once the
// aircraft state arrives and cues a sustained longitudinal acceleration with a tilt; a NaN
// sample, a silent aircraft state and the instructor each cut it off within the frame, reported
// by name; the instructor's restore brings it back once it is down.
#include "motion/motion_component.hpp"

#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::motion {
namespace {

constexpr double kG = 9.80665;

/// Writes an aircraft state every frame: 1 g level, or a 0.2 g push forward (a take-off roll's
/// acceleration), NaN, or nothing at all.
class StateWriter final : public runtime::Component {
 public:
  enum class Mode { kLevel, kAccelerating, kNan, kSilent };
  StateWriter() : Component("flight"), out_(writes(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext& frame) override {
    if (mode == Mode::kSilent) return;
    msg::AircraftState s;
    s.specific_force_eye_body_mps2({mode == Mode::kAccelerating ? 0.2 * kG : 0.0, 0.0, -kG});
    if (mode == Mode::kNan) s.specific_force_eye_body_mps2()[0] = std::nan("");
    s.stamp(frame.end_stamp());
    out_.write(s);
  }
  Mode mode = Mode::kLevel;

 private:
  runtime::Output<msg::AircraftState>& out_;
};

class MotionReader final : public runtime::Component {
 public:
  MotionReader() : Component("reader"), in_(reads(runtime::topics::motion_state)) {}
  void step(const runtime::FrameContext&) override {
    if (in_.latest()) latest = *in_.latest();
  }
  msg::MotionPlatformState latest;

 private:
  runtime::Input<msg::MotionPlatformState>& in_;
};

msg::SimCommand motion_failure(bool active) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_FAILURE);
  c.target("motion");
  c.failure().active(active);
  return c;
}

class MotionComponentTest : public ::testing::Test {
 protected:
  MotionComponentTest() : motion_("motion", MotionSetup{}), composition_({}) {
    composition_.add(writer_);
    composition_.add(motion_);
    composition_.add(reader_);
  }
  void seconds(double s) { composition_.run(static_cast<std::uint64_t>(s * 50.0)); }
  msg::MotionStatus status() const { return reader_.latest.status(); }
  const runtime::FaultReport* fault(const std::string& kind) const {
    for (const auto& f : motion_.faults()) {
      if (f.kind == kind) return &f;
    }
    return nullptr;
  }
  void engage() {
    for (int i = 0; i < 50 * 30 && status() != msg::MOTION_ENGAGED; ++i) composition_.step_frame();
    ASSERT_EQ(status(), msg::MOTION_ENGAGED);
  }

  StateWriter writer_;
  MotionComponent motion_;
  MotionReader reader_;
  runtime::Composition composition_;
};

TEST_F(MotionComponentTest, EngagesAndTiltsTheCabForASustainedAcceleration) {
  composition_.run(3);
  EXPECT_EQ(status(), msg::MOTION_ENGAGING);  // rising to neutral once the state arrived
  engage();
  const double heave_at_neutral_m = reader_.latest.position_m()[2];
  EXPECT_NEAR(heave_at_neutral_m, 0.0, 0.01);
  writer_.mode = StateWriter::Mode::kAccelerating;
  seconds(10.0);
  // Tilt coordination: the cab pitches up until gravity gives the 0.2 g (asin 0.2 = 11.5 deg),
  // at no more than 3 deg/s; the surge washes out back towards neutral.
  EXPECT_NEAR(reader_.latest.attitude_rad()[1], std::asin(0.2), 1.0 * units::kDegToRad);
  EXPECT_LT(std::abs(reader_.latest.position_m()[0]), 0.1);
  EXPECT_NEAR(reader_.latest.specific_force_cue_mps2()[0], 0.2 * kG, 0.05 * kG);
  EXPECT_EQ(motion_.fault_count(), 0u);
  // Negative control: level flight leaves the cab level.
  writer_.mode = StateWriter::Mode::kLevel;
  seconds(15.0);
  EXPECT_NEAR(reader_.latest.attitude_rad()[1], 0.0, 0.5 * units::kDegToRad);
}

TEST_F(MotionComponentTest, ANanSampleCutsTheMotionOffInTheFrameAndIsReported) {
  engage();
  writer_.mode = StateWriter::Mode::kNan;
  // Written in frame N, read and cut off in N + 1 (no frame cues it), seen by a reader in N + 2.
  composition_.run(3);
  EXPECT_EQ(status(), msg::MOTION_FAULT);
  EXPECT_NE(std::string(reader_.latest.fault_reason()).find("not finite"), std::string::npos)
      << reader_.latest.fault_reason();
  ASSERT_NE(fault("input_rejected"), nullptr);
  ASSERT_NE(fault("motion_fault"), nullptr);
  // Latched: good samples again do not re-engage it; the platform goes down.
  writer_.mode = StateWriter::Mode::kLevel;
  seconds(20.0);
  EXPECT_EQ(status(), msg::MOTION_FAULT);
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(reader_.latest.jack_velocity_mps()[k]), 1e-3);
}

TEST_F(MotionComponentTest, ASilentAircraftStateCutsTheMotionOff) {
  engage();
  writer_.mode = StateWriter::Mode::kSilent;
  composition_.run(9);
  EXPECT_EQ(status(), msg::MOTION_ENGAGED);  // 10 frames allowed (--silent-frames)
  composition_.run(3);
  EXPECT_EQ(status(), msg::MOTION_FAULT);
  ASSERT_NE(fault("input_silent"), nullptr);
  EXPECT_NE(fault("input_silent")->last.find("silent for 10 frames"), std::string::npos) << fault("input_silent")->last;
}

// Lost ticks: from 1.5 frame periods without a tick the host calls on_ticks_stopped(); up to
// 2.5 periods (50 ms at 50 Hz) the platform holds (a late tick), from then it trips in that call
// and the park's steps go out then, not in a frame that is not coming.
TEST_F(MotionComponentTest, LostTicksStartTheParkInTheWatchdogsOwnCall) {
  EXPECT_EQ(motion_.tick_watchdog_periods(), 1.5);
  engage();
  std::vector<msg::MotionStatus> written;
  composition_.on_written(runtime::topics::motion_state,
                          std::function<void(const msg::MotionPlatformState&)>(
                              [&](const msg::MotionPlatformState& s) { written.push_back(s.status()); }));
  motion_.on_ticks_stopped(composition_.last_frame(), 0.030);
  EXPECT_TRUE(written.empty()) << "30 ms without a tick is a late tick: held";
  motion_.on_ticks_stopped(composition_.last_frame(), 0.050);
  ASSERT_EQ(written.size(), 2u);  // two park steps for 50 ms of silence at 50 Hz
  EXPECT_EQ(written[0], msg::MOTION_FAULT);
  ASSERT_NE(fault("motion_fault"), nullptr);
  EXPECT_NE(fault("motion_fault")->last.find("no frame tick for 50 ms"), std::string::npos)
      << fault("motion_fault")->last;
  // The park goes on at the frame period for as long as the silence lasts.
  motion_.on_ticks_stopped(composition_.last_frame(), 0.200);
  EXPECT_EQ(written.size(), 10u);
}

// The 1 h soak's case (docs/soak.md): one 32 ms gap between two ticks (VM scheduling) is ridden
// through and counted, not a fault.
TEST_F(MotionComponentTest, OneLateTickIsRiddenThroughAndCounted) {
  engage();
  motion_.on_ticks_stopped(composition_.last_frame(), 0.030);  // the host's call at 1.5 periods
  composition_.run(1);                                         // the tick, at 32 ms
  composition_.run(5);
  EXPECT_EQ(status(), msg::MOTION_ENGAGED);
  EXPECT_EQ(motion_.late_ticks(), 1u);
  EXPECT_EQ(fault("motion_fault"), nullptr);
}

// Late again and again (3 within 50 frames): the host cannot keep the rate; cut off.
TEST_F(MotionComponentTest, ABurstOfLateTicksTripsThePlatform) {
  engage();
  for (int i = 0; i < 3; ++i) {
    motion_.on_ticks_stopped(composition_.last_frame(), 0.032);
    composition_.run(10);
  }
  EXPECT_EQ(motion_.late_ticks(), 3u);
  EXPECT_EQ(status(), msg::MOTION_FAULT);
  ASSERT_NE(fault("motion_fault"), nullptr);
  EXPECT_NE(fault("motion_fault")->last.find("3 late frame ticks within 50 frames"), std::string::npos)
      << fault("motion_fault")->last;
}

TEST_F(MotionComponentTest, TheInstructorCutsItOffAndRestoresIt) {
  engage();
  composition_.command(motion_failure(true));
  composition_.run(2);
  EXPECT_EQ(status(), msg::MOTION_FAULT);
  EXPECT_EQ(std::string(reader_.latest.fault_reason()), "instructor cut-off");
  seconds(20.0);  // down and settled
  composition_.command(motion_failure(false));
  seconds(1.0);
  EXPECT_NE(status(), msg::MOTION_FAULT);
  engage();  // back up to neutral and cueing
}

TEST(MotionMessages, ANonFiniteRateIsNamed) {
  msg::AircraftState s;
  s.specific_force_eye_body_mps2({0.0, 0.0, -kG});
  s.omega_body_radps({0.0, INFINITY, 0.0});
  MotionInputs in;
  const auto problem = inputs_from_message(s, in);
  ASSERT_TRUE(problem);
  EXPECT_EQ(*problem, "omega_body_radps not finite");
  s.omega_body_radps({0.01, 0.02, 0.03});
  EXPECT_FALSE(inputs_from_message(s, in));
  EXPECT_EQ(in.omega_body_radps[1], 0.02);
}

}  // namespace
}  // namespace fedsim::motion
