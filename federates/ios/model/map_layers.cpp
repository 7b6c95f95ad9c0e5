#include "ios/model/map_layers.hpp"

#include "common/navdb/nav_types.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>

namespace fedsim::ios {

namespace {

using nlohmann::json;
using units::kDegToRad;
using units::kRadToDeg;

json point(const nav::GeoPoint& p) {
  return {{"lat_deg", p.lat_rad * kRadToDeg}, {"lon_deg", p.lon_rad * kRadToDeg}};
}

/// The localizer's half sector [rad]: the published width, or the rule that gives 210 m full
/// scale at the threshold (ICAO Annex 10, 3.1.3.7), limited to 3 deg.
double half_sector_rad(const nav::IlsApproach& ils) {
  if (ils.course_width_rad > 0.0) return 0.5 * ils.course_width_rad;
  double distance_m = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(ils.threshold.lat_rad * kRadToDeg, ils.threshold.lon_rad * kRadToDeg,
                                           ils.localizer.lat_rad * kRadToDeg, ils.localizer.lon_rad * kRadToDeg,
                                           distance_m);
  return std::min(std::atan2(105.0, std::max(distance_m, 1.0)), 3.0 * kDegToRad);
}

}  // namespace

std::string map_json(const nav::NavDatabase& db, const std::string& airport, double radius_nm) {
  if (!(radius_nm >= 1.0 && radius_nm <= 200.0)) {
    throw std::invalid_argument("map radius_nm " + std::to_string(radius_nm) + " is outside 1..200");
  }
  const auto runways = db.airport_runways(airport);
  if (runways.empty()) throw std::invalid_argument("no runway of airport '" + airport + "' in the navigation database");
  json out;
  out["airport"] = airport;
  double lat = 0.0, lon = 0.0;
  json rw = json::array();
  for (const auto& r : runways) {
    lat += r.threshold.lat_rad / runways.size();
    lon += r.threshold.lon_rad / runways.size();
    json j = point(r.threshold);
    j["runway"] = r.runway;
    j["end_lat_deg"] = r.end.lat_rad * kRadToDeg;
    j["end_lon_deg"] = r.end.lon_rad * kRadToDeg;
    j["heading_deg"] = r.heading_true_rad * kRadToDeg;
    j["width_m"] = r.width_m;
    j["length_m"] = r.length_m;
    rw.push_back(std::move(j));
  }
  out["runways"] = std::move(rw);
  out["center"] = {{"lat_deg", lat * kRadToDeg}, {"lon_deg", lon * kRadToDeg}};
  json ils = json::array();
  for (const auto& a : db.airport_ils(airport)) {
    ils.push_back({{"runway", a.runway}, {"ident", a.ident}, {"mhz", a.frequency_khz / 1000.0},
                   {"course_deg", a.course_true_rad * kRadToDeg}, {"half_width_deg", half_sector_rad(a) * kRadToDeg},
                   {"glide_path_deg", a.glide_path_angle_rad * kRadToDeg}, {"threshold", point(a.threshold)},
                   {"localizer", point(a.localizer)}});
  }
  out["ils"] = std::move(ils);
  json navaids = json::array();
  for (const auto& hit : db.within(lat, lon, radius_nm * units::kNmToM)) {
    const auto& n = hit.navaid;
    json j = point(n.position);
    j["ident"] = n.ident;
    j["name"] = n.name;
    j["type"] = std::string(nav::navaid_type_name(n.type));
    j["khz"] = n.frequency_khz;
    j["distance_nm"] = hit.distance_m * units::kMToNm;
    navaids.push_back(std::move(j));
  }
  out["navaids"] = std::move(navaids);
  return out.dump();
}

std::optional<ExpectedPosition> expected_position(const nav::NavDatabase& db, const std::string& airport,
                                                  const std::string& runway, double gate_distance_m) {
  const auto r = db.runway(airport, runway);
  if (!r) return std::nullopt;
  if (gate_distance_m <= 0.0) return ExpectedPosition{r->threshold.lat_rad, r->threshold.lon_rad};
  // Back along the approach: the ILS course where there is one, else the runway heading.
  double course_rad = r->heading_true_rad;
  if (const auto ils = db.ils(airport, runway)) course_rad = ils->course_true_rad;
  double lat2 = 0.0, lon2 = 0.0;
  GeographicLib::Geodesic::WGS84().Direct(r->threshold.lat_rad * kRadToDeg, r->threshold.lon_rad * kRadToDeg,
                                          course_rad * kRadToDeg + 180.0, gate_distance_m, lat2, lon2);
  return ExpectedPosition{lat2 * kDegToRad, lon2 * kDegToRad};
}

}  // namespace fedsim::ios
