#include "common/navdb/row_fields.hpp"

#include "common/navdb/nav_types.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace fedsim::nav {

std::string number_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

double required_number_in(const csv::CsvRow& row, const std::string& column, double min,
                          double max) {
  if (row.empty(column)) row.fail("column '" + column + "': empty");
  const double value = row.number(column);
  if (value < min || value > max) {
    row.fail("column '" + column + "': " + row.text(column) + " is outside [" + number_text(min) +
             ", " + number_text(max) + "]");
  }
  return value;
}

std::optional<double> optional_number_in(const csv::CsvRow& row, const std::string& column,
                                         double min, double max) {
  if (row.empty(column)) return std::nullopt;
  return required_number_in(row, column, min, max);
}

const std::string& required_text(const csv::CsvRow& row, const std::string& column) {
  const std::string& text = row.text(column);
  if (text.empty()) row.fail("column '" + column + "': empty");
  return text;
}

bool flag_01(const csv::CsvRow& row, const std::string& column, bool empty_value) {
  const std::string& text = row.text(column);
  if (text.empty()) return empty_value;
  if (text == "0") return false;
  if (text == "1") return true;
  row.fail("column '" + column + "': '" + text + "' is not 0 or 1");
}

bool flag_yes_no(const csv::CsvRow& row, const std::string& column) {
  const std::string text = upper_ascii(row.text(column));
  if (text == "YES") return true;
  if (text == "NO") return false;
  row.fail("column '" + column + "': '" + row.text(column) + "' is not yes or no");
}

std::uint32_t whole_khz(const csv::CsvRow& row, const std::string& column, double min_khz,
                        double max_khz) {
  const double khz = required_number_in(row, column, min_khz, max_khz);
  if (khz != std::floor(khz)) row.fail("column '" + column + "': " + row.text(column) +
                                       " is not a whole number of kHz");
  return static_cast<std::uint32_t>(khz);
}

GeoPoint point_from_degrees(double lat_deg, double lon_deg, double elevation_m) {
  return GeoPoint{lat_deg * units::kDegToRad, lon_deg * units::kDegToRad, elevation_m};
}

double angle_difference_deg(double a_deg, double b_deg) {
  return std::abs(std::remainder(a_deg - b_deg, 360.0));
}

}  // namespace fedsim::nav
