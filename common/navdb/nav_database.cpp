#include "common/navdb/nav_database.hpp"
#include "common/util/build_paths.hpp"

#include "common/navdb/nav_schema.hpp"
#include "common/navdb/nav_types.hpp"
#include "common/navdb/search_box.hpp"
#include "common/navdb/sqlite_connection.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>


namespace fedsim::nav {

namespace {

constexpr std::string_view kNavaidColumns =
    "n.id, n.ident, n.name, n.type, n.frequency_khz, n.lat_deg, n.lon_deg, n.elevation_m, "
    "n.dme_lat_deg, n.dme_lon_deg, n.dme_elevation_m, n.dme_channel, n.magnetic_variation_deg, "
    "n.slaved_variation_deg, n.power, n.usage, n.country, n.airport";
constexpr std::string_view kRunwayColumns =
    "r.airport, r.runway, r.threshold_lat_deg, r.threshold_lon_deg, r.elevation_m, r.end_lat_deg, "
    "r.end_lon_deg, r.heading_true_deg, r.length_m, r.width_m, r.displaced_threshold_m, "
    "r.surface, r.lighted, r.closed";
constexpr std::string_view kIlsColumns =
    "i.airport, i.runway, i.ident, i.frequency_khz, i.course_magnetic_deg, "
    "i.magnetic_variation_deg, i.course_true_deg, i.glide_path_angle_deg, "
    "i.threshold_crossing_height_m, i.course_width_deg, i.localizer_lat_deg, i.localizer_lon_deg, "
    "i.localizer_elevation_m, i.glide_slope_lat_deg, i.glide_slope_lon_deg, "
    "i.glide_slope_elevation_m, i.outer_marker_m, i.middle_marker_m, i.inner_marker_m, i.dme, "
    "i.category, i.derived, i.source, r.threshold_lat_deg, r.threshold_lon_deg, r.elevation_m";

std::string navaid_query(std::string_view where) {
  return "SELECT " + std::string(kNavaidColumns) + " FROM navaids n " + std::string(where);
}
std::string runway_query(std::string_view where) {
  return "SELECT " + std::string(kRunwayColumns) + " FROM runway_ends r " + std::string(where);
}
std::string ils_query(std::string_view where) {
  return "SELECT " + std::string(kIlsColumns) +
         " FROM ils i JOIN runway_ends r ON r.airport = i.airport AND r.runway = i.runway " +
         std::string(where);
}

double rad(double deg) { return deg * units::kDegToRad; }

GeoPoint point(const SqliteStatement& s, int lat, int lon, int elevation) {
  return GeoPoint{rad(s.column_double(lat)), rad(s.column_double(lon)),
                  s.column_is_null(elevation) ? 0.0 : s.column_double(elevation)};
}

template <typename Enum>
Enum parsed_or(std::optional<Enum> value, Enum fallback) {
  return value ? *value : fallback;
}

Navaid navaid_from(const SqliteStatement& s) {
  Navaid n;
  n.id = s.column_int64(0);
  n.ident = s.column_text(1);
  n.name = s.column_text(2);
  n.type = parsed_or(parse_navaid_type(s.column_text(3)), NavaidType::kVor);
  n.frequency_khz = static_cast<std::uint32_t>(s.column_int64(4));
  n.position = point(s, 5, 6, 7);
  n.elevation_known = !s.column_is_null(7);
  if (!s.column_is_null(8)) {
    n.dme = point(s, 8, 9, 10);
    if (s.column_is_null(10)) n.dme->elevation_m = n.position.elevation_m;
  }
  n.dme_channel = s.column_text(11);
  n.magnetic_variation_rad = rad(s.column_double(12));
  n.slaved_variation_known = !s.column_is_null(13);
  n.slaved_variation_rad = n.slaved_variation_known ? rad(s.column_double(13)) : 0.0;
  n.power = parsed_or(parse_power_class(s.column_text(14)), PowerClass::kUnknown);
  n.usage = parsed_or(parse_usage_type(s.column_text(15)), UsageType::kUnknown);
  n.country = s.column_text(16);
  n.airport = s.column_text(17);
  return n;
}

RunwayEndRecord runway_from(const SqliteStatement& s) {
  RunwayEndRecord r;
  r.airport = s.column_text(0);
  r.runway = s.column_text(1);
  r.threshold = point(s, 2, 3, 4);
  r.end = point(s, 5, 6, 4);
  r.elevation_known = !s.column_is_null(4);
  r.heading_true_rad = rad(s.column_double(7));
  r.length_m = s.column_double(8);
  r.width_m = s.column_double(9);
  r.displaced_threshold_m = s.column_double(10);
  r.surface = s.column_text(11);
  r.lighted = s.column_int64(12) != 0;
  r.closed = s.column_int64(13) != 0;
  return r;
}

std::optional<double> optional_column(const SqliteStatement& s, int index) {
  if (s.column_is_null(index)) return std::nullopt;
  return s.column_double(index);
}

IlsApproach ils_from(const SqliteStatement& s) {
  IlsApproach a;
  a.airport = s.column_text(0);
  a.runway = s.column_text(1);
  a.ident = s.column_text(2);
  a.frequency_khz = static_cast<std::uint32_t>(s.column_int64(3));
  a.course_magnetic_rad = rad(s.column_double(4));
  a.magnetic_variation_rad = rad(s.column_double(5));
  a.course_true_rad = rad(s.column_double(6));
  a.glide_path_angle_rad = rad(s.column_double(7));
  a.threshold_crossing_height_m = s.column_double(8);
  a.course_width_rad = s.column_is_null(9) ? 0.0 : rad(s.column_double(9));
  a.localizer = point(s, 10, 11, 12);
  a.glide_slope = point(s, 13, 14, 15);
  a.outer_marker_distance_m = optional_column(s, 16);
  a.middle_marker_distance_m = optional_column(s, 17);
  a.inner_marker_distance_m = optional_column(s, 18);
  a.has_dme = s.column_int64(19) != 0;
  a.category = s.column_text(20);
  a.derived = s.column_text(21);
  a.source = s.column_text(22);
  a.threshold = point(s, 23, 24, 25);
  // A threshold without a published elevation: the glide slope's (sited at threshold level).
  if (s.column_is_null(25)) a.threshold.elevation_m = a.glide_slope.elevation_m;
  return a;
}

template <typename Record, typename From>
std::vector<Record> collect(SqliteStatement& s, From from) {
  std::vector<Record> out;
  while (s.step()) out.push_back(from(s));
  s.reset();
  return out;
}

template <typename Record, typename From>
std::optional<Record> first(SqliteStatement& s, From from) {
  std::optional<Record> out;
  if (s.step()) out = from(s);
  s.reset();
  return out;
}

/// Geodesic distance and true bearing from (lat, lon) [rad] to a point [deg].
void distance_and_bearing(double lat_rad, double lon_rad, double lat2_deg, double lon2_deg,
                          double& distance_m, double& bearing_rad) {
  double azimuth_deg = 0.0, azimuth2_deg = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(lat_rad * units::kRadToDeg, lon_rad * units::kRadToDeg,
                                           lat2_deg, lon2_deg, distance_m, azimuth_deg,
                                           azimuth2_deg);
  if (azimuth_deg < 0.0) azimuth_deg += 360.0;
  bearing_rad = azimuth_deg >= 360.0 ? 0.0 : azimuth_deg * units::kDegToRad;
}

std::uint32_t checked_khz(std::uint32_t khz) {
  if (khz == 0) throw std::invalid_argument("frequency 0 kHz: no station is tuned to it");
  return khz;
}

SqliteConnection open_checked(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::exists(path, error)) {
    throw std::runtime_error(path + ": no such file (build it with fedsim-navdb; the build "
                                    "makes <build>/data/nav.sqlite)");
  }
  if (!fs::is_regular_file(path, error)) throw std::runtime_error(path + ": not a regular file");
  SqliteConnection db = SqliteConnection::open_read_only(path);
  std::vector<std::string> tables;
  try {
    SqliteStatement list(db, "SELECT name FROM sqlite_master WHERE type = 'table'");
    while (list.step()) tables.push_back(list.column_text(0));
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": not an SQLite database (" + e.what() + ")");
  }
  for (const auto table : kRequiredTables) {
    if (std::find(tables.begin(), tables.end(), table) == tables.end()) {
      throw std::runtime_error(path + ": not a fedsim navigation database (no table '" +
                               std::string(table) + "'); build one with fedsim-navdb");
    }
  }
  SqliteStatement version(db, "SELECT value FROM meta WHERE key = 'schema_version'");
  if (!version.step()) {
    throw std::runtime_error(path + ": no schema_version in its meta table; rebuild it with "
                                    "fedsim-navdb");
  }
  const std::string found = version.column_text(0);
  if (found != std::to_string(kSchemaVersion)) {
    throw std::runtime_error(path + ": schema version " + found + ", but this program reads version " +
                             std::to_string(kSchemaVersion) + "; rebuild it with fedsim-navdb");
  }
  return db;
}

}  // namespace

std::string default_database_path() {
  const char* from_environment = std::getenv("FEDSIM_NAVDB");
  if (from_environment && *from_environment) return from_environment;
  return util::navdb_file();
}

struct NavDatabase::Impl {
  explicit Impl(SqliteConnection connection)
      : db(std::move(connection)),
        meta(db, "SELECT value FROM meta WHERE key = ?1"),
        find(db, navaid_query("WHERE n.ident = ?1 ORDER BY n.country, n.id")),
        on_frequency(db, navaid_query("WHERE n.frequency_khz = ?1 ORDER BY n.id")),
        all(db, navaid_query("ORDER BY n.id")),
        within(db, navaid_query("JOIN navaids_rtree t ON t.id = n.id WHERE t.max_lat_deg >= ?1 "
                                "AND t.min_lat_deg <= ?2 AND t.max_lon_deg >= ?3 AND "
                                "t.min_lon_deg <= ?4")),
        airport_runways(db, runway_query("WHERE r.airport = ?1 ORDER BY CAST(r.runway AS INTEGER), r.runway")),
        runway(db, runway_query("WHERE r.airport = ?1 AND r.runway = ?2")),
        ils(db, ils_query("WHERE i.airport = ?1 AND i.runway = ?2")),
        airport_ils(db, ils_query("WHERE i.airport = ?1 ORDER BY i.runway")),
        ils_by_ident(db, ils_query("WHERE i.ident = ?1 ORDER BY i.airport, i.runway")),
        ils_on_frequency(db, ils_query("WHERE i.frequency_khz = ?1 ORDER BY i.airport, i.runway")) {}

  SqliteConnection db;
  SqliteStatement meta, find, on_frequency, all, within, airport_runways, runway, ils, airport_ils,
      ils_by_ident, ils_on_frequency;
};

NavDatabase NavDatabase::open(const std::string& path) {
  return NavDatabase(std::make_unique<Impl>(open_checked(path)));
}

NavDatabase::NavDatabase(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
NavDatabase::NavDatabase(NavDatabase&&) noexcept = default;
NavDatabase& NavDatabase::operator=(NavDatabase&&) noexcept = default;
NavDatabase::~NavDatabase() = default;

const std::string& NavDatabase::path() const { return impl_->db.path(); }

std::string NavDatabase::meta(std::string_view key) const {
  impl_->meta.bind(1, key);
  std::string value;
  if (impl_->meta.step()) value = impl_->meta.column_text(0);
  impl_->meta.reset();
  return value;
}

std::vector<Navaid> NavDatabase::find(std::string_view ident) const {
  impl_->find.bind(1, ident);
  return collect<Navaid>(impl_->find, navaid_from);
}

std::vector<Navaid> NavDatabase::on_frequency(std::uint32_t frequency_khz) const {
  impl_->on_frequency.bind(1, static_cast<std::int64_t>(checked_khz(frequency_khz)));
  return collect<Navaid>(impl_->on_frequency, navaid_from);
}

std::vector<Navaid> NavDatabase::all_navaids() const {
  return collect<Navaid>(impl_->all, navaid_from);
}

std::vector<NavaidHit> NavDatabase::within(double lat_rad, double lon_rad, double radius_m) const {
  const SearchBoxes boxes = search_boxes(lat_rad, lon_rad, radius_m);
  std::vector<NavaidHit> hits;
  SqliteStatement& s = impl_->within;
  for (std::size_t b = 0; b < boxes.count; ++b) {
    const LatLonBox& box = boxes.boxes[b];
    s.bind(1, box.min_lat_deg);
    s.bind(2, box.max_lat_deg);
    s.bind(3, box.min_lon_deg);
    s.bind(4, box.max_lon_deg);
    while (s.step()) {
      NavaidHit hit;
      distance_and_bearing(lat_rad, lon_rad, s.column_double(5), s.column_double(6),
                           hit.distance_m, hit.bearing_true_rad);
      if (hit.distance_m > radius_m) continue;  // in the box, outside the circle
      hit.navaid = navaid_from(s);
      hits.push_back(std::move(hit));
    }
    s.reset();
  }
  // The two boxes of an antimeridian search are disjoint except at +-180 exactly.
  std::sort(hits.begin(), hits.end(), [](const NavaidHit& a, const NavaidHit& b) {
    return a.distance_m != b.distance_m ? a.distance_m < b.distance_m : a.navaid.id < b.navaid.id;
  });
  hits.erase(std::unique(hits.begin(), hits.end(),
                         [](const NavaidHit& a, const NavaidHit& b) {
                           return a.navaid.id == b.navaid.id;
                         }),
             hits.end());
  return hits;
}

std::optional<NavaidHit> NavDatabase::nearest_on_frequency(double lat_rad, double lon_rad,
                                                           std::uint32_t frequency_khz) const {
  check_position(lat_rad, lon_rad, "nearest_on_frequency");
  SqliteStatement& s = impl_->on_frequency;
  s.bind(1, static_cast<std::int64_t>(checked_khz(frequency_khz)));
  std::optional<NavaidHit> best;
  while (s.step()) {
    double distance_m = 0.0, bearing_rad = 0.0;
    distance_and_bearing(lat_rad, lon_rad, s.column_double(5), s.column_double(6), distance_m,
                         bearing_rad);
    if (best && distance_m >= best->distance_m) continue;  // ties: the lower id (ORDER BY id)
    best = NavaidHit{navaid_from(s), distance_m, bearing_rad};
  }
  s.reset();
  return best;
}

std::vector<RunwayEndRecord> NavDatabase::airport_runways(std::string_view airport) const {
  impl_->airport_runways.bind(1, airport);
  return collect<RunwayEndRecord>(impl_->airport_runways, runway_from);
}

std::optional<RunwayEndRecord> NavDatabase::runway(std::string_view airport,
                                                   std::string_view runway) const {
  impl_->runway.bind(1, airport);
  impl_->runway.bind(2, runway);
  return first<RunwayEndRecord>(impl_->runway, runway_from);
}

std::optional<IlsApproach> NavDatabase::ils(std::string_view airport,
                                            std::string_view runway) const {
  impl_->ils.bind(1, airport);
  impl_->ils.bind(2, runway);
  return first<IlsApproach>(impl_->ils, ils_from);
}

std::vector<IlsApproach> NavDatabase::airport_ils(std::string_view airport) const {
  impl_->airport_ils.bind(1, airport);
  return collect<IlsApproach>(impl_->airport_ils, ils_from);
}

std::vector<IlsApproach> NavDatabase::ils_by_ident(std::string_view ident) const {
  impl_->ils_by_ident.bind(1, ident);
  return collect<IlsApproach>(impl_->ils_by_ident, ils_from);
}

std::vector<IlsApproach> NavDatabase::ils_on_frequency(std::uint32_t frequency_khz) const {
  impl_->ils_on_frequency.bind(1, static_cast<std::int64_t>(checked_khz(frequency_khz)));
  return collect<IlsApproach>(impl_->ils_on_frequency, ils_from);
}

}  // namespace fedsim::nav
