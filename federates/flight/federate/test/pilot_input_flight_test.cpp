// The flight component behind its pilot-controls gate, in-process (no DDS): refused samples
// (NaN, 1e30, another aircraft, an absurd stamp) never reach the model, and fedsim/applied_controls
// carries exactly the controls the model flew in each frame (compared with the throttle the
// aircraft state reports, which comes from the model itself).
#include "flight/federate/flight_program.hpp"

#include "common/runtime/composition.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

namespace fedsim::flight {
namespace {

/// Writes a good throttle (0.30 + 0.001 * frame) every frame, except the frames it writes a bad
/// sample whose throttle (0.95) must never be flown.
class ScriptedControls final : public runtime::Component {
 public:
  ScriptedControls() : Component("trainer"), out_(writes(runtime::topics::pilot_controls)) {}
  void step(const runtime::FrameContext& frame) override {
    msg::PilotControls s;
    s.stamp(frame.stamp());
    for (auto& m : s.mixture()) m = 1.0f;
    for (auto& p : s.propeller()) p = 1.0f;
    s.throttle()[0] = static_cast<float>(good_throttle(frame.frame));
    switch (frame.frame % 10) {
      case 3: s.elevator(std::numeric_limits<float>::quiet_NaN()); s.throttle()[0] = 0.95f; break;
      case 5: s.aileron(1e30f); s.throttle()[0] = 0.95f; break;
      case 7: s.aircraft_id(7); s.throttle()[0] = 0.95f; break;
      case 9: s.stamp().frame(std::uint64_t{1} << 62); s.throttle()[0] = 0.95f; break;
      default: break;
    }
    out_.write(s);
  }
  static double good_throttle(std::uint64_t frame) { return 0.30 + 0.001 * static_cast<double>(frame); }

 private:
  runtime::Output<msg::PilotControls>& out_;
};

class Recorder final : public runtime::Component {
 public:
  Recorder()
      : Component("recorder"),
        state_(reads(runtime::topics::aircraft_state)),
        applied_(reads(runtime::topics::applied_controls)) {}
  void step(const runtime::FrameContext&) override {
    if (state_.latest()) flown[state_.latest()->stamp().frame()] = state_.latest()->controls().throttle()[0];
    if (applied_.latest()) applied[applied_.latest()->stamp().frame()] = applied_.latest()->throttle()[0];
  }
  std::map<std::uint64_t, double> flown;  // by the flight's frame
  std::map<std::uint64_t, float> applied;

 private:
  runtime::Input<msg::AircraftState>& state_;
  runtime::Input<msg::PilotControls>& applied_;
};

std::uint64_t faults_of(const runtime::Component& c, const std::string& kind) {
  for (const auto& f : c.faults()) {
    if (f.kind == kind) return f.count;
  }
  return 0;
}

TEST(PilotInputFlight, RefusedSamplesAreNeverFlownAndAppliedControlsAreWhatTheModelFlew) {
  ScriptedControls trainer;
  FlightOptions o;
  o.aircraft = "c172";
  o.start.trim_kind = "level";
  o.start.ktas = 100.0;
  auto flight = make_flight_component("flight", o);
  Recorder recorder;
  runtime::Composition composition({});
  composition.add(trainer);
  composition.add(*flight);
  composition.add(recorder);
  for (int i = 0; i < 100; ++i) composition.step_frame();

  ASSERT_GE(recorder.applied.size(), 90u);
  std::size_t compared = 0;
  double last_good = -1.0;
  for (const auto& [frame, applied] : recorder.applied) {
    ASSERT_TRUE(recorder.flown.count(frame)) << "frame " << frame;
    EXPECT_EQ(applied, static_cast<float>(recorder.flown.at(frame)))
        << "frame " << frame << ": applied_controls is what the model flew (the state carries it as a double)";
    EXPECT_NE(applied, 0.95f) << "frame " << frame << ": a refused sample was flown";
    if (frame >= 2) {
      // Frame N flies frame N-1's sample, or the last good one before it.
      const std::uint64_t written = frame - 1;
      if (written % 2 == 0 || written % 10 == 1) {
        EXPECT_NEAR(applied, ScriptedControls::good_throttle(written), 1e-6) << "frame " << frame;
        last_good = applied;
      } else if (last_good >= 0.0) {
        EXPECT_EQ(applied, last_good) << "frame " << frame << ": the last good input is held";
      }
      ++compared;
    }
  }
  EXPECT_GE(compared, 90u);
  EXPECT_GE(faults_of(*flight, "controls_not_finite"), 9u);
  EXPECT_GE(faults_of(*flight, "controls_out_of_range"), 9u);
  EXPECT_GE(faults_of(*flight, "controls_other_aircraft"), 9u);
  EXPECT_GE(faults_of(*flight, "controls_bad_stamp"), 9u);
  EXPECT_GT(flight->input_gate().accepted(), 50u);
}

}  // namespace
}  // namespace fedsim::flight
