#include "flight/model/scenario/reposition.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::flight {

Runway runway_of(const RunwayEnd& end) {
  Runway r;
  r.threshold.lat_rad = end.threshold_lat_rad;
  r.threshold.lon_rad = end.threshold_lon_rad;
  r.threshold.alt_m = end.elevation_m;
  r.heading_rad = end.heading_rad;
  return r;
}

TrimResult reposition_to_point(AircraftModel& model, const GeodeticPosition& position,
                               double heading_rad, double tas_mps) {
  TrimRequest request;
  request.kind = TrimKind::kLevel;
  request.position = position;
  request.heading_rad = heading_rad;
  request.airspeed_mps = tas_mps;
  request.controls = model.controls();
  return Trim(model).solve(request);
}

TrimResult reposition_to_runway(AircraftModel& model, const Runway& runway, double throttle) {
  if (!(throttle >= 0.0 && throttle <= 1.0)) {
    throw std::invalid_argument("reposition to runway: throttle must be a number within 0..1 (got " +
                                std::to_string(throttle) + ")");
  }
  model.set_runway_elevation_m(runway.threshold.alt_m);
  TrimRequest request;
  request.kind = TrimKind::kGround;
  request.ground_throttle = throttle;
  request.position = runway.threshold;
  request.heading_rad = runway.heading_rad;
  request.controls = model.controls();
  request.controls.gear_down = true;
  return Trim(model).solve(request);
}

TrimResult reposition_to_approach_gate(AircraftModel& model, const Runway& runway,
                                       double distance_m, double tas_mps, double glide_path_rad) {
  // The gate lies distance_m back along the centreline (geodesic, WGS-84), on the glide path
  // through the 50 ft threshold crossing height (ICAO Annex 14 / PANS-OPS reference datum).
  constexpr double kThresholdCrossingHeightM = 50.0 * units::kFtToM;
  double lat_deg = 0.0, lon_deg = 0.0;
  const double back_azimuth_deg = runway.heading_rad * units::kRadToDeg + 180.0;
  GeographicLib::Geodesic::WGS84().Direct(runway.threshold.lat_rad * units::kRadToDeg,
                                          runway.threshold.lon_rad * units::kRadToDeg,
                                          back_azimuth_deg, distance_m, lat_deg, lon_deg);
  model.set_runway_elevation_m(runway.threshold.alt_m);
  TrimRequest request;
  request.kind = TrimKind::kClimb;
  request.position.lat_rad = lat_deg * units::kDegToRad;
  request.position.lon_rad = lon_deg * units::kDegToRad;
  request.position.alt_m =
      runway.threshold.alt_m + kThresholdCrossingHeightM + distance_m * std::tan(glide_path_rad);
  request.heading_rad = runway.heading_rad;
  request.airspeed_mps = tas_mps;
  request.flight_path_rad = -glide_path_rad;
  request.controls = model.controls();
  return Trim(model).solve(request);
}

}  // namespace fedsim::flight
