#include "common/navdb/runway_row.hpp"

#include "common/navdb/row_fields.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cctype>
#include <cmath>
#include <optional>

namespace fedsim::nav {

namespace {

constexpr double kMaxLengthFt = 50000.0;             // longest runways are ~18,000 ft
constexpr double kMaxWidthFt = 10000.0;          // water lanes reach 7,000 ft
constexpr double kHeadingWarningDeg = 5.0;           // published heading vs the ends' azimuth
constexpr double kDesignatorToleranceDeg = 90.0;     // magnetic designator vs true azimuth
constexpr double kMinEndSeparationM = 1.0;

/// The column prefixes of the two ends (OurAirports' low and high end) and the columns each end
/// has after its prefix.
constexpr const char* kEndPrefixes[2] = {"le_", "he_"};
constexpr const char* kEndColumns[] = {"ident",        "latitude_deg", "longitude_deg",
                                       "elevation_ft", "heading_degT", "displaced_threshold_ft"};

/// The published facts of one end ("le_" or "he_" columns).
struct EndFields {
  std::string ident;
  std::optional<double> lat_deg;
  std::optional<double> lon_deg;
  std::optional<double> elevation_ft;
  std::optional<double> heading_deg;
  double displaced_ft = 0.0;
  bool positioned() const { return lat_deg.has_value(); }
};

EndFields read_end(const csv::CsvRow& row, const std::string& prefix) {
  EndFields end;
  end.ident = row.text(prefix + "ident");
  end.lat_deg = optional_number_in(row, prefix + "latitude_deg", -90.0, 90.0);
  end.lon_deg = optional_number_in(row, prefix + "longitude_deg", -180.0, 180.0);
  if (end.lat_deg.has_value() != end.lon_deg.has_value()) {
    row.fail("column '" + prefix + (end.lat_deg ? "longitude_deg" : "latitude_deg") +
             "': empty while the other coordinate is given");
  }
  end.elevation_ft = optional_number_in(row, prefix + "elevation_ft", kMinElevationFt,
                                        kMaxElevationFt);
  end.heading_deg = optional_number_in(row, prefix + "heading_degT", 0.0, 360.0);
  end.displaced_ft =
      optional_number_in(row, prefix + "displaced_threshold_ft", 0.0, kMaxLengthFt).value_or(0.0);
  return end;
}

/// The magnetic direction a designator states ("28R" -> 280), or nullopt ("H1", "N", "XX").
std::optional<double> designator_heading_deg(const std::string& ident) {
  std::size_t digits = 0;
  while (digits < ident.size() && digits < 2 && std::isdigit(static_cast<unsigned char>(ident[digits]))) {
    ++digits;
  }
  if (digits == 0) return std::nullopt;
  if (digits < ident.size()) {
    const char c = ident[digits];
    if (c != 'L' && c != 'R' && c != 'C' && c != 'l' && c != 'r' && c != 'c') return std::nullopt;
    if (digits + 1 != ident.size()) return std::nullopt;
  }
  const int number = std::stoi(ident.substr(0, digits));
  if (number < 1 || number > 36) return std::nullopt;
  return number * 10.0;
}

struct RowFacts {
  std::string airport;
  std::optional<double> length_ft;
  double width_ft = 0.0;
  std::string surface;
  bool lighted = false;
  bool closed = false;
};

RunwayEndRecord make_end(const csv::CsvRow& row, const RowFacts& facts, const EndFields& end,
                         const EndFields& opposite, const std::string& prefix,
                         std::vector<std::string>& warnings) {
  const auto& geodesic = GeographicLib::Geodesic::WGS84();
  if (end.ident.empty()) row.fail("column '" + prefix + "ident': empty");
  RunwayEndRecord r;
  r.airport = facts.airport;
  r.runway = end.ident;
  double heading_deg = 0.0;
  double length_m = facts.length_ft.value_or(0.0) * units::kFtToM;
  if (opposite.positioned()) {
    double distance_m = 0.0, azimuth_deg = 0.0, azimuth_at_opposite_deg = 0.0;
    geodesic.Inverse(*end.lat_deg, *end.lon_deg, *opposite.lat_deg, *opposite.lon_deg,
                     distance_m, azimuth_deg, azimuth_at_opposite_deg);
    if (distance_m < kMinEndSeparationM) row.fail("the two runway ends are at the same position");
    heading_deg = azimuth_deg < 0.0 ? azimuth_deg + 360.0 : azimuth_deg;
    if (length_m <= 0.0) length_m = distance_m;
    const auto designated = designator_heading_deg(end.ident);
    if (designated && angle_difference_deg(*designated, heading_deg) > kDesignatorToleranceDeg) {
      row.fail("column '" + prefix + "ident': runway " + end.ident + " but the ends' azimuth is " +
               number_text(std::round(heading_deg)) + " deg true (ends swapped?)");
    }
    if (end.heading_deg && angle_difference_deg(*end.heading_deg, heading_deg) > kHeadingWarningDeg) {
      warnings.push_back("column '" + prefix + "heading_degT': " +
                         number_text(*end.heading_deg) + " differs from the ends' azimuth " +
                         number_text(std::round(heading_deg * 10.0) / 10.0) +
                         " deg by more than 5 deg: the azimuth is used");
    }
  } else if (end.heading_deg) {
    heading_deg = *end.heading_deg;
  } else {
    row.fail("column '" + prefix + "heading_degT': empty, and the opposite end has no position");
  }
  const double displaced_m = end.displaced_ft * units::kFtToM;
  if (length_m > 0.0 && displaced_m >= length_m) {
    row.fail("column '" + prefix + "displaced_threshold_ft': " + number_text(end.displaced_ft) +
             " ft is not shorter than the runway");
  }
  r.elevation_known = end.elevation_ft.has_value();
  const double elevation_m = end.elevation_ft.value_or(0.0) * units::kFtToM;
  r.end = point_from_degrees(*end.lat_deg, *end.lon_deg, elevation_m);
  double threshold_lat_deg = *end.lat_deg, threshold_lon_deg = *end.lon_deg;
  if (displaced_m > 0.0) {
    geodesic.Direct(*end.lat_deg, *end.lon_deg, heading_deg, displaced_m, threshold_lat_deg,
                    threshold_lon_deg);
  }
  r.threshold = point_from_degrees(threshold_lat_deg, threshold_lon_deg, elevation_m);
  r.heading_true_rad = heading_deg * units::kDegToRad;
  r.length_m = length_m;
  r.width_m = facts.width_ft * units::kFtToM;
  r.displaced_threshold_m = displaced_m;
  r.surface = facts.surface;
  r.lighted = facts.lighted;
  r.closed = facts.closed;
  return r;
}

}  // namespace

const std::vector<std::string>& runway_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> names{"id",      "airport_ident", "length_ft", "width_ft",
                                   "surface", "lighted",       "closed"};
    for (const char* prefix : kEndPrefixes) {
      for (const char* column : kEndColumns) names.push_back(std::string(prefix) + column);
    }
    return names;
  }();
  return columns;
}

RunwayRow parse_runway_row(const csv::CsvRow& row) {
  RowFacts facts;
  facts.airport = required_text(row, "airport_ident");
  facts.length_ft = optional_number_in(row, "length_ft", 0.0, kMaxLengthFt);
  if (facts.length_ft && *facts.length_ft == 0.0) facts.length_ft.reset();  // 0 = unknown
  facts.width_ft = optional_number_in(row, "width_ft", 0.0, kMaxWidthFt).value_or(0.0);
  facts.surface = row.text("surface");
  facts.lighted = flag_01(row, "lighted", false);
  facts.closed = flag_01(row, "closed", false);

  RunwayRow out;
  const std::string prefixes[2] = {kEndPrefixes[0], kEndPrefixes[1]};
  std::optional<EndFields> fields[2];
  for (int i = 0; i < 2; ++i) {
    try {
      fields[i] = read_end(row, prefixes[i]);
    } catch (const csv::CsvError& e) {
      out.end_problems.push_back(e.what());
    }
  }
  const EndFields none;
  for (int i = 0; i < 2; ++i) {
    if (!fields[i]) continue;
    if (!fields[i]->positioned()) {
      ++out.unpositioned_ends;
      continue;
    }
    const EndFields& opposite = fields[1 - i] ? *fields[1 - i] : none;
    try {
      out.ends.push_back(make_end(row, facts, *fields[i], opposite, prefixes[i], out.warnings));
    } catch (const csv::CsvError& e) {
      out.end_problems.push_back(e.what());
    }
  }
  return out;
}

}  // namespace fedsim::nav
