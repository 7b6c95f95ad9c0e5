// An input device as the I/O federate reads it: readings named as the kernel names its event
// codes ("ABS_Y", "BTN_TRIGGER"), drained without blocking. evdev_device.hpp is the Linux
// implementation (libevdev); tests substitute their own.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::io {

struct DeviceReading {
  enum class Kind { kAxis, kContact };
  Kind kind = Kind::kAxis;
  std::string source;  ///< e.g. "ABS_X", "BTN_TRIGGER"
  double value = 0.0;  ///< axis: raw counts; contact: 1 pressed, 0 released
};

struct AxisInfo {
  std::string source;
  double minimum = 0.0;  ///< the range the device reports
  double maximum = 0.0;
  double value = 0.0;    ///< the present reading
};

class EventDevice {
 public:
  virtual ~EventDevice() = default;
  virtual std::string name() const = 0;
  virtual std::string path() const = 0;
  /// Appends the readings pending since the last call (never blocks). False when the device
  /// has gone (unplugged, a read error): the caller drops it.
  virtual bool poll(std::vector<DeviceReading>& readings) = 0;
  /// Every absolute axis with its range and present value.
  virtual std::vector<AxisInfo> axes() const = 0;
  /// Every key or button and whether it is pressed now.
  virtual std::vector<DeviceReading> contacts() const = 0;
  /// A file descriptor that poll(2) reports readable when readings are pending (-1: none).
  virtual int fd() const { return -1; }
};

/// Opens the device a source is configured for; nullptr when it is not there (yet).
using DeviceOpener = std::function<std::unique_ptr<EventDevice>()>;

}  // namespace fedsim::io
