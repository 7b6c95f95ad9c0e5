// The stall-entry test pilot in the I/O component (no DDS): it flies by the aircraft state of
// the frame before, and a state that is not finite is refused by name (input_rejected) while
// the controls are held. Negative control: the same run with finite states has no fault.
#include "io/io_component.hpp"
#include "io/model/stall_entry_pilot.hpp"

#include "common/runtime/composition.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace fedsim::io {
namespace {

/// An aircraft holding 100 m/s level, its airspeed not finite in frames [bad_from, bad_to).
class Aircraft final : public runtime::Component {
 public:
  Aircraft(std::uint64_t bad_from, std::uint64_t bad_to)
      : Component("flight"), out_(writes(runtime::topics::aircraft_state)), bad_from_(bad_from), bad_to_(bad_to) {}
  void step(const runtime::FrameContext& frame) override {
    msg::AircraftState s;
    const bool bad = frame.frame >= bad_from_ && frame.frame < bad_to_;
    s.air().cas_mps(bad ? std::numeric_limits<double>::quiet_NaN() : 100.0);
    s.theta_rad(0.05);
    s.controls().elevator(-0.1);
    s.stamp(frame.end_stamp());
    out_.write(s);
  }

 private:
  runtime::Output<msg::AircraftState>& out_;
  std::uint64_t bad_from_, bad_to_;
};

class Reader final : public runtime::Component {
 public:
  Reader() : Component("reader"), pilot_(reads(runtime::topics::pilot_controls)) {}
  void step(const runtime::FrameContext&) override {
    elevator.push_back(pilot_.latest() ? pilot_.latest()->elevator() : 0.0);
  }
  std::vector<double> elevator;

 private:
  runtime::Input<msg::PilotControls>& pilot_;
};

std::uint64_t rejected(const runtime::Component& c) {
  for (const auto& f : c.faults())
    if (f.kind == "input_rejected") return f.count;
  return 0;
}

TEST(StallPilotInTheLoop, FliesByTheStateAndRefusesOneThatIsNotFinite) {
  for (const bool with_bad_state : {true, false}) {
    IoComponent io("io", std::make_unique<StallEntryPilot>(StallEntryParameters{}), 0);
    Aircraft aircraft(with_bad_state ? 100 : 0, with_bad_state ? 110 : 0);
    Reader reader;
    runtime::Composition composition({});
    composition.add(io);
    composition.add(aircraft);
    composition.add(reader);
    msg::SimCommand run;
    run.kind(msg::COMMAND_RUN_STATE);
    run.run_state(msg::RUN_STATE_RUN);
    composition.step_frame();
    composition.command(run);
    for (int i = 0; i < 200; ++i) composition.step_frame();
    // Held at a steady 100 m/s while the reference falls 1 kt/s: the pilot pulls.
    EXPECT_LT(reader.elevator.back(), -0.2) << with_bad_state;
    EXPECT_EQ(rejected(io), with_bad_state ? 10u : 0u);
    if (with_bad_state) {
      // The frames after the refused states (io reads frame N-1's state) fly the controls held.
      EXPECT_NE(reader.elevator[95], reader.elevator[96]);  // before them it moves every frame
      EXPECT_EQ(reader.elevator[103], reader.elevator[104]);
    }
  }
}

}  // namespace
}  // namespace fedsim::io
