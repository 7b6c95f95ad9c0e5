// `fedsim io calibrate` end to end on a scripted device: the axes moved to their stops and left
// at rest, Enter pressed after each, the file written and read back as the calibration the
// federate flies with; an axis not moved, and stdin closed early, write nothing.
#include "fedsim/io_cli.hpp"

#include "io/devices/event_device.hpp"
#include "io/model/inceptor_calibration.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace fedsim::launcher {
namespace {

/// A stick whose readings come in batches, one batch per poll.
class ScriptedStick final : public io::EventDevice {
 public:
  std::string name() const override { return "Scripted Stick"; }
  std::string path() const override { return "/dev/input/scripted"; }
  bool poll(std::vector<io::DeviceReading>& readings) override {
    if (next_ < batches.size()) readings = batches[next_++];
    return true;
  }
  std::vector<io::AxisInfo> axes() const override { return {{"ABS_X", 0, 1023, 512}, {"ABS_Z", 0, 255, 0}}; }
  std::vector<io::DeviceReading> contacts() const override {
    return {{io::DeviceReading::Kind::kContact, "BTN_TRIGGER", 0.0}};
  }
  std::vector<std::vector<io::DeviceReading>> batches;

 private:
  std::size_t next_ = 0;
};

std::vector<io::DeviceReading> sweep(const std::string& source, std::vector<double> values) {
  std::vector<io::DeviceReading> out;
  for (double v : values) out.push_back({io::DeviceReading::Kind::kAxis, source, v});
  return out;
}

CalibrateOptions options(const std::string& out) {
  CalibrateOptions o;
  o.axes = {"ABS_X=aileron", "ABS_Z=throttle1:reversed"};
  o.buttons = {"BTN_TRIGGER=ap_disconnect"};
  o.dead_zone = 0.02;
  o.out = out;
  return o;
}

TEST(IoCalibrate, WritesTheStopsAndRestOfEachAxisAsAFileTheFederateReads) {
  const std::string file = testing::TempDir() + "scripted_stick.yaml";
  std::filesystem::remove(file);
  ScriptedStick stick;
  stick.batches = {sweep("ABS_X", {512, 200, 3, 700, 1020, 515}), sweep("ABS_Z", {0, 128, 250, 240})};
  std::istringstream enter("\n\n");
  std::ostringstream out, err;
  ASSERT_EQ(io_calibrate_device(stick, options(file), enter, out, err), 0) << err.str();
  const io::InceptorCalibration c = io::InceptorCalibration::load_file(file);
  EXPECT_EQ(c.device_name, "Scripted Stick");
  ASSERT_EQ(c.axes.size(), 2u);
  EXPECT_EQ(c.axes[0].raw_min, 3.0);
  EXPECT_EQ(c.axes[0].raw_max, 1020.0);
  EXPECT_EQ(c.axes[0].raw_centre, 515.0);
  EXPECT_EQ(c.axes[0].dead_zone, 0.02);
  EXPECT_TRUE(c.axes[1].reversed);
  EXPECT_EQ(c.axes[1].dead_zone, 0.0);  // not a centred control
  EXPECT_DOUBLE_EQ(io::calibrate_axis(c.axes[1], 0.0), 1.0);  // reversed: the low end is full
  ASSERT_EQ(c.discretes.size(), 1u);
  EXPECT_NE(out.str().find("wrote " + file), std::string::npos) << out.str();
}

TEST(IoCalibrate, AnAxisNotMovedOrStdinClosedWritesNothing) {
  const std::string file = testing::TempDir() + "unmoved_stick.yaml";
  std::filesystem::remove(file);
  {
    ScriptedStick stick;
    stick.batches = {sweep("ABS_X", {512, 530, 505})};  // barely moved
    std::istringstream enter("\n\n");
    std::ostringstream out, err;
    EXPECT_EQ(io_calibrate_device(stick, options(file), enter, out, err), 1);
    EXPECT_NE(err.str().find("move it to both stops"), std::string::npos) << err.str();
    EXPECT_FALSE(std::filesystem::exists(file));
  }
  {
    ScriptedStick stick;
    stick.batches = {sweep("ABS_X", {0, 1023, 512})};
    std::istringstream enter("\n");  // closed before the second axis
    std::ostringstream out, err;
    EXPECT_EQ(io_calibrate_device(stick, options(file), enter, out, err), 1);
    EXPECT_NE(err.str().find("stdin closed"), std::string::npos) << err.str();
    EXPECT_FALSE(std::filesystem::exists(file));
  }
  {
    ScriptedStick stick;
    CalibrateOptions o = options(file);
    o.axes = {"ABS_RY=elevator"};
    std::istringstream enter("\n");
    std::ostringstream out, err;
    EXPECT_EQ(io_calibrate_device(stick, o, enter, out, err), 2);
    EXPECT_NE(err.str().find("no axis ABS_RY (it has: ABS_X ABS_Z)"), std::string::npos) << err.str();
  }
}

}  // namespace
}  // namespace fedsim::launcher
