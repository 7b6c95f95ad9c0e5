// fedsim-io's adapter (the seed's node 1 inputs): every frame, samples the input source (a
// scripted profile, a real device through its calibration, either through the A/D emulation)
// and publishes the pilot controls, stamped with the frame they were sampled in. A source that
// has lost its device marks the sample DISCRETE_INPUTS_INVALID (reported as the fault
// input_device_lost); the flight federate then holds the last valid controls.
//
// The control-loading loop (--loader-in-the-loop): the input source's force channels
// (column_force_n, wheel_force_n, pedal_force_n: force sensors on the controls) go out in
// pilot_force_n with DISCRETE_FORCE_SENSORS; fedsim-control-loading moves its controls from
// those forces against the feel; and this federate reports the loader's positions (of the
// previous frame, the lockstep input) as elevator, aileron and rudder, which the flight federate
// flies. Force at frame k -> loader position at the end of k -> I/O's primaries at k+1 -> the
// flight model at k+1 (it steps on the I/O sample of the frame before): two frames from force
// to surface command.
#pragma once

#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "io/model/input_source.hpp"

#include <memory>
#include <string>

namespace fedsim::io {

/// A VHF NAV frequency dialled in MHz as the 50 kHz channel it selects [kHz].
std::uint32_t vhf_channel_khz(double frequency_mhz);
/// The pilot controls message of a set of control channels and the MCP's press counts (no
/// allocation). The autopilot-disconnect and TO/GA discretes are set while their buttons are
/// held, the wing leveller's while its switch is on; the force channels fill pilot_force_n.
void to_message(const ControlInputs& in, const McpButtonCounter& buttons, msg::PilotControls& out);

class IoComponent final : public runtime::Component {
 public:
  /// `controls_qos` overrides the catalogue's profile of fedsim/pilot_controls.
  /// `initial` is the cockpit before the source drives a channel (fedsim-fly: the start's
  /// trimmed controls and configuration).
  IoComponent(std::string name, std::unique_ptr<InputSource> source, int aircraft_id,
              std::string_view controls_qos = {}, bool loader_in_the_loop = false,
              const ControlInputs& initial = default_controls());
  void step(const runtime::FrameContext& frame) override;

 private:
  // ---- Ports -------------------------------------------------------------------------------
  // writes fedsim/pilot_controls every frame (profile pilot_controls: reliable, transient local,
  // EXCLUSIVE ownership with strength 10: a stronger outside writer takes the aircraft over).
  runtime::Output<msg::PilotControls>& pilot_controls_;
  // reads fedsim/control_loading_state (lockstep input) with --loader-in-the-loop only: its
  // positions are the primaries this federate reports.
  runtime::Input<msg::ControlLoadingState>* control_loading_state_ = nullptr;
  // reads fedsim/aircraft_state (lockstep input) for a closed-loop source only (a test pilot):
  // the state of the frame before, which the pilot sees before it moves the controls.
  runtime::Input<msg::AircraftState>* aircraft_state_ = nullptr;

  void watch_validity(bool valid);
  void take_loader_positions();
  void show_the_pilot_the_aircraft();

  std::unique_ptr<InputSource> source_;
  bool source_valid_ = true;
  ControlInputs controls_;
  McpButtonCounter mcp_buttons_;
  msg::PilotControls sample_;
};

/// Where the I/O federate's inputs come from (the program's options).
struct InputOptions {
  std::string profile;      // --profile
  std::string device;       // --device PATH
  std::string device_name;  // --device-name NAME
  std::string calibration;  // --calibration FILE
  std::string adc;          // --adc FILE
};
/// The source the options describe; throws std::invalid_argument / util::ConfigError.
std::unique_ptr<InputSource> make_input_source(const InputOptions& options);

/// fedsim-io as a program: --profile (scripted input, CSV) and/or --device/--device-name with
/// --calibration (a real inceptor; over the profile's channels where both are given), --adc
/// (the A/D emulation over either), --aircraft-id, --controls-qos.
runtime::FederateProgram program();

}  // namespace fedsim::io
