// One row of data/nav/ils.csv (the ILS format of data/nav/ILS.md: published units, columns in
// ils_columns(), docs/navdb.md) -> an IlsApproach (SI), its threshold taken from the runway end
// it serves.
//
// Checks: the airport/runway end exists; localizer frequency 108.10-111.95 MHz on an odd tenth
// (+0 or +50 kHz; ICAO Annex 10 Vol I 3.1.3.2.1); courses 0..360 deg, variation +-180 deg, the
// true course within 3 deg of magnetic + variation and within 10 deg of the runway's landing
// direction (an ILS course is aligned with the runway, FAA Order 8260.3 / PANS-OPS; a wrong end
// is 180 deg off); glide path 2.0-7.0 deg; TCH 10-150 ft; antenna positions in range and near the
// runway (localizer within 8 km, glide slope within 2 km of the threshold: a mistyped degree moves a
// point by ~100 km); course width 1-12 deg; markers 0-12 NM / 0-15000 ft / 0-5000 ft; dme yes/no;
// category I/II/III; `derived` names only columns of the table; a source named.
// Problems throw csv::CsvError through the row.
#pragma once

#include "common/csv/csv_reader.hpp"
#include "common/navdb/nav_records.hpp"

#include <functional>
#include <string>
#include <vector>

namespace fedsim::nav {

/// The columns ils.csv must have.
const std::vector<std::string>& ils_columns();

/// Finds a stored runway end by airport and designator (case-insensitive), or nullptr.
using RunwayEndLookup =
    std::function<const RunwayEndRecord*(const std::string& airport, const std::string& runway)>;

struct IlsRow {
  IlsApproach ils;
  std::vector<std::string> warnings;  // remarks on the kept row, without "file:line: "
};

IlsRow parse_ils_row(const csv::CsvRow& row, const RunwayEndLookup& runway_end);

}  // namespace fedsim::nav
