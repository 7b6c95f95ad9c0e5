// Builds the navigation database file from OurAirports' navaids.csv and runways.csv and the
// project's ILS table (data/nav/ils.csv), the program fedsim-navdb's engine.
//
// Inputs: CSV streams (read through common/csv), each named by its origin for messages. A bad
// row is reported ("file:line: column 'x': problem") and skipped; a header without the expected
// columns, or a stream that cannot be read, throws (csv::CsvError / std::runtime_error).
// Output: an SQLite file in the schema of nav_schema.hpp, written to "<path>.partial" and renamed
// over <path> only when complete (a reader never sees half a database).
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/navdb/navaid_row.hpp"

#include <cstddef>
#include <functional>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace fedsim::nav {

struct BuildProblem {
  std::string origin;  // the file
  int line = 0;        // its line (0: the file as a whole)
  std::string text;    // "origin:line: message"
  bool warning = false;  // true: the row was kept (a remark), false: the row/end was skipped
};

struct BuildReport {
  std::map<NavaidType, std::size_t> navaids_by_type;  // kept
  std::size_t navaid_rows = 0;         // data rows read
  std::size_t navaids_skipped = 0;
  std::size_t runway_rows = 0;
  std::size_t runway_rows_skipped = 0;     // whole rows (both ends) skipped for a row problem
  std::size_t runway_ends = 0;             // kept
  std::size_t runway_ends_skipped = 0;     // ends with a problem (including the rows skipped)
  std::size_t runway_ends_unpositioned = 0;  // ends without coordinates in the source
  std::size_t ils_rows = 0;
  std::size_t ils_kept = 0;
  std::size_t ils_skipped = 0;
  bool ils_read = false;
  std::vector<BuildProblem> problems;  // in the order found

  std::size_t navaids_kept() const;
  std::size_t errors() const;
  std::size_t warnings() const;
};

class NavDatabaseBuilder {
 public:
  /// Called with every problem as it is found (e.g. to print it); optional.
  void on_problem(std::function<void(const BuildProblem&)> sink) { sink_ = std::move(sink); }

  void read_navaids(std::istream& in, const std::string& origin);
  void read_runways(std::istream& in, const std::string& origin);
  /// After read_runways: every ILS must serve a stored runway end.
  void read_ils(std::istream& in, const std::string& origin);

  /// Writes the database atomically. `sources` are stored in the meta table (e.g.
  /// "navaids_source" -> the file name); a key "schema_version" is written by the builder.
  void write(const std::string& path, const std::map<std::string, std::string>& sources) const;

  const BuildReport& report() const { return report_; }

 private:
  struct NavaidEntry {
    Navaid navaid;
    bool dme_elevation_known = false;
  };
  void add_problem(const std::string& origin, int line, const std::string& text, bool warning);
  void add_warning(const std::string& origin, int line, const std::string& message);
  void add_navaid(NavaidRow parsed, const std::string& origin, int line);
  void add_runway_end(const RunwayEndRecord& end, const std::string& origin, int line);

  std::vector<NavaidEntry> navaids_;
  std::map<std::string, RunwayEndRecord> runway_ends_;  // key: AIRPORT/RUNWAY upper case
  std::vector<IlsApproach> ils_;
  std::map<std::int64_t, int> navaid_id_lines_;           // id -> line it was first read on
  std::map<std::string, int> runway_end_lines_;          // key -> line
  BuildReport report_;
  std::function<void(const BuildProblem&)> sink_;
};

}  // namespace fedsim::nav
