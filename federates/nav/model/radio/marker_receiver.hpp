// 75 MHz marker-beacon receiver (seed 6.8): outer, middle and inner markers of ILS approaches.
//
// Inputs: the ILS approaches whose markers may be overflown (the caller passes those near the
// aircraft, e.g. every ILS of the destination airport), the aircraft pose and the station
// outages. Output (MarkerReading): the beacon overflown, with its lamp colour, tone and keying
// (ICAO Annex 10 Vol I 3.1.7.4-3.1.7.5; FAA AIM 1-1-9 Table 1-1-3):
//   outer  — blue lamp,  400 Hz, two dashes per second;
//   middle — amber lamp, 1300 Hz, alternate dots and dashes;
//   inner  — white lamp, 3000 Hz, six dots per second.
// Beacons: on the extended centreline at the record's distances from the threshold, at the
// threshold's elevation. Each radiates an upward cone about its vertical; the aircraft receives
// it while its horizontal distance from the beacon is at most h tan(alpha), h the height above
// the beacon. The half-angle alpha is chosen per beacon so that along the glide path the
// signal lasts the nominal coverage of ICAO Annex 10 Vol I 3.1.7.3.2 (inner 150 m, middle
// 300 m, outer 600 m, measured on the glide path and localizer course): tan(alpha) = (L / 2) /
// h_gp with h_gp = TCH + d tan(theta) the glide-path height over a beacon d from the threshold.
// For a 3 deg path with the outer marker at 4-7 NM that is a cone of 37-23 deg half-angle; the
// middle and inner markers' cones are wide and low (~65 deg). The real fan patterns are
// elliptical (wider across the course); the circular cone is a simplification.
// If two beacons are received at once the nearer (horizontally) one is reported.
// Failures: a failed receiver gives kReceiverFailed; an ILS off the air, or with its markers off
// the air, contributes none. A bad pose gives kInvalidInput; a bad record throws
// std::invalid_argument. No beacon overhead: kOutsideCoverage.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/signal_status.hpp"
#include "common/radio/station_outages.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace fedsim::nav {

enum class MarkerBeacon : std::uint8_t { kNone, kOuter, kMiddle, kInner };
enum class MarkerLamp : std::uint8_t { kOff, kBlue, kAmber, kWhite };

struct MarkerCode {
  MarkerLamp lamp = MarkerLamp::kOff;
  double tone_hz = 0.0;      // audio modulation [Hz]
  std::string_view keying;   // Morse-like pattern per cycle: "--" (2/s), ".-" (alternating), "......" (6/s)
};

/// The lamp, tone and keying of a beacon (kNone: lamp off, no tone).
MarkerCode marker_code(MarkerBeacon beacon);
/// Nominal coverage along the glide path (ICAO Annex 10 Vol I 3.1.7.3.2) [m]; 0 for kNone.
double marker_coverage_length_m(MarkerBeacon beacon);

struct MarkerReading {
  radio::SignalStatus status = radio::SignalStatus::kNoStation;  // kValid while a beacon is received
  MarkerBeacon beacon = MarkerBeacon::kNone;
  MarkerCode code;
  std::string ident;                 // the ILS the beacon belongs to
  double horizontal_offset_m = 0.0;  // from the beacon [m]
  bool valid() const { return status == radio::SignalStatus::kValid; }
};

class MarkerReceiver {
 public:
  void set_failed(bool failed) { failed_ = failed; }
  bool failed() const { return failed_; }

  MarkerReading read(std::span<const IlsApproach> approaches, const radio::AircraftPose& pose,
                     const radio::StationOutages& outages) const;

 private:
  bool failed_ = false;
};

}  // namespace fedsim::nav
