// `fedsim io calibrate`: makes a calibration file (data/inceptors/README.md) for a joystick,
// yoke, pedals or throttle quadrant, interactively: for each axis the user moves the control to
// both stops and lets it come to rest, then presses Enter.
//   fedsim io calibrate --list                              readable input devices
//   fedsim io calibrate (--device PATH | --device-name NAME)
//       --axis ABS_X=aileron [--axis ABS_Y=elevator:reversed ...]
//       [--button BTN_TRIGGER=ap_disconnect[:toggle] ...] [--dead-zone 0.02] --out FILE
// Exit status: 0 written, 1 the calibration failed (an axis not moved, stdin closed), 2 bad
// argument or device.
#pragma once

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace fedsim::io {
class EventDevice;
}

namespace fedsim::launcher {

struct CalibrateOptions {
  bool list = false;
  std::string device;
  std::string device_name;
  std::vector<std::string> axes;     // SOURCE=CHANNEL[:reversed]
  std::vector<std::string> buttons;  // SOURCE=CHANNEL[:toggle]
  double dead_zone = 0.0;
  std::string out;
};

/// Runs the calibration reading the user's Enter from `in`; returns the exit status.
int io_calibrate(const CalibrateOptions& options, std::istream& in, std::ostream& out, std::ostream& err);
/// The same on a device already open (the tests' scripted one; --device/--device-name ignored).
int io_calibrate_device(io::EventDevice& device, const CalibrateOptions& options, std::istream& in,
                        std::ostream& out, std::ostream& err);

/// Registers `fedsim io calibrate`.
void add_io_commands(CLI::App& app, int& exit_code);

}  // namespace fedsim::launcher
