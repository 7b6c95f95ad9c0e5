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

namespace {
void require_within(double value, double lo, double hi, const char* field) {
  if (!(value >= lo && value <= hi)) {  // NaN fails both
    throw std::invalid_argument(std::string("intercept start: ") + field + " must be within " +
                                std::to_string(lo) + ".." + std::to_string(hi) + " (got " +
                                std::to_string(value) + ")");
  }
}
}  // namespace

TrimResult reposition_to_intercept(AircraftModel& model, const Runway& runway, const InterceptStart& s) {
  require_within(s.distance_m, 0.0, 100000.0, "distance_m");
  require_within(s.left_m, -20000.0, 20000.0, "left_m");
  require_within(s.intercept_rad, 0.0, units::kHalfPi, "intercept_rad");
  require_within(s.altitude_msl_m, runway.threshold.alt_m + 30.0, 20000.0, "altitude_msl_m (30 m above the runway at least)");
  require_within(s.airspeed_mps, 1.0, 400.0, "airspeed_mps");
  const auto& geodesic = GeographicLib::Geodesic::WGS84();
  const double runway_heading_deg = runway.heading_rad * units::kRadToDeg;
  double lat_deg = 0.0, lon_deg = 0.0, on_line_lat = 0.0, on_line_lon = 0.0;
  geodesic.Direct(runway.threshold.lat_rad * units::kRadToDeg, runway.threshold.lon_rad * units::kRadToDeg,
                  runway_heading_deg + 180.0, s.distance_m, on_line_lat, on_line_lon);
  // Left of the landing direction is its heading minus 90 deg.
  geodesic.Direct(on_line_lat, on_line_lon, runway_heading_deg - 90.0, s.left_m, lat_deg, lon_deg);
  // Flying the landing direction from the left of the centreline, the centreline lies to the
  // right: the intercept heading is the runway heading plus the intercept angle; from the
  // right, minus.
  const double towards_centreline = s.left_m >= 0.0 ? 1.0 : -1.0;
  model.set_runway_elevation_m(runway.threshold.alt_m);
  TrimRequest request;
  request.kind = TrimKind::kLevel;
  request.position = {lat_deg * units::kDegToRad, lon_deg * units::kDegToRad, s.altitude_msl_m};
  request.heading_rad = runway.heading_rad + towards_centreline * s.intercept_rad;
  request.airspeed_mps = s.airspeed_mps;
  request.airspeed_is_cas = s.airspeed_is_cas;
  request.controls = model.controls();
  return Trim(model).solve(request);
}

}  // namespace fedsim::flight
