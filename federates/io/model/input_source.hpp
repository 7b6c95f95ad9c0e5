// Where pilot inputs come from. The scripted profile is one source; joystick (SDL2/evdev) and
// A/D-converter emulation slot in as further implementations.
#pragma once

#include "io/model/control_inputs.hpp"

#include <string>

namespace fedsim::io {

class InputSource {
 public:
  virtual ~InputSource() = default;
  /// Writes the inputs at simulation time `sim_time_s` into `controls`. Channels the source
  /// does not drive are left as they are.
  virtual void sample(double sim_time_s, ControlInputs& controls) = 0;
  /// One line for logs, e.g. "profile doublets.csv (3 channels, 0-30 s)".
  virtual std::string describe() const = 0;
};

}  // namespace fedsim::io
