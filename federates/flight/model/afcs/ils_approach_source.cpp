#include "flight/model/afcs/ils_approach_source.hpp"
#include "common/util/build_paths.hpp"

#include "common/csv/csv_reader.hpp"
#include "common/navdb/ils_row.hpp"
#include "common/radio/approach_geometry.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cctype>
#include <stdexcept>

namespace fedsim::flight::afcs {

namespace {
bool same_text(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}
}  // namespace

nav::IlsApproach load_ils_approach(const std::string& ils_csv_path, const RunwayTable& runways,
                                   const std::string& airport, const std::string& runway) {
  csv::CsvReader reader = csv::CsvReader::open(ils_csv_path);
  reader.require_columns(nav::ils_columns());
  nav::RunwayEndRecord end_record;
  const nav::RunwayEndLookup lookup = [&](const std::string& a, const std::string& r) -> const nav::RunwayEndRecord* {
    const std::optional<RunwayEnd> end = runways.find(a, r);
    if (!end) return nullptr;
    end_record.airport = end->airport;
    end_record.runway = end->runway;
    end_record.threshold = {end->threshold_lat_rad, end->threshold_lon_rad, end->elevation_m};
    end_record.heading_true_rad = end->heading_rad;
    end_record.length_m = end->length_m;
    end_record.elevation_known = true;
    return &end_record;
  };
  csv::CsvRow row;
  while (reader.next(row)) {
    if (same_text(row.text("airport"), airport) && same_text(row.text("runway"), runway)) {
      return nav::parse_ils_row(row, lookup).ils;
    }
  }
  throw std::invalid_argument(ils_csv_path + ": no ILS for " + airport + " " + runway);
}

nav::IlsApproach load_default_ils_approach(const std::string& airport, const std::string& runway) {
  return load_ils_approach(fedsim::util::data_dir() + "/nav/ils.csv", RunwayTable::load_default(),
                           airport, runway);
}

nav::IlsApproach with_course_through_threshold(const nav::IlsApproach& approach,
                                               double* misalignment_at_threshold_m) {
  if (misalignment_at_threshold_m != nullptr) {
    const radio::ApproachGeometry g = radio::approach_geometry(approach);
    *misalignment_at_threshold_m =
        radio::course_coordinates(approach, g, approach.threshold.lat_rad, approach.threshold.lon_rad).left_m;
  }
  double distance_m = 0.0, azimuth_at_threshold_deg = 0.0, azimuth_at_antenna_deg = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(
      approach.threshold.lat_rad * units::kRadToDeg, approach.threshold.lon_rad * units::kRadToDeg,
      approach.localizer.lat_rad * units::kRadToDeg, approach.localizer.lon_rad * units::kRadToDeg, distance_m,
      azimuth_at_threshold_deg, azimuth_at_antenna_deg);
  nav::IlsApproach aligned = approach;
  double course = azimuth_at_antenna_deg * units::kDegToRad;
  if (course < 0.0) course += units::kTwoPi;
  aligned.course_true_rad = course;
  return aligned;
}

}  // namespace fedsim::flight::afcs
