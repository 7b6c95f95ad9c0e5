// The navigation database (read side): radio navigation aids, runway ends and ILS approaches
// from the SQLite file fedsim-navdb builds (schema: nav_schema.hpp, docs/navdb.md).
//
// Inputs: positions WGS-84 geodetic [rad], distances [m], frequencies [kHz]. Outputs: the records
// of nav_records.hpp (SI). Distances and bearings are geodesic on the WGS-84 ellipsoid
// (GeographicLib, Karney 2013, accurate to nanometres); a bearing is the true azimuth at the
// query point of the geodesic to the station, in [0, 2 pi).
// Every query uses a statement prepared once at open(); none writes. One instance is not
// thread-safe (SQLite statements are stateful): give each thread its own.
#pragma once

#include "common/navdb/nav_records.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fedsim::nav {

/// A navaid found from a position.
struct NavaidHit {
  Navaid navaid;
  double distance_m = 0.0;        // geodesic, query point -> station [m]
  double bearing_true_rad = 0.0;  // true azimuth of the station from the query point [rad]
};

/// The database the build made (util::navdb_file(), <build>/data/nav.sqlite), or the file the
/// environment variable FEDSIM_NAVDB names when it is set.
std::string default_database_path();

class NavDatabase {
 public:
  /// Opens a database read-only. Throws std::runtime_error naming the path and the problem: no
  /// such file, not an SQLite file, not a navigation database (tables missing), or a schema
  /// version other than kSchemaVersion (rebuild it with fedsim-navdb).
  static NavDatabase open(const std::string& path);

  NavDatabase(NavDatabase&&) noexcept;
  NavDatabase& operator=(NavDatabase&&) noexcept;
  ~NavDatabase();

  const std::string& path() const;
  /// A value of the meta table ("" when absent): schema_version, navaids_source, ...
  std::string meta(std::string_view key) const;

  /// Navaids with this ident (case-insensitive), by country then id.
  std::vector<Navaid> find(std::string_view ident) const;
  /// Navaids on a frequency [kHz] (a DME/TACAN: its paired VHF), by id.
  std::vector<Navaid> on_frequency(std::uint32_t frequency_khz) const;
  /// Navaids within radius_m [m] of a position, nearest first (R*Tree box, then exact geodesic
  /// distance). Throws std::invalid_argument for a position or radius out of range (see
  /// search_box.hpp).
  std::vector<NavaidHit> within(double lat_rad, double lon_rad, double radius_m) const;
  /// The nearest navaid on a frequency [kHz] anywhere, or nullopt when none is on it.
  std::optional<NavaidHit> nearest_on_frequency(double lat_rad, double lon_rad,
                                                std::uint32_t frequency_khz) const;
  /// Every navaid, by id (for tests, tools and brute-force checks).
  std::vector<Navaid> all_navaids() const;

  /// An airport's runway ends (case-insensitive ident), by designator number ("1L" before "10L").
  std::vector<RunwayEndRecord> airport_runways(std::string_view airport) const;
  std::optional<RunwayEndRecord> runway(std::string_view airport, std::string_view runway) const;

  /// The ILS of a runway end, or nullopt.
  std::optional<IlsApproach> ils(std::string_view airport, std::string_view runway) const;
  /// An airport's ILS approaches, by runway.
  std::vector<IlsApproach> airport_ils(std::string_view airport) const;
  /// ILS approaches whose localizer has this ident (case-insensitive).
  std::vector<IlsApproach> ils_by_ident(std::string_view ident) const;
  /// ILS approaches on a localizer frequency [kHz].
  std::vector<IlsApproach> ils_on_frequency(std::uint32_t frequency_khz) const;

 private:
  struct Impl;
  explicit NavDatabase(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace fedsim::nav
