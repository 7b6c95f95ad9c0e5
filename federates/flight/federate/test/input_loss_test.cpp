// A lost input device end to end in the in-process composition: the I/O federate's source goes
// invalid (a joystick unplugged), the I/O federate reports input_device_lost and marks its
// samples DISCRETE_INPUTS_INVALID, the flight federate reports pilot_inputs_invalid and flies
// the last valid controls until the samples are valid again, then takes them.
#include "flight/federate/flight_program.hpp"
#include "io/io_component.hpp"

#include "common/runtime/composition.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace fedsim::flight {
namespace {

/// A stick that is unplugged from 2 s to 4 s; the aileron it would read moves all the time
/// (what the I/O federate is left with while it is gone is not the pilot's).
class UnpluggedStick final : public io::InputSource {
 public:
  void sample(double t, io::ControlInputs& controls) override {
    now_s = t;
    controls[io::Channel::kAileron] = t < 1.0 ? 0.1 : (t < 3.0 ? 0.2 : 0.3);
  }
  std::string describe() const override { return "test stick"; }
  bool valid() const override { return now_s < 2.0 || now_s >= 4.0; }
  double now_s = 0.0;
};

class FlownAileron final : public runtime::Component {
 public:
  FlownAileron() : Component("recorder"), aircraft_(reads(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext&) override {
    if (aircraft_.latest()) aileron.push_back(aircraft_.latest()->controls().aileron());
  }
  std::vector<double> aileron;

 private:
  runtime::Input<msg::AircraftState>& aircraft_;
};

std::uint64_t faults_of(const runtime::Component& c, const std::string& kind) {
  for (const auto& f : c.faults()) {
    if (f.kind == kind) return f.count;
  }
  return 0;
}

TEST(InputLoss, TheFlightFederateHoldsTheLastValidControlsWhileTheDeviceIsGone) {
  io::IoComponent io("io", std::make_unique<UnpluggedStick>(), 0);
  FlightOptions o;
  o.aircraft = "c172";
  o.start.trim_kind = "level";
  o.start.ktas = 100.0;
  auto flight = make_flight_component("flight", o);
  FlownAileron recorder;
  runtime::Composition composition({});
  composition.add(io);
  composition.add(*flight);
  composition.add(recorder);
  for (int i = 0; i < 6 * 50; ++i) composition.step_frame();
  const std::vector<double>& a = recorder.aileron;
  ASSERT_GE(a.size(), 290u);
  auto at = [&](double t) { return a[static_cast<std::size_t>(t * 50.0)]; };
  EXPECT_NEAR(at(1.5), 0.2, 1e-6);
  EXPECT_NEAR(at(2.5), 0.2, 1e-6);  // unplugged: the stick "reads" 0.2 and then 0.3, held at 0.2
  EXPECT_NEAR(at(3.5), 0.2, 1e-6);
  EXPECT_NEAR(at(4.5), 0.3, 1e-6);  // back: taken again
  EXPECT_EQ(faults_of(io, "input_device_lost"), 1u);
  EXPECT_EQ(faults_of(*flight, "pilot_inputs_invalid"), 1u);
}

}  // namespace
}  // namespace fedsim::flight
