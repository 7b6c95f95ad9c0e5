#include "common/radio/approach_geometry.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/radio/radio_geometry.hpp"
#include "common/radio/station_checks.hpp"
#include "common/units/units.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace fedsim::radio {

namespace {
constexpr double kTailoredHalfWidthAtThresholdM = 350.0 * units::kFtToM;  // 700 ft sector
constexpr double kMaxHalfWidthRad = 3.0 * units::kDegToRad;              // 6 deg sector
}  // namespace

ApproachGeometry approach_geometry(const nav::IlsApproach& approach) {
  check_approach(approach);
  ApproachGeometry geometry;
  geometry.inbound_course_true_rad = wrap_two_pi(approach.course_true_rad);
  geometry.localizer_back_azimuth_rad = wrap_two_pi(approach.course_true_rad + units::kPi);
  const LinkGeometry to_threshold = link_geometry(approach.localizer, approach.threshold.lat_rad,
                                                  approach.threshold.lon_rad,
                                                  approach.threshold.elevation_m);
  geometry.localizer_to_threshold_m = to_threshold.ground_distance_m;
  geometry.course_half_width_rad =
      approach.course_width_rad > 0.0
          ? 0.5 * approach.course_width_rad
          : std::min(kMaxHalfWidthRad, std::atan2(kTailoredHalfWidthAtThresholdM,
                                                  geometry.localizer_to_threshold_m));
  geometry.glide_slope_along_m =
      course_coordinates(approach, geometry, approach.glide_slope.lat_rad,
                         approach.glide_slope.lon_rad)
          .along_m;
  geometry.threshold_along_m =
      course_coordinates(approach, geometry, approach.threshold.lat_rad,
                         approach.threshold.lon_rad)
          .along_m;
  return geometry;
}

CourseCoordinates course_coordinates(const nav::IlsApproach& approach,
                                     const ApproachGeometry& geometry, double lat_rad,
                                     double lon_rad) {
  const nav::GeoPoint& origin = approach.localizer;
  const Eigen::Vector3d origin_ecef =
      Wgs84::ecef_from_geodetic({origin.lat_rad, origin.lon_rad, origin.elevation_m});
  const Eigen::Vector3d point_ecef =
      Wgs84::ecef_from_geodetic({lat_rad, lon_rad, origin.elevation_m});
  const Eigen::Vector3d offset_ned =
      Wgs84::ned_from_ecef(origin.lat_rad, origin.lon_rad) * (point_ecef - origin_ecef);
  const double b = geometry.localizer_back_azimuth_rad;
  CourseCoordinates coordinates;
  coordinates.along_m = offset_ned.x() * std::cos(b) + offset_ned.y() * std::sin(b);
  coordinates.left_m = -offset_ned.x() * std::sin(b) + offset_ned.y() * std::cos(b);
  return coordinates;
}

}  // namespace fedsim::radio
