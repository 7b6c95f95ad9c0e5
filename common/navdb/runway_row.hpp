// One row of OurAirports' runways.csv (a runway: its "le" and "he" ends) -> up to two
// RunwayEndRecords (SI).
//
// For each end with a position: the landing direction is the geodesic azimuth from this end to
// the opposite end when both are positioned (OurAirports' headings are rounded, some wrong), else
// the published heading; the threshold is the end moved along the landing direction by the
// displaced threshold (GeographicLib geodesic); the length is the published one, else the
// geodesic distance between the ends (0 when neither is known).
// Checks: coordinates both given or neither, in range; elevation -1500..30000 ft; heading
// 0..360 deg; displacement >= 0 and shorter than the runway; the two ends apart; a numeric
// designator (e.g. "28R") within 90 deg of the ends' azimuth (otherwise the ends are swapped).
// Row problems (length, width, flags, airport) throw csv::CsvError; an end's problem skips that
// end only.
#pragma once

#include "common/csv/csv_reader.hpp"
#include "common/navdb/nav_records.hpp"

#include <string>
#include <vector>

namespace fedsim::nav {

/// The columns runways.csv must have.
const std::vector<std::string>& runway_columns();

struct RunwayRow {
  std::vector<RunwayEndRecord> ends;      // the usable ends (0, 1 or 2)
  std::vector<std::string> end_problems;  // "file:line: ..." of each end skipped
  int unpositioned_ends = 0;              // ends without a position (not stored, not an error)
  std::vector<std::string> warnings;      // remarks on kept ends (without "file:line: ")
};

/// Parses and checks one row (throws csv::CsvError for a problem of the whole row).
RunwayRow parse_runway_row(const csv::CsvRow& row);

}  // namespace fedsim::nav
