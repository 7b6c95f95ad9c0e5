#include "nav/model/radio/marker_receiver.hpp"

#include "common/radio/radio_geometry.hpp"

#include "common/radio/approach_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace fedsim::nav {

namespace {

// The outer marker is at most about 7 NM (13 km) from the threshold (ICAO Annex 10 Vol I
// 3.1.7.6.2: 7.2 km, +-0.8 km where practicable; some older sites up to 7 NM): beyond 30 km
// from the threshold no beacon of that approach can be heard.
constexpr double kMarkerSearchRadiusM = 30000.0;

struct Candidate {
  MarkerBeacon beacon = MarkerBeacon::kNone;
  double horizontal_offset_m = 0.0;
};

// Whether the aircraft is inside the cone of the beacon `distance_m` from the threshold.
std::optional<double> inside_cone(const IlsApproach& approach, const radio::ApproachGeometry& geometry,
                                  const radio::CourseCoordinates& aircraft, double height_above_m,
                                  MarkerBeacon beacon, double distance_m) {
  if (height_above_m <= 0.0) return std::nullopt;
  const double glide_path_height_m = approach.threshold_crossing_height_m +
                                     distance_m * std::tan(approach.glide_path_angle_rad);
  const double tan_half_angle =
      0.5 * marker_coverage_length_m(beacon) / std::max(glide_path_height_m, 1.0);
  const double beacon_along_m = geometry.threshold_along_m + distance_m;
  const double offset_m = std::hypot(aircraft.along_m - beacon_along_m, aircraft.left_m);
  if (offset_m > height_above_m * tan_half_angle) return std::nullopt;
  return offset_m;
}

void consider(const IlsApproach& approach, const radio::ApproachGeometry& geometry,
              const radio::CourseCoordinates& aircraft, double height_above_m, MarkerBeacon beacon,
              const std::optional<double>& distance_m, Candidate& best) {
  if (!distance_m) return;
  const auto offset = inside_cone(approach, geometry, aircraft, height_above_m, beacon, *distance_m);
  if (!offset) return;
  if (best.beacon == MarkerBeacon::kNone || *offset < best.horizontal_offset_m) {
    best = {beacon, *offset};
  }
}

}  // namespace

MarkerCode marker_code(MarkerBeacon beacon) {
  switch (beacon) {
    case MarkerBeacon::kOuter: return {MarkerLamp::kBlue, 400.0, "--"};
    case MarkerBeacon::kMiddle: return {MarkerLamp::kAmber, 1300.0, ".-"};
    case MarkerBeacon::kInner: return {MarkerLamp::kWhite, 3000.0, "......"};
    case MarkerBeacon::kNone: break;
  }
  return {};
}

double marker_coverage_length_m(MarkerBeacon beacon) {
  switch (beacon) {
    case MarkerBeacon::kOuter: return 600.0;
    case MarkerBeacon::kMiddle: return 300.0;
    case MarkerBeacon::kInner: return 150.0;
    case MarkerBeacon::kNone: break;
  }
  return 0.0;
}

MarkerReading MarkerReceiver::read(std::span<const IlsApproach> approaches,
                                   const radio::AircraftPose& pose, const radio::StationOutages& outages) const {
  MarkerReading reading;
  if (failed_) {
    reading.status = radio::SignalStatus::kReceiverFailed;
    return reading;
  }
  if (!radio::pose_problem(pose).empty()) {
    reading.status = radio::SignalStatus::kInvalidInput;
    return reading;
  }
  const IlsApproach* owner = nullptr;
  Candidate best;
  for (const IlsApproach& approach : approaches) {
    // Markers lie on the approach within a few miles of the threshold: far approaches are
    // skipped without their geometry.
    if (radio::ground_distance_lower_bound_m(approach.threshold, pose.lat_rad, pose.lon_rad) >
        kMarkerSearchRadiusM) {
      continue;
    }
    const radio::ApproachGeometry geometry = radio::approach_geometry(approach);  // checks the record
    if (outages.off_air(approach.ident, radio::StationComponent::kMarkers)) continue;
    const radio::CourseCoordinates at =
        radio::course_coordinates(approach, geometry, pose.lat_rad, pose.lon_rad);
    const double height_m = pose.altitude_msl_m - approach.threshold.elevation_m;
    const Candidate before = best;
    consider(approach, geometry, at, height_m, MarkerBeacon::kOuter,
             approach.outer_marker_distance_m, best);
    consider(approach, geometry, at, height_m, MarkerBeacon::kMiddle,
             approach.middle_marker_distance_m, best);
    consider(approach, geometry, at, height_m, MarkerBeacon::kInner,
             approach.inner_marker_distance_m, best);
    if (best.beacon != before.beacon || best.horizontal_offset_m != before.horizontal_offset_m) {
      owner = &approach;
    }
  }
  if (owner == nullptr) {
    reading.status = radio::SignalStatus::kOutsideCoverage;
    return reading;
  }
  reading.status = radio::SignalStatus::kValid;
  reading.beacon = best.beacon;
  reading.code = marker_code(best.beacon);
  reading.ident = owner->ident;
  reading.horizontal_offset_m = best.horizontal_offset_m;
  return reading;
}

}  // namespace fedsim::nav
