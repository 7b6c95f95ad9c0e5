// The records of the navigation database (common/navdb): radio navigation aids, ILS approaches
// and runway ends, in SI. The database (SQLite, built from OurAirports and data/nav/ils.csv)
// returns them; the receivers of the navigation federate (federates/nav/model) compute with them.
// Pure data: no SQLite, no DDS.
//
// Angles in radians, positions WGS-84 geodetic, heights above mean sea level in metres,
// frequencies in kHz (VOR/ILS 108.00-117.95 MHz are 108000-117950 kHz; NDB 190-1750 kHz).
// Magnetic variation is east-positive: magnetic bearing = true bearing - variation.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace fedsim::nav {

/// The kinds of station in OurAirports' navaids.csv ("VOR", "VOR-DME", "VORTAC", "DME",
/// "TACAN", "NDB", "NDB-DME").
enum class NavaidType : std::uint8_t { kVor, kVorDme, kVortac, kDme, kTacan, kNdb, kNdbDme };

/// OurAirports' power class ("HIGH", "MEDIUM", "LOW", "UNKNOWN") and usage type ("HI", "LO",
/// "BOTH", "TERMINAL", "RNAV"); the receivers derive a service range from them.
enum class PowerClass : std::uint8_t { kUnknown, kLow, kMedium, kHigh };
enum class UsageType : std::uint8_t { kUnknown, kTerminal, kLow, kHigh, kBoth, kRnav };

struct GeoPoint {
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double elevation_m = 0.0;  // above MSL [m]
};

/// A radio navigation aid (VOR, DME, TACAN, NDB and their co-located combinations).
struct Navaid {
  std::int64_t id = 0;             // OurAirports id (stable across releases)
  std::string ident;               // e.g. "SFO"
  std::string name;                // e.g. "San Francisco"
  NavaidType type = NavaidType::kVor;
  std::uint32_t frequency_khz = 0; // VOR/NDB frequency; a DME or TACAN: its paired VHF [kHz]
  GeoPoint position;               // the VOR/NDB antenna (DME-only: the DME)
  bool elevation_known = false;    // OurAirports leaves some elevations empty (then 0)
  std::optional<GeoPoint> dme;     // the DME antenna where there is one
  std::string dme_channel;         // e.g. "084X" ("" when none)
  double magnetic_variation_rad = 0.0;  // at the station, east positive [rad]
  double slaved_variation_rad = 0.0;    // the variation a VOR is aligned to (its "slaving") [rad]
  bool slaved_variation_known = false;
  PowerClass power = PowerClass::kUnknown;
  UsageType usage = UsageType::kUnknown;
  std::string country;             // ISO 3166-1 alpha-2
  std::string airport;             // associated airport ident ("" when none)
};

/// The localizer and glide slope of one runway end (data/nav/ils.csv, from public aeronautical
/// publications; facts that could not be found are derived by the rules in data/nav/ILS.md and
/// flagged).
struct IlsApproach {
  std::string airport;             // ICAO ident, e.g. "KSFO"
  std::string runway;              // designator, e.g. "28R"
  std::string ident;               // localizer ident, e.g. "ISFO" (without the dash)
  std::uint32_t frequency_khz = 0; // localizer frequency (the glide slope is paired) [kHz]
  double course_true_rad = 0.0;    // localizer front course, true [rad]
  double magnetic_variation_rad = 0.0;  // the variation its magnetic course is published with [rad]
  double glide_path_angle_rad = 0.0;    // glide-slope angle above the horizontal [rad]
  double threshold_crossing_height_m = 0.0;  // glide path height over the threshold [m]
  double course_width_rad = 0.0;   // full-scale-to-full-scale sector width (0: from the rule) [rad]
  GeoPoint threshold;              // landing threshold
  GeoPoint localizer;              // localizer antenna (beyond the stop end)
  GeoPoint glide_slope;            // glide-slope antenna (abeam the touchdown zone)
  std::optional<double> outer_marker_distance_m;   // from the threshold along the approach [m]
  std::optional<double> middle_marker_distance_m;
  std::optional<double> inner_marker_distance_m;
  bool has_dme = false;            // a DME paired with the localizer, at the glide slope
  std::string derived;             // fields derived by rule, ';'-separated ("" when none)
  std::string source;              // the publication each fact comes from
  // Added with the database (common/navdb/nav_database.hpp):
  double course_magnetic_rad = 0.0;  // published front course, magnetic [rad]
  std::string category;            // ILS category: "I", "II" or "III"
};

/// One landing end of a runway (every runway end of OurAirports' runways.csv).
struct RunwayEndRecord {
  std::string airport;             // ident, e.g. "KSFO"
  std::string runway;              // designator, e.g. "28R"
  GeoPoint threshold;              // landing threshold (displacement applied)
  GeoPoint end;                    // the runway end as published (before displacement)
  double heading_true_rad = 0.0;   // landing direction, true [rad]
  double length_m = 0.0;           // end to end [m]
  double width_m = 0.0;            // [m]; 0 when unknown
  double displaced_threshold_m = 0.0;
  std::string surface;             // OurAirports' code, e.g. "ASP", "CON"
  bool lighted = false;
  bool closed = false;
  // Added with the database (common/navdb/nav_database.hpp):
  bool elevation_known = false;    // OurAirports leaves some end elevations empty (then 0)
};

}  // namespace fedsim::nav
