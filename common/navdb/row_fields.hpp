// Field helpers for the navigation database's CSV loaders: required and optional numbers with
// ranges. Every problem throws csv::CsvError "file:line: column 'name': problem" through the
// row, so that the loader reports the row and skips it.
#pragma once

#include "common/csv/csv_reader.hpp"
#include "common/navdb/nav_records.hpp"

#include <optional>
#include <string>

namespace fedsim::nav {

/// A required finite number in [min, max] ("empty" is its own message).
double required_number_in(const csv::CsvRow& row, const std::string& column, double min,
                          double max);
/// nullopt for an empty field, else a finite number in [min, max].
std::optional<double> optional_number_in(const csv::CsvRow& row, const std::string& column,
                                         double min, double max);
/// A required non-empty text field.
const std::string& required_text(const csv::CsvRow& row, const std::string& column);
/// A "0"/"1" flag (OurAirports' lighted, closed); empty is `empty_value`.
bool flag_01(const csv::CsvRow& row, const std::string& column, bool empty_value);
/// A "yes"/"no" flag (case-insensitive).
bool flag_yes_no(const csv::CsvRow& row, const std::string& column);
/// A whole number of kHz in [min_khz, max_khz] from a field holding kHz.
std::uint32_t whole_khz(const csv::CsvRow& row, const std::string& column, double min_khz,
                        double max_khz);
/// Formats a number for messages without trailing zeros ("108.1", "3").
std::string number_text(double value);

/// Plausible heights above MSL [ft] of a station, an antenna or a runway end (the Dead Sea shore
/// is 1,400 ft below MSL; the highest stations are near 14,000 ft).
inline constexpr double kMinElevationFt = -1500.0;
inline constexpr double kMaxElevationFt = 30000.0;

/// A position as the files publish it (latitude, longitude [deg]) with its elevation [m], in SI.
GeoPoint point_from_degrees(double lat_deg, double lon_deg, double elevation_m);
/// |a - b| of two directions [deg], wrapped into [0, 180].
double angle_difference_deg(double a_deg, double b_deg);

}  // namespace fedsim::nav
