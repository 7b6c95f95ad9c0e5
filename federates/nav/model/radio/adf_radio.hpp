// ADF radio: tuner and receiver of the automatic direction finder (seed 6.5).
//
// Inputs: the tuned frequency [kHz] and the AircraftPose; the StationSource and StationOutages
// given at construction (held by reference: they must outlive the radio). Output: AdfReading
// of the nearest NDB (NDB, NDB-DME) on the frequency that is on the air and inside its service
// radius (adf_receiver.hpp); when none is, the status of the nearest NDB on the frequency
// (kNoStation when there is none). Failures: set_failed(true) gives kReceiverFailed.
// Per-frame inputs: a frequency outside 190-1750 kHz (the NDB band and the broadcast band an ADF
// also tunes; FAA AIM 1-1-3) gives kNotTuned, a bad pose kInvalidInput. A bad record throws.
#pragma once

#include "common/radio/aircraft_pose.hpp"
#include "common/radio/station_outages.hpp"
#include "common/radio/station_source.hpp"
#include "nav/model/radio/adf_receiver.hpp"

#include <cstdint>

namespace fedsim::nav {

inline constexpr std::uint32_t kAdfBandLowKhz = 190;
inline constexpr std::uint32_t kAdfBandHighKhz = 1750;

class AdfRadio {
 public:
  AdfRadio(const radio::StationSource& source, const radio::StationOutages& outages);

  void set_failed(bool failed) { failed_ = failed; }
  bool failed() const { return failed_; }

  AdfReading receive(std::uint32_t frequency_khz, const radio::AircraftPose& pose) const;

 private:
  const radio::StationSource* source_;
  const radio::StationOutages* outages_;
  AdfReceiver adf_;
  bool failed_ = false;
};

}  // namespace fedsim::nav
