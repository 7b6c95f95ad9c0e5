// One row of OurAirports' navaids.csv -> a Navaid (SI), with the checks that make a station
// usable by the receivers:
//   - frequency on the station's band and channel grid: VOR 108.00-117.95 MHz in 50 kHz steps,
//     below 112 MHz on even tenths only (odd tenths are ILS localizers), ICAO Annex 10 Vol I
//     3.3.2.1 and Vol V 4.2; NDB 190-1750 kHz (Annex 10 Vol I 3.4.2.1);
//   - a DME or TACAN channel (3 digits + X/Y) whose Annex 10 Table A pairing equals the station's
//     frequency (a VOR-DME's DME is paired with its VOR); channels 1-16 and 60-69 have no VHF
//     pairing (TACAN only; stored with frequency 0); a missing channel of a paired station is
//     derived from its frequency (the pairing is one to one);
//   - latitude, longitude, elevation (-1500..30000 ft), variations (+-180 deg) in range, the
//     DME position complete (both coordinates or neither: then co-located with the station).
// Problems throw csv::CsvError through the row (file:line: column 'x': problem).
#pragma once

#include "common/csv/csv_reader.hpp"
#include "common/navdb/nav_records.hpp"

#include <string>
#include <vector>

namespace fedsim::nav {

/// The columns navaids.csv must have.
const std::vector<std::string>& navaid_columns();

struct NavaidRow {
  Navaid navaid;
  bool dme_elevation_known = false;   // the DME's elevation was given or taken from the station
  std::vector<std::string> warnings;  // remarks on the kept row, without "file:line: "
};

/// Parses and checks one row (throws csv::CsvError for a problem).
NavaidRow parse_navaid_row(const csv::CsvRow& row);

}  // namespace fedsim::nav
