// The pilot's inceptors and selectors as plain numbers (no DDS), shared by the I/O federate and
// the batch flight program. Ranges and signs as in federates/flight/DESIGN.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fedsim::io {

constexpr int kMaxEngines = 4;

enum class Channel {
  kElevator, kAileron, kRudder,                       // -1..1
  kElevatorTrim, kAileronTrim, kRudderTrim,           // -1..1
  kThrottle1, kThrottle2, kThrottle3, kThrottle4,     // 0..1
  kMixture1, kMixture2, kMixture3, kMixture4,         // 0..1
  kPropeller1, kPropeller2, kPropeller3, kPropeller4, // 0..1
  kFlaps, kSpeedbrake, kGearDown,                     // 0..1 (gear: 0 up, 1 down)
  kBrakeLeft, kBrakeRight,                            // 0..1
  kNosewheelSteering,                                 // -1..1
  kWingLeveller,                                      // switch: on while >= 0.5
  // Force sensors on the primaries, for a control loader in the loop (+ push, + right) [N]
  kColumnForceN, kWheelForceN, kPedalForceN,          // -1500..1500 N
  // Radio tuning (the edges' units, as a pilot dials them; 0 = not tuned). A profile should
  // change them in steps (a repeated time), not ramps, or the radio tunes through the band.
  kNav1Mhz, kNav2Mhz,                                 // 0..117.95 MHz
  kAdfKhz,                                            // 0..1750 kHz
  kObs1Deg, kObs2Deg,                                 // 0..360 deg, magnetic
  // The autopilot's mode control panel (MCP), in the edges' units: selections...
  kMcpHeadingDeg,                                     // 0..360 deg, TRUE (fedsim's headings are)
  kMcpAltitudeFt,                                     // -1000..50000 ft MSL
  kMcpVerticalSpeedFpm,                               // -6000..6000 ft/min, + up
  kMcpSpeedKt,                                        // 80..380 kt calibrated
  kMcpBankLimitDeg,                                   // 5..30 deg
  kFlightDirector, kAutothrottleArm,                  // switches: on while >= 0.5
  kAutobrake,                                         // 0 off, 1, 2, 3, 4 = MAX (rounded)
  // ...and buttons, in the order of controls.idl's MCP_* indices: held while >= 0.5, each
  // rise from below 0.5 is one press (a profile steps 0 -> 1 -> 0 to press).
  kMcpCmd, kMcpCws, kApDisconnect, kAtDisconnect, kMcpHdgSel, kMcpWlv, kMcpVorLoc, kMcpApp,
  kMcpAltHld, kMcpVs, kMcpLvlChg, kMcpSpeed, kMcpN1, kToga,
  kCount
};
constexpr int kChannelCount = static_cast<int>(Channel::kCount);
constexpr int kMcpButtonCount = static_cast<int>(Channel::kToga) - static_cast<int>(Channel::kMcpCmd) + 1;

struct ChannelInfo {
  std::string_view name;  // as written in profile files
  double min;
  double max;
};
const ChannelInfo& channel_info(Channel channel);
/// Channels a profile column name stands for: "elevator" -> {kElevator}; "throttle" -> all
/// four throttles; "brakes" -> both brakes. Empty if the name is unknown.
std::vector<Channel> channels_named(std::string_view name);
/// Every accepted column name, for error messages and documentation.
std::vector<std::string> known_channel_names();

struct ControlInputs {
  std::array<double, kChannelCount> value{};  // indexed by Channel

  double& operator[](Channel c) { return value[static_cast<int>(c)]; }
  double operator[](Channel c) const { return value[static_cast<int>(c)]; }
  double throttle(int engine) const { return value[static_cast<int>(Channel::kThrottle1) + engine]; }
  double mixture(int engine) const { return value[static_cast<int>(Channel::kMixture1) + engine]; }
  double propeller(int engine) const { return value[static_cast<int>(Channel::kPropeller1) + engine]; }
  /// Clamps every channel to its range.
  void clamp();
};

/// A sensible cockpit at rest: controls centred, mixture and propeller full forward, gear down;
/// the MCP at heading 000, 0 ft, 0 ft/min, 150 kt, bank limit 25 deg, FD on, A/T and autobrake off.
ControlInputs default_controls();

/// Counts the presses of the MCP buttons: a button channel rising to >= 0.5 is one press.
class McpButtonCounter {
 public:
  void update(const ControlInputs& controls);
  /// Presses of each button so far (index = button channel - kMcpCmd = controls.idl's MCP_*).
  const std::array<std::uint32_t, kMcpButtonCount>& presses() const { return presses_; }
  /// Whether a button is held in the latest update.
  bool held(Channel button) const;

 private:
  std::array<std::uint32_t, kMcpButtonCount> presses_{};
  std::array<bool, kMcpButtonCount> held_{};
};

}  // namespace fedsim::io
