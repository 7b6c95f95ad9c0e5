#include "common/airports/runway_table.hpp"
#include "common/util/build_paths.hpp"

#include "common/csv/csv_reader.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

namespace fedsim {

RunwayTable RunwayTable::load_file(const std::string& path) {
  csv::CsvReader reader = csv::CsvReader::open(path);
  reader.require_columns({"airport", "runway", "threshold_lat_deg", "threshold_lon_deg",
                          "elevation_m", "heading_true_deg", "length_m", "displaced_threshold_m"});
  RunwayTable table;
  const auto& wgs84 = GeographicLib::Geodesic::WGS84();
  csv::CsvRow row;
  while (reader.next(row)) {
    RunwayEnd end;
    end.airport = row.text("airport");
    end.runway = row.text("runway");
    if (end.airport.empty() || end.runway.empty()) row.fail("airport and runway must be named");
    const double lat_deg = row.number_in("threshold_lat_deg", -90.0, 90.0);
    const double lon_deg = row.number_in("threshold_lon_deg", -180.0, 180.0);
    end.elevation_m = row.number_in("elevation_m", -500.0, 9000.0);
    const double heading_deg = row.number_in("heading_true_deg", 0.0, 360.0);
    end.length_m = row.number_in("length_m", 1.0, 20000.0);
    const double displaced_m = row.number_in("displaced_threshold_m", 0.0, end.length_m);
    double lat_t = lat_deg, lon_t = lon_deg;
    if (displaced_m > 0) wgs84.Direct(lat_deg, lon_deg, heading_deg, displaced_m, lat_t, lon_t);
    end.threshold_lat_rad = lat_t * units::kDegToRad;
    end.threshold_lon_rad = lon_t * units::kDegToRad;
    end.heading_rad = heading_deg * units::kDegToRad;
    table.by_airport_[end.airport].push_back(table.ends_.size());
    table.ends_.push_back(std::move(end));
  }
  return table;
}

RunwayTable RunwayTable::load_default() {
  return load_file(fedsim::util::data_dir() + "/nav/runways.csv");
}

std::optional<RunwayEnd> RunwayTable::find(const std::string& airport,
                                           const std::string& runway) const {
  const auto it = by_airport_.find(airport);
  if (it == by_airport_.end()) return std::nullopt;
  for (std::size_t i : it->second) {
    if (ends_[i].runway == runway) return ends_[i];
  }
  return std::nullopt;
}

RunwayEnd RunwayTable::at(const std::string& airport, const std::string& runway) const {
  if (auto end = find(airport, runway)) return *end;
  const auto it = by_airport_.find(airport);
  if (it == by_airport_.end()) {
    throw std::invalid_argument("unknown airport '" + airport +
                                "' (the runway table holds hard runways of 5000 ft or more)");
  }
  std::string have;
  for (std::size_t i : it->second) have += (have.empty() ? "" : ", ") + ends_[i].runway;
  throw std::invalid_argument("airport " + airport + " has no runway '" + runway + "' (it has " +
                              have + ")");
}

}  // namespace fedsim
