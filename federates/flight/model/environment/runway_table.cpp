#include "flight/model/environment/runway_table.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace fedsim::flight {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) out.push_back(field);
  return out;
}
}  // namespace

RunwayTable RunwayTable::load_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open runway table");
  RunwayTable table;
  std::string line;
  std::getline(in, line);  // header
  int line_no = 1;
  const auto& wgs84 = GeographicLib::Geodesic::WGS84();
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    const auto f = split(line);
    if (f.size() != 8) throw std::runtime_error(path + ":" + std::to_string(line_no) + ": expected 8 fields");
    try {
      RunwayEnd end;
      end.airport = f[0];
      end.runway = f[1];
      const double lat = std::stod(f[2]), lon = std::stod(f[3]);
      end.elevation_m = std::stod(f[4]);
      const double heading_deg = std::stod(f[5]);
      end.length_m = std::stod(f[6]);
      const double displaced_m = std::stod(f[7]);
      double lat_t = lat, lon_t = lon;
      if (displaced_m > 0) wgs84.Direct(lat, lon, heading_deg, displaced_m, lat_t, lon_t);
      end.threshold_lat_rad = lat_t * kDegToRad;
      end.threshold_lon_rad = lon_t * kDegToRad;
      end.heading_rad = heading_deg * kDegToRad;
      table.by_airport_[end.airport].push_back(table.ends_.size());
      table.ends_.push_back(std::move(end));
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": malformed number");
    }
  }
  return table;
}

RunwayTable RunwayTable::load_default() {
  return load_file(std::string(FEDSIM_DATA_DIR) + "/nav/runways.csv");
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

}  // namespace fedsim::flight
