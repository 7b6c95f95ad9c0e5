// Instructor commands as JSON, the instructor station page's form (edge units, as typed):
//   {"command": "freeze"}                       run | freeze | reset
//   {"command": "reposition", "airport": "KSFO", "runway": "28R", "gate_nm": 10}
//   {"command": "reposition", "lat_deg": 37.6, "lon_deg": -122.3, "alt_ft": 3000, "heading_deg": 280, "kt": 140}
//   {"command": "weather", "wind_from_deg": 280, "wind_kt": 15, "turbulence": "light", "visibility_m": 800, ...}
//   {"command": "fail", "system": "engine1"}     fail | restore
//   {"command": "time_of_day", "utc": "2026-12-22T01:30:00", "lights": true}
//   {"command": "tune", "nav1_mhz": 111.7, "obs1_deg": 284}
//   {"command": "snapshot", "channel": "centre", "tag": "gate"}
// Every key is checked: an unknown key, a value of the wrong type or out of range is a
// RequestError naming it; nothing is guessed.
#pragma once

#include "common/instructor/instructor_request.hpp"

#include <nlohmann/json_fwd.hpp>

namespace fedsim::instructor {

InstructorRequest request_from_json(const nlohmann::json& body);
/// Parses `text` first (a syntax error is a RequestError too).
InstructorRequest request_from_json_text(const std::string& text);

}  // namespace fedsim::instructor
