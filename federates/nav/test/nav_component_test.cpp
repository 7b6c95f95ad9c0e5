// The navigation federate's adapter in the in-process composition (no DDS): instructor tuning
// and failures reach the readings, a bad aircraft-state sample is rejected and counted, a
// reposition realigns the INS.
#include "nav/nav_component.hpp"

#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

namespace fedsim::nav {
namespace {

/// Writes a fixed aircraft state every frame (level at 3000 ft, 2 NM west of the SFO VOR,
/// eastbound), or NaN in its latitude when told to.
class StateWriter final : public runtime::Component {
 public:
  StateWriter() : Component("state"), out_(writes(runtime::topics::aircraft_state)) {
    s_.latitude_rad(37.6195 * units::kDegToRad);
    s_.longitude_rad(-122.416 * units::kDegToRad);
    s_.altitude_msl_m(914.0);
    s_.q_ned_from_body({std::cos(units::kPi / 4), 0.0, 0.0, std::sin(units::kPi / 4)});
    s_.psi_rad(units::kHalfPi);
    s_.velocity_ned_mps({0.0, 55.0, 0.0});
    s_.air().tas_mps(55.0);
    s_.mass_kg(1000.0);
    s_.force_body_n({0.0, 0.0, -9806.65});
  }
  void step(const runtime::FrameContext& frame) override {
    msg::AircraftState s = s_;
    if (nan_) s.latitude_rad(std::nan(""));
    s.stamp(frame.end_stamp());
    out_.write(s);
  }
  void set_nan(bool nan) { nan_ = nan; }

 private:
  runtime::Output<msg::AircraftState>& out_;
  msg::AircraftState s_;
  bool nan_ = false;
};

/// Keeps the latest navigation state.
class NavReader final : public runtime::Component {
 public:
  NavReader() : Component("reader"), in_(reads(runtime::topics::navigation_state)) {}
  void step(const runtime::FrameContext&) override {
    if (in_.latest()) latest = *in_.latest();
  }
  msg::NavigationState latest;

 private:
  runtime::Input<msg::NavigationState>& in_;
};

msg::SimCommand failure(const std::string& target, bool active) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_FAILURE);
  c.target(target);
  c.failure().active(active);
  return c;
}

class NavComponentTest : public ::testing::Test {
 protected:
  NavComponentTest() : composition_({}) {
    NavSetup setup;
    setup.database = std::make_unique<NavDatabase>(NavDatabase::open(default_database_path()));
    nav_ = std::make_unique<NavComponent>("nav", std::move(setup));
    composition_.add(writer_);
    composition_.add(*nav_);
    composition_.add(reader_);
  }
  const msg::NavReceiver& nav1() { return reader_.latest.nav()[0]; }
  void frames(int n) { composition_.run(static_cast<std::uint64_t>(n)); }

  StateWriter writer_;
  std::unique_ptr<NavComponent> nav_;
  NavReader reader_;
  runtime::Composition composition_;
};

TEST_F(NavComponentTest, InstructorTuningAndFailuresReachTheReadings) {
  frames(5);
  EXPECT_EQ(nav1().status(), msg::SIGNAL_NOT_TUNED);  // nothing tuned yet

  msg::SimCommand tune;
  tune.kind(msg::COMMAND_RADIO_TUNING);
  tune.radios().nav1_khz(115800);
  tune.radios().obs1_rad(static_cast<float>(units::kHalfPi));
  composition_.command(tune);
  frames(5);
  ASSERT_EQ(nav1().status(), msg::SIGNAL_VALID);
  EXPECT_EQ(nav1().ident().to_string(), "SFO");
  EXPECT_EQ(nav1().to_from(), msg::TO_FROM_TO);  // west of the station, course 090
  EXPECT_EQ(nav1().dme_status(), msg::SIGNAL_VALID);
  EXPECT_TRUE(reader_.latest.gps().valid());
  EXPECT_TRUE(reader_.latest.ins().valid());

  composition_.command(failure("nav1", true));
  composition_.command(failure("gps", true));
  frames(3);
  EXPECT_EQ(nav1().status(), msg::SIGNAL_RECEIVER_FAILED);
  EXPECT_EQ(nav1().course_deviation(), 0.0);
  EXPECT_EQ(nav1().to_from(), msg::TO_FROM_OFF);
  EXPECT_FALSE(reader_.latest.gps().valid());
  EXPECT_TRUE(reader_.latest.gps().denied());

  composition_.command(failure("nav1", false));
  composition_.command(failure("gps", false));
  composition_.command(failure("station-dme:SFO", true));
  frames(3);
  EXPECT_EQ(nav1().status(), msg::SIGNAL_VALID);        // the VOR is on the air
  EXPECT_EQ(nav1().dme_status(), msg::SIGNAL_STATION_OFF_AIR);  // its DME is not
  EXPECT_LT(nav1().dme_slant_range_m(), 0.0);
  EXPECT_TRUE(reader_.latest.gps().valid());
  EXPECT_EQ(composition_.fault_count(), 0u);
}

TEST_F(NavComponentTest, ANonFiniteAircraftStateIsRejectedAndCounted) {
  frames(5);
  writer_.set_nan(true);
  frames(5);
  EXPECT_GE(composition_.fault_count(), 4u);
  ASSERT_FALSE(nav_->faults().empty());
  EXPECT_EQ(nav_->faults()[0].kind, "input_rejected");
  EXPECT_NE(nav_->faults()[0].last.find("lat_rad not finite"), std::string::npos) << nav_->faults()[0].last;
  // The navigation state still comes from the last good sample, never from NaN.
  EXPECT_TRUE(std::isfinite(reader_.latest.ins().latitude_rad()));
  EXPECT_TRUE(reader_.latest.ins().valid());
}

}  // namespace
}  // namespace fedsim::nav
