// Where the pilot's eye is and how the body is oriented: the input of every channel each frame.
// Position WGS-84 geodetic with the height above the ellipsoid taken as MSL (as fedsim's
// aircraft state gives it); attitude the 3-2-1 Euler angles that take the local NED frame at the
// eye to the body frame (docs/frames.md: psi true heading, theta pitch, phi roll).
#pragma once

#include <string>
#include <string_view>

namespace fedsim::visual {

struct EyePose {
  double lat_rad = 0.0;    // geodetic latitude [rad]
  double lon_rad = 0.0;    // longitude, east positive [rad]
  double alt_msl_m = 0.0;  // height above the WGS-84 ellipsoid, taken as MSL [m]
  double phi_rad = 0.0;    // roll [rad]
  double theta_rad = 0.0;  // pitch [rad]
  double psi_rad = 0.0;    // true heading [rad]
};

/// Throws std::invalid_argument naming the field for a NaN/infinity or a value out of range:
/// latitude +-90 deg, longitude +-180 deg, altitude -1000..100000 m, roll +-180 deg, pitch
/// +-90 deg, heading +-360 deg.
void validate(const EyePose& pose, std::string_view where);

}  // namespace fedsim::visual
