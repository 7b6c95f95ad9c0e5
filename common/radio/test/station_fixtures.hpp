// Station records for the radio tests, from OurAirports (navaids.csv and runways.csv as of the
// copy in shared/reference/ourairports; row ids given) converted to SI here, and helpers that place
// the aircraft with GeographicLib directly (the reference the receivers are checked against).
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <string>

namespace fedsim::radio::test {

using namespace fedsim::nav;  // the station records (common/navdb)

constexpr double kDeg = units::kDegToRad;
constexpr double kFt = units::kFtToM;
constexpr double kNm = units::kNmToM;

inline GeoPoint point_deg(double lat_deg, double lon_deg, double elevation_m) {
  return {lat_deg * kDeg, lon_deg * kDeg, elevation_m};
}

inline Navaid navaid(std::int64_t id, std::string ident, NavaidType type, std::uint32_t khz,
                     double lat_deg, double lon_deg, double elevation_ft, double slaved_deg,
                     double magnetic_deg, UsageType usage, PowerClass power) {
  Navaid n;
  n.id = id;
  n.ident = std::move(ident);
  n.name = n.ident;
  n.type = type;
  n.frequency_khz = khz;
  n.position = point_deg(lat_deg, lon_deg, elevation_ft * kFt);
  n.elevation_known = true;
  n.magnetic_variation_rad = magnetic_deg * kDeg;
  n.slaved_variation_rad = slaved_deg * kDeg;
  n.slaved_variation_known = true;
  n.usage = usage;
  n.power = power;
  return n;
}

// 93531 San_Francisco_VOR-DME_US: 115.80 MHz, 105X, 13 ft, slaved 17.001 E, variation 14.423 E.
inline Navaid sfo_vor_dme() {
  return navaid(93531, "SFO", NavaidType::kVorDme, 115800, 37.61949920654297, -122.3740005493164,
                13, 17.001, 14.423, UsageType::kBoth, PowerClass::kMedium);
}
// 91839 Oakland_VORTAC_US: 116.80 MHz, 10 ft.
inline Navaid oak_vortac() {
  return navaid(91839, "OAK", NavaidType::kVortac, 116800, 37.72589874267578, -122.2239990234375,
                10, 17.001, 14.426, UsageType::kBoth, PowerClass::kHigh);
}
// 93393 Sauveterre_VOR_FR: 116.80 MHz too (co-channel with OAK), 385 ft.
inline Navaid sau_vor_france() {
  return navaid(93393, "SAU", NavaidType::kVor, 116800, 44.67679977416992, -0.15291699767112732,
                385, -3.007, -1.287, UsageType::kBoth, PowerClass::kHigh);
}
// 93647 San_Jose_VOR-DME_US: usage LO.
inline Navaid sjc_vor_dme() {
  return navaid(93647, "SJC", NavaidType::kVorDme, 114100, 37.374698638916016, -121.94499969482422,
                43, 16.001, 14.345, UsageType::kLow, PowerClass::kMedium);
}
// 93518 Brijj_NDB_US "SF": 379 kHz, 11 ft, TERMINAL LOW (a compass locator), KSFO.
inline Navaid brijj_ndb() {
  Navaid n = navaid(93518, "SF", NavaidType::kNdb, 379, 37.572200775146484, -122.26000213623047,
                    11, 0.0, 14.405, UsageType::kTerminal, PowerClass::kLow);
  n.slaved_variation_known = false;
  return n;
}
// 86637 Kanan_NDB_US "CC": 335 kHz, 5 ft, TERMINAL LOW.
inline Navaid kanan_ndb() {
  Navaid n = navaid(86637, "CC", NavaidType::kNdb, 335, 38.0463981628418, -122.03299713134766, 5,
                    0.0, 14.46, UsageType::kTerminal, PowerClass::kLow);
  n.slaved_variation_known = false;
  return n;
}
// 90615 Reiga_NDB_US "LV": 374 kHz, LO LOW (MH class).
inline Navaid reiga_ndb() {
  Navaid n = navaid(90615, "LV", NavaidType::kNdb, 374, 37.69219970703125, -121.68399810791016,
                    683, 0.0, 14.371, UsageType::kLow, PowerClass::kLow);
  n.slaved_variation_known = false;
  return n;
}

inline const GeographicLib::Geodesic& geodesic() { return GeographicLib::Geodesic::WGS84(); }

/// The point `distance_m` from `from` along the geodesic leaving it at `azimuth_deg`; the
/// forward azimuth there [deg] in `azimuth_out_deg` when given.
inline GeoPoint direct(const GeoPoint& from, double azimuth_deg, double distance_m,
                       double elevation_m, double* azimuth_out_deg = nullptr) {
  double lat2 = 0.0, lon2 = 0.0, azi2 = 0.0;
  geodesic().Direct(from.lat_rad / kDeg, from.lon_rad / kDeg, azimuth_deg, distance_m, lat2, lon2,
                    azi2);
  if (azimuth_out_deg != nullptr) *azimuth_out_deg = azi2;
  return point_deg(lat2, lon2, elevation_m);
}

struct Inverse {
  double distance_m, azimuth1_deg, azimuth2_deg;
};
inline Inverse inverse(const GeoPoint& a, const GeoPoint& b) {
  Inverse out{};
  geodesic().Inverse(a.lat_rad / kDeg, a.lon_rad / kDeg, b.lat_rad / kDeg, b.lon_rad / kDeg,
                     out.distance_m, out.azimuth1_deg, out.azimuth2_deg);
  return out;
}

/// Gaussian radius of curvature sqrt(M N) of WGS-84 at a latitude: the local sphere.
inline double local_sphere_radius_m(double lat_rad) {
  const double f = GeographicLib::Constants::WGS84_f();
  const double e2 = f * (2 - f);
  const double w = 1.0 - e2 * std::sin(lat_rad) * std::sin(lat_rad);
  return GeographicLib::Constants::WGS84_a() * std::sqrt(1.0 - e2) / w;
}

/// Straight-line distance between points at heights h1, h2 a ground distance s apart on a sphere
/// of radius r (law of cosines).
inline double spherical_slant_range_m(double s_m, double h1_m, double h2_m, double r_m) {
  const double r1 = r_m + h1_m;
  const double r2 = r_m + h2_m;
  return std::sqrt(r1 * r1 + r2 * r2 - 2 * r1 * r2 * std::cos(s_m / r_m));
}

inline AircraftPose pose_at(const GeoPoint& where, double altitude_msl_m,
                            double heading_true_deg = 0.0, double airspeed_mps = 60.0) {
  AircraftPose pose;
  pose.lat_rad = where.lat_rad;
  pose.lon_rad = where.lon_rad;
  pose.altitude_msl_m = altitude_msl_m;
  pose.heading_true_rad = heading_true_deg * kDeg;
  pose.true_airspeed_mps = airspeed_mps;
  return pose;
}

/// KSFO runway 28R as an ILS record built from OurAirports runways.csv row 240772: the 28R end
/// 37.613538 N 122.35716 W, 13 ft, threshold displaced 300 ft; the opposite (10L) end 37.628742 N
/// 122.39341 W, 5 ft. By the rules of ILS_SCHEMA: the localizer on the extended centreline
/// 1,000 ft beyond the 10L end at its elevation; a 3.00 deg glide path with a 50 ft TCH, the
/// glide-slope antenna abeam the point TCH / tan(3 deg) past the threshold, 400 ft left of the
/// landing direction, at threshold elevation; course width by rule. Markers at typical sites
/// (AIM 1-1-9 e: outer 4-7 NM, middle ~3,500 ft, inner between the middle marker and the
/// threshold): 5 NM, 3,500 ft and 1,000 ft. Ident and frequency are illustrative.
inline IlsApproach ksfo_28r() {
  const GeoPoint end_28r = point_deg(37.613538, -122.35716, 13 * kFt);
  const GeoPoint end_10l = point_deg(37.628742, -122.39341, 5 * kFt);
  const Inverse runway = inverse(end_28r, end_10l);
  IlsApproach ils;
  ils.airport = "KSFO";
  ils.runway = "28R";
  ils.ident = "ISFO";
  ils.frequency_khz = 109550;
  ils.glide_path_angle_rad = 3.0 * kDeg;
  ils.threshold_crossing_height_m = 50 * kFt;
  double threshold_azimuth_deg = 0.0;
  ils.threshold = direct(end_28r, runway.azimuth1_deg, 300 * kFt, 13 * kFt, &threshold_azimuth_deg);
  double localizer_azimuth_deg = 0.0;
  ils.localizer = direct(end_28r, runway.azimuth1_deg, runway.distance_m + 1000 * kFt, 5 * kFt,
                         &localizer_azimuth_deg);
  ils.course_true_rad = localizer_azimuth_deg * kDeg;  // inbound course at the antenna
  ils.magnetic_variation_rad = 14.0 * kDeg;
  double abeam_azimuth_deg = 0.0;
  const GeoPoint abeam =
      direct(ils.threshold, threshold_azimuth_deg,
             ils.threshold_crossing_height_m / std::tan(ils.glide_path_angle_rad), 13 * kFt,
             &abeam_azimuth_deg);
  ils.glide_slope = direct(abeam, abeam_azimuth_deg - 90.0, 400 * kFt, 13 * kFt);
  ils.outer_marker_distance_m = 5.0 * kNm;
  ils.middle_marker_distance_m = 3500 * kFt;
  ils.inner_marker_distance_m = 1000 * kFt;
  ils.has_dme = true;
  ils.source = "test fixture from OurAirports runways.csv 240772";
  return ils;
}

/// A point on the approach side of the course line, `distance_m` from the localizer antenna
/// along the geodesic whose azimuth there is the back course plus `offset_deg` (+ = left of the
/// inbound course).
inline GeoPoint from_localizer(const IlsApproach& ils, double distance_m, double offset_deg) {
  return direct(ils.localizer, ils.course_true_rad / kDeg + 180.0 + offset_deg, distance_m, 0.0);
}

/// A pose at elevation angle `elevation_rad` above the glide-slope antenna's horizontal plane,
/// horizontally above `where` (within the antenna's tangent plane), via GeographicLib's
/// LocalCartesian.
inline AircraftPose at_elevation_from_glide_slope(const IlsApproach& ils, const GeoPoint& where,
                                                  double elevation_rad) {
  const GeoPoint& gs = ils.glide_slope;
  const GeographicLib::LocalCartesian frame(gs.lat_rad / kDeg, gs.lon_rad / kDeg, gs.elevation_m);
  double x = 0.0, y = 0.0, z = 0.0;
  frame.Forward(where.lat_rad / kDeg, where.lon_rad / kDeg, gs.elevation_m, x, y, z);
  const double up_m = std::hypot(x, y) * std::tan(elevation_rad);
  double lat = 0.0, lon = 0.0, h = 0.0;
  frame.Reverse(x, y, up_m, lat, lon, h);
  return pose_at(point_deg(lat, lon, 0.0), h, ils.course_true_rad / kDeg);
}

// 10 NM south-east of the SFO VOR at 6000 ft, heading 300: in range of the Bay Area's stations.
inline AircraftPose near_bay_area() {
  return pose_at(direct(sfo_vor_dme().position, 135, 10 * kNm, 0), 6000 * kFt, 300);
}

}  // namespace fedsim::radio::test
