// Runway ends from data/nav/runways.csv (OurAirports, trimmed by tools/navdata/trim_runways.py):
// where the instructor can put the aircraft on a runway or an approach gate.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace fedsim {

struct RunwayEnd {
  std::string airport;        // ICAO ident, e.g. "KSFO"
  std::string runway;         // designator, e.g. "28R"
  double threshold_lat_rad = 0.0;  // landing threshold (displacement applied) [rad]
  double threshold_lon_rad = 0.0;
  double elevation_m = 0.0;   // threshold elevation above MSL [m]
  double heading_rad = 0.0;   // true heading of the landing direction [rad]
  double length_m = 0.0;      // runway length end to end [m]
};

class RunwayTable {
 public:
  /// Loads the CSV; throws std::runtime_error naming file and line on a malformed row.
  static RunwayTable load_file(const std::string& path);
  /// The table shipped in data/nav/runways.csv.
  static RunwayTable load_default();

  /// The runway end; std::nullopt if unknown.
  std::optional<RunwayEnd> find(const std::string& airport, const std::string& runway) const;
  /// As find(), but throws std::invalid_argument with the runways the airport does have.
  RunwayEnd at(const std::string& airport, const std::string& runway) const;
  std::size_t size() const { return ends_.size(); }

 private:
  std::vector<RunwayEnd> ends_;
  std::unordered_map<std::string, std::vector<std::size_t>> by_airport_;
};

}  // namespace fedsim
