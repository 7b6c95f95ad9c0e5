// What the instructor station's moving map draws around an airport (seed 9.6): every runway of
// the airport (both ends, width), the ILS approaches with their feathers (localizer course, the
// full-scale sector and a 10 NM length), and the navaids within a radius, from the navigation
// database; and where a runway reposition will put the aircraft (so that the station can check
// the flight federate did it).
#pragma once

#include "common/navdb/nav_database.hpp"
#include "ios/model/command_tracker.hpp"

#include <optional>
#include <string>

namespace fedsim::ios {

/// The map of `airport` as JSON:
/// {"airport": "KSFO", "center": {"lat_deg", "lon_deg"},
///  "runways": [{"runway", "lat_deg", "lon_deg", "end_lat_deg", "end_lon_deg", "heading_deg", "width_m", "length_m"}],
///  "ils": [{"runway", "ident", "mhz", "course_deg", "half_width_deg", "glide_path_deg", "threshold": {...}, "localizer": {...}}],
///  "navaids": [{"ident", "name", "type", "khz", "lat_deg", "lon_deg", "distance_nm"}]}
/// Throws std::invalid_argument for an airport the database has no runway of, or a radius
/// outside 1..200 NM.
std::string map_json(const nav::NavDatabase& db, const std::string& airport, double radius_nm);

/// Where a runway reposition puts the aircraft: the threshold, or `gate_distance_m` back along
/// the approach course from it; nullopt if the database lacks the runway.
std::optional<ExpectedPosition> expected_position(const nav::NavDatabase& db, const std::string& airport,
                                                  const std::string& runway, double gate_distance_m);

}  // namespace fedsim::ios
