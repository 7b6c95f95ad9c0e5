// Linux input devices through libevdev (the kernel's evdev interface, /dev/input/event*):
// joysticks, yokes, pedals and throttle quadrants as the kernel's HID drivers present them.
#pragma once

#include "io/devices/event_device.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::io {

class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Opens `path` (non-blocking). Throws DeviceError naming the path and the reason.
std::unique_ptr<EventDevice> open_evdev(const std::string& path);

/// The /dev/input/event* device whose name is `name` (exact match), opened; nullptr if none.
/// Devices that cannot be opened (permissions) are skipped.
std::unique_ptr<EventDevice> find_evdev(const std::string& name);

struct EvdevListing {
  std::string path;
  std::string name;
  int axes = 0;
  int buttons = 0;
};
/// Every readable /dev/input/event* device, for `fedsim io calibrate --list`.
std::vector<EvdevListing> list_evdev();

/// The opener a source retries with: by path when `path` is set, else by name.
DeviceOpener evdev_opener(const std::string& path, const std::string& name);

}  // namespace fedsim::io
