#include "common/navdb/ils_row.hpp"

#include "common/navdb/nav_types.hpp"
#include "common/navdb/row_fields.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cctype>
#include <cmath>
#include <sstream>

namespace fedsim::nav {

namespace {

constexpr double kLocalizerLowMhz = 108.10;   // Annex 10 Vol I 3.1.3.2.1: 108-111.975 MHz,
constexpr double kLocalizerHighMhz = 111.95;  // odd tenths and odd tenths + 50 kHz
constexpr double kMaxTrueVsMagneticDeg = 3.0;
constexpr double kMaxCourseVsRunwayDeg = 10.0;
constexpr double kMaxLocalizerDistanceM = 8000.0;
constexpr double kMaxGlideSlopeDistanceM = 2000.0;

std::uint32_t localizer_khz(const csv::CsvRow& row) {
  const double mhz = required_number_in(row, "frequency_mhz", kLocalizerLowMhz, kLocalizerHighMhz);
  const auto khz = static_cast<std::uint32_t>(std::llround(mhz * 1000.0));
  const bool on_grid = std::abs(mhz * 1000.0 - khz) < 1e-3 && khz % 50 == 0;
  if (!on_grid || (khz / 100) % 2 == 0) {
    row.fail("column 'frequency_mhz': " + row.text("frequency_mhz") +
             " MHz is not a localizer frequency (odd tenths, +0.05, 108.10-111.95 MHz)");
  }
  return khz;
}

GeoPoint antenna(const csv::CsvRow& row, const std::string& name, const RunwayEndRecord& end,
                 double max_distance_m) {
  const double lat_deg = required_number_in(row, name + "_lat_deg", -90.0, 90.0);
  const double lon_deg = required_number_in(row, name + "_lon_deg", -180.0, 180.0);
  const double elevation_ft =
      required_number_in(row, name + "_elevation_ft", kMinElevationFt, kMaxElevationFt);
  double distance_m = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(end.threshold.lat_rad * units::kRadToDeg,
                                           end.threshold.lon_rad * units::kRadToDeg, lat_deg,
                                           lon_deg, distance_m);
  if (distance_m > max_distance_m) {
    row.fail("column '" + name + "_lat_deg'/'" + name + "_lon_deg': " +
             number_text(std::round(distance_m)) + " m from the threshold of " + end.airport + " " +
             end.runway + " (at most " + number_text(max_distance_m) + " m)");
  }
  return point_from_degrees(lat_deg, lon_deg, elevation_ft * units::kFtToM);
}

std::optional<double> marker_m(const csv::CsvRow& row, const std::string& column, double max,
                               double metres_per_unit) {
  const auto value = optional_number_in(row, column, 0.0, max);
  if (value && *value <= 0.0) row.fail("column '" + column + "': must be positive (or empty)");
  if (!value) return std::nullopt;
  return *value * metres_per_unit;
}

void check_ident(const csv::CsvRow& row, const std::string& ident) {
  bool alphanumeric = ident.size() >= 2 && ident.size() <= 5;
  for (char c : ident) alphanumeric = alphanumeric && std::isalnum(static_cast<unsigned char>(c));
  if (!alphanumeric) {
    row.fail("column 'ident': '" + ident + "' is not a localizer ident (2-5 letters/digits, no dash)");
  }
}

void check_derived(const csv::CsvRow& row, const std::string& derived) {
  std::stringstream tokens(derived);
  std::string token;
  while (std::getline(tokens, token, ';')) {
    const auto first = token.find_first_not_of(' ');
    if (first == std::string::npos) continue;  // "a;;b", a trailing ';'
    token = token.substr(first, token.find_last_not_of(' ') - first + 1);
    bool known = false;
    for (const auto& c : ils_columns()) known = known || c == token;
    if (!known) row.fail("column 'derived': '" + token + "' is not a column of the ILS table");
  }
}

void set_courses(const csv::CsvRow& row, const RunwayEndRecord& end, IlsApproach& ils) {
  const double magnetic_deg = required_number_in(row, "course_magnetic_deg", 0.0, 360.0);
  const double variation_deg = required_number_in(row, "magnetic_variation_deg", -180.0, 180.0);
  const double true_deg = required_number_in(row, "course_true_deg", 0.0, 360.0);
  if (angle_difference_deg(true_deg, magnetic_deg + variation_deg) > kMaxTrueVsMagneticDeg) {
    row.fail("column 'course_true_deg': " + row.text("course_true_deg") +
             " differs from magnetic + variation (" + number_text(magnetic_deg + variation_deg) +
             ") by more than 3 deg");
  }
  const double runway_deg = end.heading_true_rad * units::kRadToDeg;
  if (angle_difference_deg(true_deg, runway_deg) > kMaxCourseVsRunwayDeg) {
    row.fail("column 'course_true_deg': " + row.text("course_true_deg") + " is " +
             number_text(std::round(angle_difference_deg(true_deg, runway_deg))) +
             " deg from runway " + end.runway + "'s landing direction " +
             number_text(std::round(runway_deg * 10.0) / 10.0) + " deg true");
  }
  ils.course_magnetic_rad = magnetic_deg * units::kDegToRad;
  ils.magnetic_variation_rad = variation_deg * units::kDegToRad;
  ils.course_true_rad = true_deg * units::kDegToRad;
}

}  // namespace

const std::vector<std::string>& ils_columns() {
  static const std::vector<std::string> columns{
      "airport", "runway", "ident", "frequency_mhz", "course_magnetic_deg",
      "magnetic_variation_deg", "course_true_deg", "glide_path_angle_deg",
      "threshold_crossing_height_ft", "localizer_lat_deg", "localizer_lon_deg",
      "localizer_elevation_ft", "glide_slope_lat_deg", "glide_slope_lon_deg",
      "glide_slope_elevation_ft", "course_width_deg", "outer_marker_nm", "middle_marker_ft",
      "inner_marker_ft", "dme", "category", "derived", "source"};
  return columns;
}

IlsRow parse_ils_row(const csv::CsvRow& row, const RunwayEndLookup& runway_end) {
  IlsRow out;
  IlsApproach& ils = out.ils;
  const std::string& airport = required_text(row, "airport");
  const std::string& runway = required_text(row, "runway");
  const RunwayEndRecord* end = runway_end(airport, runway);
  if (!end) {
    row.fail("column 'runway': no runway end " + airport + " " + runway +
             " in the runway table (or it was skipped)");
  }
  ils.airport = end->airport;
  ils.runway = end->runway;
  ils.ident = required_text(row, "ident");
  check_ident(row, ils.ident);
  ils.frequency_khz = localizer_khz(row);
  set_courses(row, *end, ils);
  ils.glide_path_angle_rad =
      required_number_in(row, "glide_path_angle_deg", 2.0, 7.0) * units::kDegToRad;
  ils.threshold_crossing_height_m =
      required_number_in(row, "threshold_crossing_height_ft", 10.0, 150.0) * units::kFtToM;
  ils.course_width_rad =
      optional_number_in(row, "course_width_deg", 1.0, 12.0).value_or(0.0) * units::kDegToRad;
  ils.localizer = antenna(row, "localizer", *end, kMaxLocalizerDistanceM);
  ils.glide_slope = antenna(row, "glide_slope", *end, kMaxGlideSlopeDistanceM);
  ils.threshold = end->threshold;
  // A threshold without a published elevation takes the glide slope's (sited at threshold
  // elevation, data/nav/ILS.md).
  if (!end->elevation_known) ils.threshold.elevation_m = ils.glide_slope.elevation_m;
  ils.outer_marker_distance_m = marker_m(row, "outer_marker_nm", 12.0, units::kNmToM);
  ils.middle_marker_distance_m = marker_m(row, "middle_marker_ft", 15000.0, units::kFtToM);
  ils.inner_marker_distance_m = marker_m(row, "inner_marker_ft", 5000.0, units::kFtToM);
  ils.has_dme = flag_yes_no(row, "dme");
  ils.category = upper_ascii(row.text("category"));
  if (ils.category != "I" && ils.category != "II" && ils.category != "III") {
    row.fail("column 'category': '" + row.text("category") + "' is not I, II or III");
  }
  ils.derived = row.text("derived");
  check_derived(row, ils.derived);
  ils.source = required_text(row, "source");
  if (end->closed) out.warnings.push_back("runway " + end->airport + " " + end->runway + " is closed");
  return out;
}

}  // namespace fedsim::nav
