// An ILS approach record (nav::IlsApproach) from the project's data files, without the
// navigation database: the row of data/nav/ils.csv for the runway end, parsed and checked by
// common/navdb's parse_ils_row() (the database builder's own reader), its threshold from the
// runway table (data/nav/runways.csv through common/airports). For batch runs and tests that
// fly an approach with the flight model alone; a federation reads the database.
#pragma once

#include "common/airports/runway_table.hpp"
#include "common/navdb/nav_records.hpp"

#include <string>

namespace fedsim::flight::afcs {

/// Throws csv::CsvError ("file:line: column: problem") for a bad row, std::invalid_argument when
/// the table has no ILS for the runway end (naming the file, airport and runway).
nav::IlsApproach load_ils_approach(const std::string& ils_csv_path, const RunwayTable& runways,
                                   const std::string& airport, const std::string& runway);

/// data/nav/ils.csv and data/nav/runways.csv of this checkout.
nav::IlsApproach load_default_ils_approach(const std::string& airport, const std::string& runway);

/// The record with its front course laid through the threshold: the inbound azimuth, at the
/// localizer antenna, of the geodesic from the threshold to the antenna. For an antenna on the
/// extended runway centreline (as the record's own siting rule puts it, data/nav/ILS.md) this is
/// the runway centreline, where ICAO Annex 10 Vol I 3.1.3.6.1 requires the course line within
/// 3 m (Cat III) at the threshold. `misalignment_at_threshold_m`, when given, receives how far
/// the record's own course line passed from the threshold [m] (KSFO 28R: the table's true course
/// 297.903 deg against the runway's 297.814 deg puts it 7.6 m off).
nav::IlsApproach with_course_through_threshold(const nav::IlsApproach& approach,
                                               double* misalignment_at_threshold_m = nullptr);

}  // namespace fedsim::flight::afcs
