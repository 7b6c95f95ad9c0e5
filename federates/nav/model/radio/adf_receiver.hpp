// Automatic direction finder (seed 6.5): the needle's bearing to an NDB relative to the nose.
//
// Inputs: the NDB record (Navaid of type NDB or NDB-DME) and the aircraft pose (position, true
// heading). Outputs (AdfReading): the relative bearing, clockwise from the nose, [0, 2 pi) — the
// geodesic azimuth at the aircraft towards the beacon minus the true heading, measured in the
// horizontal plane (the ADF's dip error in a bank is not modelled, nor quadrantal error, night
// effect or coastal refraction); the true bearing and the ground distance.
// Valid within the NDB's service radius by class (FAA AIM 1-1-8 Table 1-1-2, service_volume.hpp).
// LF/MF ground waves follow the earth's curvature, so no line-of-sight limit applies to NDBs.
// Per-frame inputs: a bad pose gives kInvalidInput; a bad record or one that is not an NDB throws
// std::invalid_argument.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/signal_status.hpp"

#include <string>

namespace fedsim::nav {

struct AdfReading {
  radio::SignalStatus status = radio::SignalStatus::kNoStation;
  std::string ident;
  double relative_bearing_rad = 0.0;         // clockwise from the nose, [0, 2 pi)
  double bearing_to_station_true_rad = 0.0;  // [0, 2 pi)
  double ground_distance_m = 0.0;            // [m]
  bool valid() const { return status == radio::SignalStatus::kValid; }
};

class AdfReceiver {
 public:
  AdfReading read(const Navaid& ndb, const radio::AircraftPose& pose) const;
};

}  // namespace fedsim::nav
