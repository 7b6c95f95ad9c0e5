// The pilot's wing-leveller switch end to end in the in-process composition: a scripted
// profile sets the I/O federate's `wing_leveller` channel, which travels as the
// DISCRETE_WING_LEVELLER bit of fedsim/pilot_controls to the flight federate, which engages
// the C172 pack's wing leveller. The C172 starts in a trimmed 20 deg turn with relative
// controls, so without the switch it keeps turning (the negative control).
#include "flight/federate/flight_program.hpp"
#include "io/io_component.hpp"
#include "io/model/input_profile.hpp"

#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::flight {
namespace {

constexpr double kDeg = units::kDegToRad;

class BankRecorder final : public runtime::Component {
 public:
  BankRecorder() : Component("recorder"), aircraft_(reads(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext&) override {
    if (aircraft_.latest()) bank_rad.push_back(aircraft_.latest()->phi_rad());
  }
  std::vector<double> bank_rad;  // one per frame

 private:
  runtime::Input<msg::AircraftState>& aircraft_;
};

FlightOptions c172_in_a_turn() {
  FlightOptions o;
  o.aircraft = "c172";
  o.controls = "relative";
  o.start.trim_kind = "turn";
  o.start.bank_deg = 20.0;
  o.start.alt_ft = 4000.0;
  o.start.ktas = 100.0;
  return o;
}

/// Flies 30 s at 50 Hz with the switch turned on at `switch_on_s` (never if negative); the
/// bank of every frame.
std::vector<double> fly(double switch_on_s) {
  std::string profile = "time_s,wing_leveller\n0,0\n";
  if (switch_on_s >= 0.0) {
    profile += std::to_string(switch_on_s) + ",0\n" + std::to_string(switch_on_s) + ",1\n";
  }
  io::IoComponent io("io", std::make_unique<io::InputProfile>(io::InputProfile::parse(profile, "switch.csv")), 0);
  auto flight = make_flight_component("flight", c172_in_a_turn());
  BankRecorder recorder;
  runtime::Composition composition({});
  composition.add(io);
  composition.add(*flight);
  composition.add(recorder);
  for (int i = 0; i < 30 * 50; ++i) composition.step_frame();
  return recorder.bank_rad;
}

double largest_bank_after(const std::vector<double>& bank, double from_s) {
  double worst = 0.0;
  for (std::size_t i = static_cast<std::size_t>(from_s * 50.0); i < bank.size(); ++i) {
    worst = std::max(worst, std::abs(bank[i]));
  }
  return worst;
}

TEST(WingLevellerSwitch, TheProfilesSwitchLevelsTheWingsOfTheC172) {
  const std::vector<double> on = fly(5.0);
  ASSERT_GT(on.size(), 1400u);
  EXPECT_NEAR(on[static_cast<std::size_t>(4.9 * 50)], 20.0 * kDeg, 1.0 * kDeg);  // still turning
  EXPECT_LT(largest_bank_after(on, 17.0), 1.0 * kDeg);  // level within 12 s, and held
  // Negative control: no switch, the trimmed turn goes on.
  const std::vector<double> off = fly(-1.0);
  EXPECT_NEAR(off.back(), 20.0 * kDeg, 2.0 * kDeg);
}

}  // namespace
}  // namespace fedsim::flight
