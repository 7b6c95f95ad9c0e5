// Why a radio-navigation reading is or is not usable. Every receiver output carries one; a reading
// whose status is not kValid has its numerical fields zeroed and is to be shown flagged (OFF flag,
// no needle, dashes): the receivers never give a wrong reading marked valid.
#pragma once

#include <cstdint>
#include <string_view>

namespace fedsim::radio {

enum class SignalStatus : std::uint8_t {
  kValid,
  kInvalidInput,        // a per-frame input (pose, OBS, selected value) was not finite or out of range
  kNotTuned,            // the frequency is outside the receiver's band (or 0)
  kNoStation,           // no station of the receiver's kind on the tuned frequency
  kReceiverFailed,      // the airborne receiver is failed (instructor failure)
  kStationOffAir,       // the ground station (or this component of it) is off the air
  kOutOfServiceVolume,  // beyond the station's service volume (FAA AIM 1-1-8)
  kBelowRadioHorizon,   // VHF/UHF path blocked by the earth's curvature (4/3-earth radio horizon)
  kConeOfConfusion,     // VOR: too steeply above the station for a usable bearing
  kOutsideCoverage,     // ILS: outside the localizer / glide-slope / marker coverage sector
  kBehindAntenna,       // ILS: past the localizer antenna (back course, not modelled) or the glide slope
};

/// Lower-case name for logs and tests, e.g. "below_radio_horizon".
std::string_view to_string(SignalStatus status);

}  // namespace fedsim::radio
