// ILS glide-slope receiver (seed 6.8).
//
// Inputs: the IlsApproach record and the aircraft pose. Outputs (GlideSlopeReading):
//   elevation angle: of the aircraft above the glide-slope antenna's local horizontal plane
//     (ECEF -> NED at the antenna; the image-type glide path is the cone of constant elevation
//     about the antenna's vertical);
//   DDM = 0.0875 x (elevation - theta) / (0.12 theta), theta the glide path angle, signed +
//     where the 90 Hz tone predominates, i.e. above the path: the nominal angular displacement
//     sensitivity of ICAO Annex 10 Vol I 3.1.5.6 (DDM 0.0875 at 0.12 theta, the Cat II/III value
//     and the nominal Cat I value within its 0.07-0.14 theta range);
//   deviation = -DDM / 0.175 (full scale 150 uA at DDM 0.175, i.e. at +-0.24 theta = +-0.72 deg
//     for a 3 deg path), clamped to -1..1, + = fly up (aircraft below the path);
//   valid only inside the coverage of ICAO Annex 10 Vol I 3.1.5.3.1: within 8 deg in azimuth
//     each side of the course, measured from the course line's point abeam the antenna, to
//     10 NM from the antenna, between 0.45 theta and 1.75 theta above the horizontal, and in the
//     VHF/UHF line of sight. This main-lobe sector contains no false glide paths (the false
//     paths of an image array lie near 2 theta, 3 theta, above 1.75 theta), so none are modelled.
//     Past the abeam point (over the runway beyond the antenna) the status is kBehindAntenna.
// Per-frame inputs: a bad pose gives kInvalidInput; a bad record throws std::invalid_argument.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/signal_status.hpp"

#include <string>

namespace fedsim::radio {

struct GlideSlopeReading {
  SignalStatus status = SignalStatus::kNoStation;
  std::string ident;
  double elevation_angle_rad = 0.0;      // above the antenna's horizontal [rad]
  double glide_path_angle_rad = 0.0;     // theta [rad]
  double ddm = 0.0;                      // + = 90 Hz predominant = above the path [-]
  double deviation = 0.0;                // -1..1 full scale, + = fly up [-]
  double distance_from_antenna_m = 0.0;  // geodesic [m]
  bool valid() const { return status == SignalStatus::kValid; }
};

class GlideSlopeReceiver {
 public:
  GlideSlopeReading read(const nav::IlsApproach& approach, const AircraftPose& pose) const;
};

}  // namespace fedsim::radio
