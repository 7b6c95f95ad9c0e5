// Conversion between the I/O channels (io::ControlInputs, what input profiles drive) and the
// flight model's commands (AircraftControls).
#pragma once

#include "flight/model/aircraft/aircraft_controls.hpp"
#include "io/model/control_inputs.hpp"

namespace fedsim::flight {

/// The channels of a command set (spoilers have no I/O channel and are dropped).
io::ControlInputs to_control_inputs(const AircraftControls& controls);

/// The commands of a channel set; `base` supplies what the channels do not carry (spoilers).
/// The gear lever is down for a channel value of 0.5 or more.
AircraftControls from_control_inputs(const io::ControlInputs& inputs, const AircraftControls& base);

}  // namespace fedsim::flight
