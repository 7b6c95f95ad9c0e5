// `fedsim nav find|near`: looks up the navigation database (common/navdb) from a terminal.
//   fedsim nav find <ident|airport>   navaids with that ident, localizers with it, an airport's
//                                     runway ends and ILS approaches
//   fedsim nav near <lat_deg> <lon_deg> [--radius-nm 40] [--type VOR,NDB,...]
//                                     stations within a radius, nearest first, with distance
//                                     [NM] and bearing (true, and magnetic with the station's
//                                     variation) from the position
//   --db PATH                         another database (default: the one the build made)
// Exit status: 0 found, 1 nothing found, 2 bad argument or database.
#pragma once

#include <CLI/CLI.hpp>

#include <iosfwd>
#include <string>

namespace fedsim::launcher {

struct NavNearQuery {
  double lat_deg = 0.0;        // [deg], -90..90
  double lon_deg = 0.0;        // [deg], -180..180
  double radius_nm = 40.0;     // [NM], (0, 10800]
  std::string types;           // "VOR,NDB" (OurAirports type names); empty = every type
};

/// `fedsim nav find`: prints what the database holds under `query`; returns the exit status.
int nav_find(const std::string& db_path, const std::string& query, std::ostream& out,
             std::ostream& err);
/// `fedsim nav near`: prints the stations near a position; returns the exit status.
int nav_near(const std::string& db_path, const NavNearQuery& query, std::ostream& out,
             std::ostream& err);

/// Registers `fedsim nav find|near` (output on `out`, errors on `err`).
void add_nav_commands(CLI::App& app, int& exit_code, std::ostream& out, std::ostream& err);

}  // namespace fedsim::launcher
