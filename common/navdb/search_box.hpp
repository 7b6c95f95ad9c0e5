// The latitude/longitude boxes that hold every point within a geodesic distance of a centre on
// the WGS-84 ellipsoid: the R*Tree's coarse search (navaids_rtree, degrees) before the exact
// geodesic filter.
//
// Bounds, rigorous for any radius (an arc element ds >= M(lat)|dlat| and ds >= p(lat)|dlon|,
// with M the meridian radius of curvature and p = N cos(lat) the radius of the parallel, and
// every point of the geodesic to a point within r is itself within r of the centre):
//   |dlat| <= r / M_min,  M_min = a (1 - e^2) (the meridian radius at the equator);
//   |dlon| <= r / p(lat_far), lat_far the band's latitude nearest a pole.
// A band that reaches a pole takes every longitude; a box that crosses the antimeridian
// (+-180 deg) is split in two.
#pragma once

#include <array>
#include <cstddef>

namespace fedsim::nav {

struct LatLonBox {
  double min_lat_deg = 0.0;
  double max_lat_deg = 0.0;
  double min_lon_deg = 0.0;  // -180 <= min <= max <= 180
  double max_lon_deg = 0.0;
};

struct SearchBoxes {
  std::array<LatLonBox, 2> boxes{};
  std::size_t count = 0;  // 1, or 2 when the search crosses the antimeridian
};

/// The largest search radius [m]: half the meridian (any point of the earth is within it).
inline constexpr double kMaxSearchRadiusM = 20.1e6;

/// The boxes holding every point within radius_m of (lat_rad, lon_rad). Throws
/// std::invalid_argument for a non-finite value, latitude outside [-pi/2, pi/2], longitude
/// outside [-pi, pi] or a radius outside [0, kMaxSearchRadiusM].
SearchBoxes search_boxes(double lat_rad, double lon_rad, double radius_m);

/// Checks a query position and radius as search_boxes does (the message names `what`).
void check_position(double lat_rad, double lon_rad, const char* what);

}  // namespace fedsim::nav
