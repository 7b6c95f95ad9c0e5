// The AFCS's translation layer in the flight federate (no DDS calls): the mode control panel and
// the force sensors (control-wheel steering) of fedsim/pilot_controls and NAV1's ILS or VOR readings of fedsim/navigation_state in, the FMA, the
// flight-director bars and the AFCS's commands out on fedsim/autopilot_state.
//
// Buttons travel as press counters (controls.idl McpPanel): McpPressTracker turns the increase
// of a counter into one press in the frame it is first seen, whatever samples were lost or
// repeated in between.
#pragma once

#include "fedsim/msg/autopilot.h"
#include "fedsim/msg/controls.h"
#include "fedsim/msg/navigation.h"
#include "flight/model/afcs/afcs.hpp"

#include <array>
#include <optional>
#include <string>

namespace fedsim::flight {

/// Why an MCP sample cannot be used (a non-finite value, or one outside the AFCS's input
/// ranges, afcs_inputs.hpp), or nullopt if it can.
std::optional<std::string> check_mcp(const msg::McpPanel& mcp);

/// The MCP selections (held values) of a sample checked by check_mcp(); the CWS inputs are
/// hands off (the caller sets them from cws_inputs()).
afcs::McpSelections mcp_selections(const msg::McpPanel& mcp);
/// Control-wheel steering: the AFCS's pilot_pitch_input / pilot_roll_input (-1..1) from the force
/// sensors of a pilot-controls sample (pilot_force_n: column + push, wheel + right).
struct CwsInputs {
  double pitch = 0.0;  // + nose up (a pull: the column's force negative)
  double roll = 0.0;   // + right wing down (the wheel's force positive)
};
/// One axis: 0 within +-breakout, then linear to +-1 at +-full, held beyond (same sign as the
/// force). NaN gives 0.
double cws_input_from_force(double force_n, double breakout_n, double full_n);
/// Why the force sensors' readings of a sample cannot be used (a non-finite value, or one beyond
/// kMaxPilotForceN on any axis, pedals included), or nullopt. Only meaningful with
/// DISCRETE_FORCE_SENSORS.
std::optional<std::string> check_pilot_forces(const msg::PilotControls& pilot);
inline constexpr double kMaxPilotForceN = 2000.0;
/// The CWS inputs of a sample checked by check_pilot_forces(): hands off (0, 0) without
/// DISCRETE_FORCE_SENSORS (no sensors: pilot_force_n means nothing) or with
/// DISCRETE_INPUTS_INVALID (the I/O federate's device is lost).
CwsInputs cws_inputs(const msg::PilotControls& pilot, const afcs::AfcsParameters& parameters);

/// The selections before any panel sample arrived: the aircraft's own heading, altitude and
/// speed (clamped into the MCP's ranges), so that the AFCS sees a valid panel.
afcs::McpSelections mcp_before_first_sample(const afcs::AfcsAircraftState& aircraft);

class McpPressTracker {
 public:
  /// The buttons pressed since the previous sample. The first sample seen presses nothing (its
  /// counts are the baseline: a federate joining late does not replay old presses); a counter
  /// that went down (the I/O federate restarted) becomes the new baseline.
  afcs::McpButtons presses(const msg::McpPanel& mcp);
  void reset() { seen_ = false; }

 private:
  std::array<std::uint32_t, msg::MCP_BUTTON_COUNT> counts_{};
  bool seen_ = false;
};

/// The AFCS's NAV port from a NAV receiver of the navigation state: the localizer only when the
/// receiver holds a valid localizer signal, the glide slope only when its status is valid; with
/// a VOR received (signal VOR, valid or flagged) the vor part: tuned, valid, the cone-of-confusion
/// flag, and when valid the deviation, course, TO/FROM (full scale: common/radio's 10 deg, which
/// navigation.idl does not carry), the DME's slant range when its status is valid. A flagged
/// signal's numbers are never passed on.
afcs::AfcsIlsSignals ils_signals_from_receiver(const msg::NavReceiver& nav);
/// The vor part of ils_signals_from_receiver().
afcs::AfcsVorSignals vor_signals_from_receiver(const msg::NavReceiver& nav);

/// Fills an AutopilotState sample from the AFCS after its step (no allocation).
void fill_autopilot_state(const afcs::Afcs& afcs, std::uint32_t transitions, msg::AutopilotState& out);

/// The IDL enums of the FMA's modes (the same order as afcs_modes.hpp).
msg::FmaThrustMode to_message(afcs::ThrustMode mode);
msg::FmaRollMode to_message(afcs::LateralMode mode);
msg::FmaPitchMode to_message(afcs::VerticalMode mode);

}  // namespace fedsim::flight
