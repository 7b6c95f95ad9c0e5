// The device source's hot-plug and mapping with a scripted device standing in for the kernel:
// a device that goes away makes the source invalid (the controls keep their last values), the
// source retries at its interval, and takes the device's present state when it comes back.
#include "io/devices/device_source.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace fedsim::io {
namespace {

/// The device's state, shared by every "plug-in" of it.
struct FakeHardware {
  bool plugged = true;
  std::string name = "Fake Stick";
  double x = 512.0;
  bool trigger = false;
  std::vector<DeviceReading> pending;
  int opens = 0;
};

class FakeDevice final : public EventDevice {
 public:
  explicit FakeDevice(FakeHardware& hw) : hw_(hw) {}
  std::string name() const override { return hw_.name; }
  std::string path() const override { return "/dev/input/fake"; }
  bool poll(std::vector<DeviceReading>& readings) override {
    if (!hw_.plugged) return false;
    readings.insert(readings.end(), hw_.pending.begin(), hw_.pending.end());
    hw_.pending.clear();
    return true;
  }
  std::vector<AxisInfo> axes() const override { return {{"ABS_X", 0, 1023, hw_.x}}; }
  std::vector<DeviceReading> contacts() const override {
    return {{DeviceReading::Kind::kContact, "BTN_TRIGGER", hw_.trigger ? 1.0 : 0.0}};
  }

 private:
  FakeHardware& hw_;
};

InceptorCalibration stick_calibration() {
  InceptorCalibration c;
  c.device_name = "Fake Stick";
  AxisCalibration x;
  x.source = "ABS_X";
  x.channel = Channel::kAileron;
  x.raw_min = 0;
  x.raw_centre = 512;
  x.raw_max = 1023;
  c.axes.push_back(x);
  DiscreteCalibration t;
  t.source = "BTN_TRIGGER";
  t.channel = Channel::kApDisconnect;
  t.debounce_s = 0.0;
  c.discretes.push_back(t);
  return c;
}

struct Rig {
  FakeHardware hw;
  double now_s = 0.0;
  std::unique_ptr<DeviceSource> source;
  Rig() {
    DeviceSource::Options o;
    o.retry_interval_s = 1.0;
    o.now_s = [this] { return now_s; };
    source = std::make_unique<DeviceSource>(
        [this]() -> std::unique_ptr<EventDevice> {
          ++hw.opens;
          return hw.plugged ? std::make_unique<FakeDevice>(hw) : nullptr;
        },
        "fake", stick_calibration(), o);
  }
  ControlInputs sample(double t) {
    now_s = t;
    ControlInputs in = default_controls();
    in[Channel::kAileron] = last_aileron;
    source->sample(t, in);
    last_aileron = in[Channel::kAileron];
    return in;
  }
  double last_aileron = 0.0;
};

TEST(DeviceSource, TakesTheDevicesStateAtOpenAndItsEventsAfter) {
  Rig r;
  r.hw.x = 1023.0;  // held right before the federate started: no event will come
  ControlInputs in = r.sample(0.0);
  EXPECT_TRUE(r.source->valid());
  EXPECT_DOUBLE_EQ(in[Channel::kAileron], 1.0);
  r.hw.pending = {{DeviceReading::Kind::kAxis, "ABS_X", 0.0},
                  {DeviceReading::Kind::kContact, "BTN_TRIGGER", 1.0}};
  in = r.sample(0.02);
  EXPECT_DOUBLE_EQ(in[Channel::kAileron], -1.0);
  EXPECT_EQ(in[Channel::kApDisconnect], 1.0);
  EXPECT_NE(r.source->describe().find("'Fake Stick'"), std::string::npos) << r.source->describe();
}

TEST(DeviceSource, UnpluggedItIsInvalidRetriesAtItsIntervalAndResumes) {
  Rig r;
  r.sample(0.0);
  r.hw.pending = {{DeviceReading::Kind::kAxis, "ABS_X", 767.5}};  // aileron +0.5
  EXPECT_DOUBLE_EQ(r.sample(0.02)[Channel::kAileron], 0.5);
  r.hw.plugged = false;
  ControlInputs in = r.sample(0.04);
  EXPECT_FALSE(r.source->valid());
  EXPECT_EQ(r.source->losses(), 1u);
  EXPECT_DOUBLE_EQ(in[Channel::kAileron], 0.5);  // the last reading stays (the sample is marked invalid)
  EXPECT_NE(r.source->last_problem().find("went away"), std::string::npos);
  const int opens = r.hw.opens;
  for (double t = 0.06; t < 1.0; t += 0.02) r.sample(t);  // within the retry interval: no attempt
  EXPECT_EQ(r.hw.opens, opens);
  r.sample(1.05);                                         // one attempt, still unplugged
  EXPECT_EQ(r.hw.opens, opens + 1);
  EXPECT_FALSE(r.source->valid());
  r.hw.plugged = true;
  r.hw.x = 0.0;  // moved while unplugged
  r.sample(1.5);
  EXPECT_FALSE(r.source->valid());  // next attempt at 2.05
  in = r.sample(2.1);
  EXPECT_TRUE(r.source->valid());
  EXPECT_EQ(r.source->connections(), 2u);
  EXPECT_DOUBLE_EQ(in[Channel::kAileron], -1.0);  // its present state, read at the reconnection
}

TEST(DeviceSource, ADeviceOtherThanTheCalibratedOneIsRefused) {
  Rig r;
  r.hw.name = "Another Gamepad";
  r.sample(0.0);
  EXPECT_FALSE(r.source->valid());
  EXPECT_NE(r.source->last_problem().find("'Another Gamepad', the calibration is for 'Fake Stick'"),
            std::string::npos)
      << r.source->last_problem();
}

}  // namespace
}  // namespace fedsim::io
