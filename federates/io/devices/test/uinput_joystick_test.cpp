// A joystick through the kernel: a virtual device made with uinput (libevdev's uinput API) is
// read by the evdev device source exactly as a USB stick would be, unplugged and plugged back.
// Needs /dev/uinput (the uinput module, and the right to open it): where it is missing the test
// is skipped and says so; the mapping, calibration and hot-plug logic are tested without it
// (device_source_test.cpp, io/model/test).
#include "io/devices/device_source.hpp"
#include "io/devices/evdev_device.hpp"

#include <gtest/gtest.h>
#include <libevdev/libevdev-uinput.h>
#include <libevdev/libevdev.h>

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

namespace fedsim::io {
namespace {

constexpr const char* kName = "fedsim test joystick";

/// A virtual two-axis stick with a trigger; destroyed (unplugged) with the object.
class VirtualStick {
 public:
  VirtualStick() {
    libevdev* dev = libevdev_new();
    libevdev_set_name(dev, kName);
    input_absinfo abs{};
    abs.minimum = 0;
    abs.maximum = 1023;
    abs.value = 512;
    libevdev_enable_event_code(dev, EV_ABS, ABS_X, &abs);
    libevdev_enable_event_code(dev, EV_ABS, ABS_Y, &abs);
    libevdev_enable_event_code(dev, EV_KEY, BTN_TRIGGER, nullptr);
    const int rc = libevdev_uinput_create_from_device(dev, LIBEVDEV_UINPUT_OPEN_MANAGED, &uinput_);
    libevdev_free(dev);
    if (rc < 0) uinput_ = nullptr;
  }
  ~VirtualStick() {
    if (uinput_) libevdev_uinput_destroy(uinput_);
  }
  bool ok() const { return uinput_ != nullptr; }
  void move(unsigned code, int value) {
    libevdev_uinput_write_event(uinput_, EV_ABS, code, value);
    libevdev_uinput_write_event(uinput_, EV_SYN, SYN_REPORT, 0);
  }
  void press(bool down) {
    libevdev_uinput_write_event(uinput_, EV_KEY, BTN_TRIGGER, down ? 1 : 0);
    libevdev_uinput_write_event(uinput_, EV_SYN, SYN_REPORT, 0);
  }

 private:
  libevdev_uinput* uinput_ = nullptr;
};

std::string uinput_unavailable() {
  const int fd = ::open("/dev/uinput", O_RDWR | O_CLOEXEC);
  if (fd < 0) return "/dev/uinput cannot be opened here (no uinput module, or no permission)";
  ::close(fd);
  return "";
}

InceptorCalibration calibration() {
  return InceptorCalibration::parse(std::string("fedsim_inceptor_calibration: 1\ndevice_name: \"") + kName +
                                        "\"\naxes:\n"
                                        "  - {source: ABS_X, channel: aileron, raw_min: 0, raw_centre: 512, raw_max: 1023}\n"
                                        "  - {source: ABS_Y, channel: elevator, raw_min: 0, raw_centre: 512, raw_max: 1023, reversed: true}\n"
                                        "discretes:\n  - {source: BTN_TRIGGER, channel: ap_disconnect, debounce_ms: 0}\n",
                                    "virtual.yaml");
}

/// Samples until `done` holds (the kernel delivers asynchronously, and udev makes a new device's
/// node a little after it is created: the source retries opening it) or 5 s have passed.
template <class Done>
ControlInputs sample_until(DeviceSource& source, double& t, Done done) {
  ControlInputs in = default_controls();
  for (int i = 0; i < 500; ++i) {
    t += 0.01;
    source.sample(t, in);
    if (done(in)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return in;
}

TEST(UinputJoystick, AVirtualStickFliesThroughEvdevAndSurvivesBeingUnplugged) {
  if (const std::string why = uinput_unavailable(); !why.empty()) {
    GTEST_SKIP() << "uinput joystick test not run: " << why
                 << "; the calibration, mapping and hot-plug logic are tested without a device";
  }
  auto stick = std::make_unique<VirtualStick>();
  ASSERT_TRUE(stick->ok()) << "could not create the uinput device";
  DeviceSource::Options options;
  options.retry_interval_s = 0.05;
  DeviceSource source(evdev_opener("", kName), "named test joystick", calibration(), options);
  double t = 0.0;
  ControlInputs in = sample_until(source, t, [&](const ControlInputs&) { return source.valid(); });
  ASSERT_TRUE(source.valid()) << source.last_problem();
  stick->move(ABS_X, 1023);
  stick->move(ABS_Y, 0);
  stick->press(true);
  in = sample_until(source, t, [](const ControlInputs& c) { return c[Channel::kApDisconnect] == 1.0; });
  EXPECT_DOUBLE_EQ(in[Channel::kAileron], 1.0);
  EXPECT_DOUBLE_EQ(in[Channel::kElevator], 1.0);  // reversed: stick fully back reads 0
  EXPECT_EQ(in[Channel::kApDisconnect], 1.0);

  stick.reset();  // unplugged
  sample_until(source, t, [&](const ControlInputs&) { return !source.valid(); });
  EXPECT_FALSE(source.valid());
  EXPECT_EQ(source.losses(), 1u);
  stick = std::make_unique<VirtualStick>();  // plugged back (a new node, found by name)
  in = sample_until(source, t, [&](const ControlInputs&) { return source.valid(); });
  EXPECT_TRUE(source.valid()) << source.last_problem();
  EXPECT_DOUBLE_EQ(in[Channel::kAileron], 0.0);  // the new stick rests centred
}

}  // namespace
}  // namespace fedsim::io
