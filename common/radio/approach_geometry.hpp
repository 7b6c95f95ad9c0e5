// The geometry of one ILS approach that the localizer, glide-slope and marker receivers share.
//
// The course line is the geodesic that leaves the localizer antenna at azimuth
// course_true_rad + pi, i.e. course_true_rad is taken as the inbound course where it ends, at the
// antenna (on a 4 km runway at mid-latitude it differs from the course at the threshold by
// ~0.03 deg, far inside the Cat I alignment tolerance of +-10.5 m at the threshold, ICAO Annex 10
// Vol I 3.1.3.6.1).
//
// Course width (full scale to full scale, DDM 0.155 each side): course_width_rad when the record
// gives one, else the rule of data/nav ILS_SCHEMA: tailored to 700 ft (213.36 m) at the
// threshold, i.e. a half-width of atan(106.68 m / D) for D the localizer-to-threshold distance,
// limited to 6 deg (FAA AIM 1-1-9 b; ICAO Annex 10 Vol I 3.1.3.7.1's displacement sensitivity
// of 0.00145 DDM/m at the threshold puts DDM 0.155 at 106.9 m: the same to 0.2%).
//
// Course coordinates of a point: in the local horizontal plane (NED) at the localizer antenna,
// `along_m` from the antenna towards the approach (+ on the approach side), `left_m` to the left
// of an aircraft flying the inbound course. Over the 10-25 NM of an ILS the tangent-plane
// distances differ from geodesic ones by parts in 10^6; heights are not taken from this plane.
#pragma once

#include "common/navdb/nav_records.hpp"

namespace fedsim::radio {

inline constexpr double kLocalizerFullScaleDdm = 0.155;   // ICAO Annex 10 Vol I 3.1.3.7.1
inline constexpr double kGlideSlopeFullScaleDdm = 0.175;  // 2 x 0.0875 (ICAO 3.1.5.6.2)

struct CourseCoordinates {
  double along_m = 0.0;  // from the localizer antenna towards the approach [m]
  double left_m = 0.0;   // left of the inbound course [m]
};

struct ApproachGeometry {
  double inbound_course_true_rad = 0.0;   // [0, 2 pi)
  double localizer_back_azimuth_rad = 0.0;  // azimuth at the antenna towards the approach
  double localizer_to_threshold_m = 0.0;  // geodesic [m]
  double course_half_width_rad = 0.0;     // angle off course for DDM 0.155 [rad]
  double glide_slope_along_m = 0.0;       // abeam point of the glide-slope antenna [m]
  double threshold_along_m = 0.0;         // the threshold on the course line [m]
};

/// Checks the record (throws std::invalid_argument on a bad one) and derives its geometry.
ApproachGeometry approach_geometry(const nav::IlsApproach& approach);

/// Course coordinates of a point (latitude, longitude [rad]) for `approach`.
CourseCoordinates course_coordinates(const nav::IlsApproach& approach,
                                     const ApproachGeometry& geometry, double lat_rad,
                                     double lon_rad);

}  // namespace fedsim::radio
