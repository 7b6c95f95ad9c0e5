// ILS localizer receiver (seed 6.8).
//
// Inputs: the IlsApproach record and the aircraft pose. Outputs (LocalizerReading):
//   angle off course: the geodesic azimuth at the localizer antenna towards the aircraft minus
//     the azimuth of the course line there (approach_geometry.hpp), + = aircraft left of the
//     inbound course;
//   DDM = 0.155 x angle / half course width, signed + where the 90 Hz tone predominates, which is
//     the left of the course seen from an approaching aircraft (ICAO Annex 10 Vol I 3.1.3.5),
//     i.e. + = fly right; the DDM grows linearly in the course sector and beyond it the
//     clearance signal keeps it at or above full scale (3.1.3.7): the model keeps it linear;
//   deviation = DDM / 0.155 (full scale, 150 uA on a standard indicator), clamped to -1..1,
//     + = fly right ("+ = fly right" in idl/navigation.idl);
//   valid only in front of the antenna and inside the coverage of FAA AIM 1-1-9 b (ICAO Annex 10
//     Vol I 3.1.3.3.1's reduced limits): within 10 deg of the course to 18 NM and within 35 deg
//     to 10 NM from the antenna, below the higher of 4,500 ft above the antenna (AIM) and the
//     surface rising at 7 deg from it (ICAO Annex 10 Vol I 3.1.3.3.2), and within the VHF line
//     of sight; beyond 90 deg from the front course the aircraft is behind the antenna
//     (kBehindAntenna: the back course is not modelled), between 35 and 90 deg kOutsideCoverage.
// Per-frame inputs: a bad pose gives kInvalidInput; a bad record throws std::invalid_argument.
// False courses and multipath bends are not modelled.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/signal_status.hpp"

#include <string>

namespace fedsim::radio {

struct LocalizerReading {
  SignalStatus status = SignalStatus::kNoStation;
  std::string ident;
  double angle_off_course_rad = 0.0;     // at the antenna, + = left of course [rad]
  double ddm = 0.0;                      // + = 90 Hz predominant = fly right [-]
  double deviation = 0.0;                // -1..1 full scale, + = fly right [-]
  double course_true_rad = 0.0;          // inbound front course, true, [0, 2 pi)
  double course_half_width_rad = 0.0;    // angle for full scale [rad]
  double bearing_to_antenna_true_rad = 0.0;  // at the aircraft, [0, 2 pi)
  double distance_from_antenna_m = 0.0;  // geodesic [m]
  bool valid() const { return status == SignalStatus::kValid; }
};

class LocalizerReceiver {
 public:
  LocalizerReading read(const nav::IlsApproach& approach, const AircraftPose& pose) const;
};

}  // namespace fedsim::radio
