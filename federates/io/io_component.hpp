// fedsim-io's adapter (the seed's node 1 inputs): every frame, samples the input source (a
// scripted profile today; joysticks and A/D emulation implement the same InputSource) and
// publishes the pilot controls, stamped with the frame they were sampled in.
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
/// allocation). The autopilot-disconnect and TO/GA discretes are set while their buttons are held.
void to_message(const ControlInputs& in, const McpButtonCounter& buttons, msg::PilotControls& out);

class IoComponent final : public runtime::Component {
 public:
  /// `controls_qos` overrides the catalogue's profile of fedsim/pilot_controls.
  IoComponent(std::string name, std::unique_ptr<InputSource> source, int aircraft_id,
              std::string_view controls_qos = {});
  void step(const runtime::FrameContext& frame) override;

 private:
  // ---- Ports -------------------------------------------------------------------------------
  // writes fedsim/pilot_controls every frame (lockstep_data: reliable, transient local).
  runtime::Output<msg::PilotControls>& pilot_controls_;

  std::unique_ptr<InputSource> source_;
  ControlInputs controls_ = default_controls();
  McpButtonCounter mcp_buttons_;
  msg::PilotControls sample_;
};

/// fedsim-io as a program: --profile (scripted input, CSV), --aircraft-id, --controls-qos.
runtime::FederateProgram program();

}  // namespace fedsim::io
