// The control-loading loop in the in-process composition (no DDS), with the I/O federate's own
// component: a scripted push on the column's force sensor goes out in pilot_force_n, the loader
// moves the column against its feel, and the I/O federate reports the loader's position as the
// elevator, one frame later (io_component.hpp documents the loop). Negative control: without
// the loop the same force moves nothing.
#include "control_loading/control_loading_component.hpp"
#include "io/io_component.hpp"
#include "io/model/input_profile.hpp"

#include "common/runtime/composition.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fedsim::control_loading {
namespace {

/// The aircraft the feel is scheduled on: 3000 Pa of dynamic pressure, in flight.
class Aircraft final : public runtime::Component {
 public:
  Aircraft() : Component("flight"), out_(writes(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext& frame) override {
    msg::AircraftState s;
    s.air().qbar_pa(3000.0);
    s.air().alpha_rad(0.05);
    s.stamp(frame.end_stamp());
    out_.write(s);
  }

 private:
  runtime::Output<msg::AircraftState>& out_;
};

/// Every frame: the I/O federate's elevator and the loader's column position.
class Reader final : public runtime::Component {
 public:
  Reader()
      : Component("reader"),
        pilot_(reads(runtime::topics::pilot_controls)),
        loader_(reads(runtime::topics::control_loading_state)) {}
  void step(const runtime::FrameContext&) override {
    elevator.push_back(pilot_.latest() ? pilot_.latest()->elevator() : 0.0);
    force_bit.push_back(pilot_.latest() && (pilot_.latest()->discretes() & msg::DISCRETE_FORCE_SENSORS) != 0);
    column.push_back(loader_.latest() ? loader_.latest()->pitch().position() : 0.0);
    column_force_n.push_back(loader_.latest() ? loader_.latest()->pitch().force_n() : 0.0);
  }
  std::vector<double> elevator, column, column_force_n;
  std::vector<bool> force_bit;

 private:
  runtime::Input<msg::PilotControls>& pilot_;
  runtime::Input<msg::ControlLoadingState>& loader_;
};

struct Loop {
  explicit Loop(bool in_the_loop)
      : io("io",
           std::make_unique<io::InputProfile>(io::InputProfile::parse(
               "time_s,column_force_n\n0,0\n1,0\n1,60\n", "push.csv")),
           0, {}, in_the_loop),
        loader("control_loading", ControlLoadingSetup{}),
        composition({}) {
    composition.add(io);
    composition.add(aircraft);
    composition.add(loader);
    composition.add(reader);
    for (int i = 0; i < 6 * 50; ++i) composition.step_frame();
  }
  io::IoComponent io;
  Aircraft aircraft;
  ControlLoadingComponent loader;
  Reader reader;
  runtime::Composition composition;
};

TEST(LoaderInTheLoop, APushOnTheForceSensorMovesTheColumnAndTheElevatorFollowsIt) {
  Loop loop(true);
  const Reader& r = loop.reader;
  ASSERT_EQ(r.elevator.size(), 300u);
  EXPECT_TRUE(r.force_bit.back());
  EXPECT_NEAR(r.column[40], 0.0, 1e-6);  // no force yet: the column rests on its datum
  // 60 N forward held: the column settles forward, the feel pushing back with the pilot's force.
  EXPECT_GT(r.column.back(), 0.05);
  EXPECT_NEAR(r.column_force_n.back(), -60.0, 5.0);  // (within the dry friction)
  // What the I/O federate reports is the loader's position of the frame before.
  for (std::size_t k = 60; k < r.column.size(); ++k) {
    ASSERT_NEAR(r.elevator[k], r.column[k - 1], 1e-6) << "frame " << k;
  }
}

TEST(LoaderInTheLoop, WithoutTheLoopTheForceChannelMovesNothing) {
  Loop loop(false);
  const Reader& r = loop.reader;
  EXPECT_FALSE(r.force_bit.back());
  EXPECT_EQ(r.elevator.back(), 0.0);           // the profile's elevator (none: 0)
  EXPECT_NEAR(r.column.back(), 0.0, 1e-3);     // the simulated pilot holds the column there
}

}  // namespace
}  // namespace fedsim::control_loading
