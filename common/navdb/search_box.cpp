#include "common/navdb/search_box.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

// A little slack on every bound (far above double rounding, far below any station spacing).
constexpr double kMarginDeg = 1e-7;

double parallel_radius_m(double lat_rad) {
  const double s = std::sin(lat_rad);
  const double n = wgs84::kSemiMajorAxisM / std::sqrt(1.0 - wgs84::kEccentricitySquared * s * s);
  return n * std::cos(lat_rad);
}

}  // namespace

void check_position(double lat_rad, double lon_rad, const char* what) {
  if (!std::isfinite(lat_rad) || !std::isfinite(lon_rad)) {
    throw std::invalid_argument(std::string(what) + ": latitude/longitude not finite");
  }
  if (std::abs(lat_rad) > units::kHalfPi) {
    throw std::invalid_argument(std::string(what) + ": latitude " +
                                std::to_string(lat_rad * units::kRadToDeg) +
                                " deg is outside [-90, 90]");
  }
  if (std::abs(lon_rad) > units::kPi) {
    throw std::invalid_argument(std::string(what) + ": longitude " +
                                std::to_string(lon_rad * units::kRadToDeg) +
                                " deg is outside [-180, 180]");
  }
}

SearchBoxes search_boxes(double lat_rad, double lon_rad, double radius_m) {
  check_position(lat_rad, lon_rad, "search centre");
  if (!std::isfinite(radius_m) || radius_m < 0.0 || radius_m > kMaxSearchRadiusM) {
    throw std::invalid_argument("search radius " + std::to_string(radius_m) +
                                " m is outside [0, " + std::to_string(kMaxSearchRadiusM) + "]");
  }
  const double min_meridian_radius_m =
      wgs84::kSemiMajorAxisM * (1.0 - wgs84::kEccentricitySquared);
  const double dlat_rad = radius_m / min_meridian_radius_m;
  const double lat_lo_rad = lat_rad - dlat_rad;
  const double lat_hi_rad = lat_rad + dlat_rad;

  SearchBoxes result;
  LatLonBox box;
  box.min_lat_deg = std::max(-90.0, lat_lo_rad * units::kRadToDeg - kMarginDeg);
  box.max_lat_deg = std::min(90.0, lat_hi_rad * units::kRadToDeg + kMarginDeg);
  box.min_lon_deg = -180.0;
  box.max_lon_deg = 180.0;
  if (lat_lo_rad <= -units::kHalfPi || lat_hi_rad >= units::kHalfPi) {
    result.boxes[0] = box;  // the band reaches a pole: every longitude
    result.count = 1;
    return result;
  }
  const double lat_far_rad = std::max(std::abs(lat_lo_rad), std::abs(lat_hi_rad));
  const double dlon_deg = radius_m / parallel_radius_m(lat_far_rad) * units::kRadToDeg + kMarginDeg;
  const double lon_deg = lon_rad * units::kRadToDeg;
  if (dlon_deg >= 180.0) {
    result.boxes[0] = box;
    result.count = 1;
    return result;
  }
  const double lo = lon_deg - dlon_deg;
  const double hi = lon_deg + dlon_deg;
  if (lo < -180.0) {
    box.min_lon_deg = lo + 360.0;  // the part east of the antimeridian...
    box.max_lon_deg = 180.0;
    result.boxes[1] = box;
    box.min_lon_deg = -180.0;      // ...and the part west of it
    box.max_lon_deg = hi;
    result.boxes[0] = box;
    result.count = 2;
  } else if (hi > 180.0) {
    box.min_lon_deg = lo;
    box.max_lon_deg = 180.0;
    result.boxes[0] = box;
    box.min_lon_deg = -180.0;
    box.max_lon_deg = hi - 360.0;
    result.boxes[1] = box;
    result.count = 2;
  } else {
    box.min_lon_deg = lo;
    box.max_lon_deg = hi;
    result.boxes[0] = box;
    result.count = 1;
  }
  return result;
}

}  // namespace fedsim::nav
