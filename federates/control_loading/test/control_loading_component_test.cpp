// The control-loading federate's adapter in the in-process composition (no DDS): it fades the
// forces in once the aircraft state arrives; the force that holds the column grows with the
// dynamic pressure (the gradient's schedule); the autopilot back-drives the column; a NaN
// sample and the instructor cut it off to SAFE within the frame, reported by name.
#include "control_loading/control_loading_component.hpp"
#include "common/util/build_paths.hpp"

#include "common/runtime/composition.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace fedsim::control_loading {
namespace {

/// The aircraft (dynamic pressure, angle of attack), the pilot (column forward by `column`) and,
/// when told, the autopilot engaged with its elevator command.
class Writers final : public runtime::Component {
 public:
  Writers()
      : Component("writers"),
        aircraft_(writes(runtime::topics::aircraft_state)),
        pilot_(writes(runtime::topics::pilot_controls)),
        autopilot_(writes(runtime::topics::autopilot_state)) {}
  void step(const runtime::FrameContext& frame) override {
    msg::AircraftState s;
    s.air().qbar_pa(nan ? std::nan("") : qbar_pa);
    s.air().alpha_rad(alpha_rad);
    s.weight_on_wheels(on_ground);
    s.stamp(frame.end_stamp());
    aircraft_.write(s);
    msg::PilotControls c;
    c.elevator(column);
    c.stamp(frame.stamp());
    pilot_.write(c);
    if (autopilot_elevator) {
      msg::AutopilotState a;
      a.fma().autopilot_engaged(true);
      a.elevator(*autopilot_elevator);
      a.stamp(frame.end_stamp());
      autopilot_.write(a);
    }
  }
  double qbar_pa = 3000.0, alpha_rad = 0.05, column = 0.0;
  bool nan = false, on_ground = false;
  std::optional<double> autopilot_elevator;

 private:
  runtime::Output<msg::AircraftState>& aircraft_;
  runtime::Output<msg::PilotControls>& pilot_;
  runtime::Output<msg::AutopilotState>& autopilot_;
};

class Reader final : public runtime::Component {
 public:
  Reader() : Component("reader"), in_(reads(runtime::topics::control_loading_state)) {}
  void step(const runtime::FrameContext&) override {
    if (in_.latest()) latest = *in_.latest();
  }
  msg::ControlLoadingState latest;

 private:
  runtime::Input<msg::ControlLoadingState>& in_;
};

msg::SimCommand cut(bool active) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_FAILURE);
  c.target("control_loading");
  c.failure().active(active);
  return c;
}

class ControlLoadingComponentTest : public ::testing::Test {
 protected:
  ControlLoadingComponentTest() : loader_("control_loading", ControlLoadingSetup{}), composition_({}) {
    composition_.add(writers_);
    composition_.add(loader_);
    composition_.add(reader_);
  }
  void seconds(double s) { composition_.run(static_cast<std::uint64_t>(s * 50.0)); }
  const runtime::FaultReport* fault(const std::string& kind) const {
    for (const auto& f : loader_.faults()) {
      if (f.kind == kind) return &f;
    }
    return nullptr;
  }
  double column_force_at(double qbar_pa) {
    writers_.qbar_pa = qbar_pa;
    seconds(3.0);
    return reader_.latest.pitch().force_n();
  }

  Writers writers_;
  ControlLoadingComponent loader_;
  Reader reader_;
  runtime::Composition composition_;
};

TEST_F(ControlLoadingComponentTest, FadesInAndTheColumnGetsHeavierWithDynamicPressure) {
  composition_.run(3);
  EXPECT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_FADING_IN);
  seconds(1.0);
  ASSERT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_ACTIVE);
  writers_.column = 0.5;
  const double slow = column_force_at(1000.0);
  const double fast = column_force_at(8000.0);
  EXPECT_NEAR(reader_.latest.pitch().position(), 0.5, 0.05);  // the simulated pilot holds it there
  EXPECT_GT(std::abs(fast), 1.5 * std::abs(slow)) << slow << " N at 1 kPa, " << fast << " N at 8 kPa";
  EXPECT_FALSE(reader_.latest.pitch_backdriven());
  EXPECT_EQ(loader_.fault_count(), 0u);
}

TEST_F(ControlLoadingComponentTest, TheShakerWarnsOfTheStallInFlightOnly) {
  seconds(1.0);
  EXPECT_FALSE(reader_.latest.stick_shaker());
  writers_.alpha_rad = 0.30;  // beyond the 737's 0.24 rad shaker angle
  seconds(0.5);
  EXPECT_TRUE(reader_.latest.stick_shaker());
  writers_.on_ground = true;  // the same angle on the ground: inhibited
  seconds(0.5);
  EXPECT_FALSE(reader_.latest.stick_shaker());
}

TEST_F(ControlLoadingComponentTest, TheAutopilotBackDrivesTheColumn) {
  seconds(1.0);
  writers_.autopilot_elevator = -0.3;  // nose up: column aft
  seconds(3.0);
  EXPECT_TRUE(reader_.latest.pitch_backdriven());
  EXPECT_FALSE(reader_.latest.yaw_backdriven());  // the pedals only in rollout
  EXPECT_NEAR(reader_.latest.pitch().position(), -0.3, 0.05);
  // Negative control: disengaged, the pilot's (centred) column again.
  writers_.autopilot_elevator.reset();
  seconds(0.1);
  EXPECT_FALSE(reader_.latest.pitch_backdriven());
  seconds(3.0);
  EXPECT_NEAR(reader_.latest.pitch().position(), 0.0, 0.05);
}

TEST_F(ControlLoadingComponentTest, ANanSampleAndTheInstructorCutItOffByName) {
  seconds(1.0);
  writers_.nan = true;
  composition_.run(3);
  EXPECT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_SAFE);
  EXPECT_NE(std::string(reader_.latest.cut_off_reason()).find("qbar_pa not finite"), std::string::npos)
      << reader_.latest.cut_off_reason();
  ASSERT_NE(fault("input_rejected"), nullptr);
  ASSERT_NE(fault("control_loading_cut_off"), nullptr);

  writers_.nan = false;
  composition_.command(cut(false));  // restore: engages again
  seconds(1.0);
  EXPECT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_ACTIVE);
  composition_.command(cut(true));
  composition_.run(2);
  EXPECT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_SAFE);
  EXPECT_EQ(std::string(reader_.latest.cut_off_reason()), "instructor cut-off");
  seconds(1.0);
  EXPECT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_SAFE);  // stays cut off until restored
}

// Lost ticks: the host calls on_ticks_stopped() once no tick came for tick_watchdog_periods()
// frame periods (1.5: half a frame after the tick that did not come); up to 2.5 periods that is
// a late tick (held), from then the SAFE state is written in that very call, not in a frame that
// is not coming. (Over DDS: Federation.StoppedTicks...)
TEST_F(ControlLoadingComponentTest, LostTicksCutItOffInTheWatchdogsOwnCall) {
  EXPECT_EQ(loader_.tick_watchdog_periods(), 1.5);
  seconds(1.0);
  ASSERT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_ACTIVE);
  std::vector<msg::ControlLoadingStatus> written;
  composition_.on_written(runtime::topics::control_loading_state,
                          std::function<void(const msg::ControlLoadingState&)>(
                              [&](const msg::ControlLoadingState& s) { written.push_back(s.status()); }));
  loader_.on_ticks_stopped(composition_.last_frame(), 0.030);
  EXPECT_TRUE(written.empty()) << "30 ms without a tick is a late tick: held";
  EXPECT_EQ(fault("control_loading_cut_off"), nullptr);
  loader_.on_ticks_stopped(composition_.last_frame(), 0.050);
  ASSERT_EQ(written.size(), 1u) << "the cut-off must go out without another frame";
  EXPECT_EQ(written[0], msg::CONTROL_LOADING_SAFE);
  ASSERT_NE(fault("control_loading_cut_off"), nullptr);
  EXPECT_NE(fault("control_loading_cut_off")->last.find("no frame tick for 50 ms"), std::string::npos)
      << fault("control_loading_cut_off")->last;
  // Negative control: while it is cut off, the watchdog has nothing more to write.
  loader_.on_ticks_stopped(composition_.last_frame(), 0.070);
  EXPECT_EQ(written.size(), 1u);
}

// The 1 h soak's case (docs/soak.md): one 32 ms gap between two ticks is ridden through and
// counted, not a cut-off.
TEST_F(ControlLoadingComponentTest, OneLateTickIsRiddenThroughAndCounted) {
  seconds(1.0);
  ASSERT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_ACTIVE);
  loader_.on_ticks_stopped(composition_.last_frame(), 0.030);  // the host's call at 1.5 periods
  seconds(0.2);                                                // the tick came at 32 ms
  EXPECT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_ACTIVE);
  EXPECT_EQ(loader_.late_ticks(), 1u);
  EXPECT_EQ(fault("control_loading_cut_off"), nullptr);
}

// Late again and again (3 within 50 frames): cut off.
TEST_F(ControlLoadingComponentTest, ABurstOfLateTicksCutsItOff) {
  seconds(1.0);
  ASSERT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_ACTIVE);
  for (int i = 0; i < 3; ++i) {
    loader_.on_ticks_stopped(composition_.last_frame(), 0.032);
    seconds(0.2);
  }
  EXPECT_EQ(loader_.late_ticks(), 3u);
  EXPECT_EQ(reader_.latest.status(), msg::CONTROL_LOADING_SAFE);
  ASSERT_NE(fault("control_loading_cut_off"), nullptr);
  EXPECT_NE(fault("control_loading_cut_off")->last.find("3 late frame ticks within 50 frames"), std::string::npos)
      << fault("control_loading_cut_off")->last;
}

TEST(ShakerSchedule, ThePacksStallWarningAnglesScheduleTheShakerOnTheFlaps) {
  ControlLoadingSetup setup;
  EXPECT_TRUE(std::isnan(scheduled_shaker_alpha_rad(setup, 0.5)));  // no --aircraft
  schedule_shaker_from_pack(fedsim::util::data_dir() + "/aircraft/c172.yaml", setup);
  ASSERT_EQ(setup.shaker_alpha_rad.size(), 5u);
  for (double a : setup.shaker_alpha_rad) {
    EXPECT_GT(a, 0.1);
    EXPECT_LT(a, 0.35);
  }
  EXPECT_DOUBLE_EQ(scheduled_shaker_alpha_rad(setup, 0.0), setup.shaker_alpha_rad[0]);
  EXPECT_DOUBLE_EQ(scheduled_shaker_alpha_rad(setup, 0.125),
                   0.5 * (setup.shaker_alpha_rad[0] + setup.shaker_alpha_rad[1]));
  EXPECT_DOUBLE_EQ(scheduled_shaker_alpha_rad(setup, 7.0), setup.shaker_alpha_rad[4]);  // clamped
  EXPECT_DOUBLE_EQ(scheduled_shaker_alpha_rad(setup, std::nan("")), setup.shaker_alpha_rad[0]);
}

}  // namespace
}  // namespace fedsim::control_loading
