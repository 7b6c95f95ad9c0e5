#include "common/radio/glide_slope_receiver.hpp"

#include "common/radio/approach_geometry.hpp"
#include "common/radio/radio_geometry.hpp"
#include "common/radio/receiver_link.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::radio {

namespace {

constexpr double kHalfSectorRad = 8.0 * units::kDegToRad;
constexpr double kRangeM = 10.0 * units::kNmToM;
constexpr double kLowerEdge = 0.45;        // x theta
constexpr double kUpperEdge = 1.75;        // x theta
constexpr double kHalfFullScale = 0.12;    // x theta for DDM 0.0875

SignalStatus coverage_status(const nav::IlsApproach& approach, const ApproachGeometry& geometry,
                             const LinkGeometry& link, double lat_rad, double lon_rad) {
  const CourseCoordinates at = course_coordinates(approach, geometry, lat_rad, lon_rad);
  const double ahead_of_antenna_m = at.along_m - geometry.glide_slope_along_m;
  if (ahead_of_antenna_m <= 0.0) return SignalStatus::kBehindAntenna;
  if (std::abs(std::atan2(at.left_m, ahead_of_antenna_m)) > kHalfSectorRad ||
      link.ground_distance_m > kRangeM) {
    return SignalStatus::kOutsideCoverage;
  }
  const double theta = approach.glide_path_angle_rad;
  if (link.elevation_angle_rad < kLowerEdge * theta ||
      link.elevation_angle_rad > kUpperEdge * theta) {
    return SignalStatus::kOutsideCoverage;
  }
  return SignalStatus::kValid;
}

}  // namespace

GlideSlopeReading GlideSlopeReceiver::read(const nav::IlsApproach& approach,
                                           const AircraftPose& pose) const {
  const IlsReception reception = ils_reception(approach, approach.glide_slope, pose);
  GlideSlopeReading reading{.status = reception.path.status, .ident = approach.ident};
  if (!reading.valid()) return reading;
  const LinkGeometry& link = reception.path.link;
  reading.status = coverage_status(approach, reception.geometry, link, pose.lat_rad, pose.lon_rad);
  if (!reading.valid()) return reading;
  const double theta = approach.glide_path_angle_rad;
  reading.elevation_angle_rad = link.elevation_angle_rad;
  reading.glide_path_angle_rad = theta;
  reading.ddm = 0.5 * kGlideSlopeFullScaleDdm * (link.elevation_angle_rad - theta) /
                (kHalfFullScale * theta);
  reading.deviation = std::clamp(-reading.ddm / kGlideSlopeFullScaleDdm, -1.0, 1.0);
  reading.distance_from_antenna_m = link.ground_distance_m;
  return reading;
}

}  // namespace fedsim::radio
