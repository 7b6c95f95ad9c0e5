// The pilot's inceptors and selectors as plain numbers (no DDS), shared by the I/O federate and
// the batch flight program. Ranges and signs as in federates/flight/DESIGN.md.
#pragma once

#include <array>
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
  // Radio tuning (the edges' units, as a pilot dials them; 0 = not tuned). A profile should
  // change them in steps (a repeated time), not ramps, or the radio tunes through the band.
  kNav1Mhz, kNav2Mhz,                                 // 0..117.95 MHz
  kAdfKhz,                                            // 0..1750 kHz
  kObs1Deg, kObs2Deg,                                 // 0..360 deg, magnetic
  kCount
};
constexpr int kChannelCount = static_cast<int>(Channel::kCount);

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

/// A sensible cockpit at rest: controls centred, mixture and propeller full forward, gear down.
ControlInputs default_controls();

}  // namespace fedsim::io
