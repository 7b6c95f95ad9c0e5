// San Francisco International (KSFO) runway ends as OurAirports' runways.csv gives them
// (/work/shared/reference/ourairports/runways.csv, rows 240769-240772; data/nav/ourairports in
// the repository), turned into nav::RunwayEndRecords the way common/navdb does: the threshold
// is the runway end moved along the geodesic towards the opposite end by the displaced
// threshold, the heading the geodesic azimuth to the opposite end (GeographicLib).
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <string>
#include <vector>

namespace fedsim::visual::test {

struct RunwayCsvRow {  // one row of runways.csv, its units
  const char* airport;
  double length_ft, width_ft;
  const char* surface;
  bool lighted, closed;
  const char* le_ident;
  double le_lat_deg, le_lon_deg, le_elevation_ft, le_displaced_ft;
  const char* he_ident;
  double he_lat_deg, he_lon_deg, he_elevation_ft, he_displaced_ft;
};

inline nav::RunwayEndRecord end_record(const RunwayCsvRow& row, bool low_end) {
  using units::kDegToRad;
  using units::kFtToM;
  const double lat = low_end ? row.le_lat_deg : row.he_lat_deg;
  const double lon = low_end ? row.le_lon_deg : row.he_lon_deg;
  const double other_lat = low_end ? row.he_lat_deg : row.le_lat_deg;
  const double other_lon = low_end ? row.he_lon_deg : row.le_lon_deg;
  const double elevation_m = (low_end ? row.le_elevation_ft : row.he_elevation_ft) * kFtToM;
  const double displaced_m = (low_end ? row.le_displaced_ft : row.he_displaced_ft) * kFtToM;
  const auto& earth = GeographicLib::Geodesic::WGS84();
  double distance_m = 0.0, azimuth_deg = 0.0, azimuth2_deg = 0.0;
  earth.Inverse(lat, lon, other_lat, other_lon, distance_m, azimuth_deg, azimuth2_deg);
  double thr_lat = lat, thr_lon = lon;
  earth.Direct(lat, lon, azimuth_deg, displaced_m, thr_lat, thr_lon);

  nav::RunwayEndRecord r;
  r.airport = row.airport;
  r.runway = low_end ? row.le_ident : row.he_ident;
  r.threshold = {thr_lat * kDegToRad, thr_lon * kDegToRad, elevation_m};
  r.end = {lat * kDegToRad, lon * kDegToRad, elevation_m};
  r.heading_true_rad = (azimuth_deg < 0.0 ? azimuth_deg + 360.0 : azimuth_deg) * kDegToRad;
  r.length_m = row.length_ft * kFtToM;
  r.width_m = row.width_ft * kFtToM;
  r.displaced_threshold_m = displaced_m;
  r.surface = row.surface;
  r.lighted = row.lighted;
  r.closed = row.closed;
  r.elevation_known = true;
  return r;
}

inline std::vector<nav::RunwayEndRecord> ksfo_runway_ends() {
  // clang-format off
  static const RunwayCsvRow rows[] = {
      // airport length width surface lighted closed | low end: ident lat lon elev_ft disp_ft |
      // high end: ident lat lon elev_ft disp_ft
      {"KSFO", 11870, 200, "ASP", true, false,
       "10L", 37.628742, -122.39341, 5, 0, "28R", 37.613538, -122.35716, 13, 300},
      {"KSFO", 11381, 200, "ASP", true, false,
       "10R", 37.626298, -122.393124, 6, 0, "28L", 37.61172, -122.358367, 13, 300},
      {"KSFO", 7650, 200, "ASP", true, false,
       "1L", 37.607898, -122.38295, 10, 645, "19R", 37.626476, -122.37063, 9, 0},
      {"KSFO", 8660, 200, "ASP", true, false,
       "1R", 37.606333, -122.381061, 12, 560, "19L", 37.627346, -122.367124, 10, 0},
  };
  // clang-format on
  std::vector<nav::RunwayEndRecord> ends;
  for (const auto& row : rows) {
    ends.push_back(end_record(row, true));
    ends.push_back(end_record(row, false));
  }
  return ends;
}

}  // namespace fedsim::visual::test
