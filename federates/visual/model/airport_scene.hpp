// Builds the scene of one airport from its runway-end records (common/navdb: OurAirports'
// runways with the displaced thresholds applied; pass them in, e.g. from
// NavDatabase::airport_runways(), so that this library needs no SQLite).
//
// Inputs: the airport's RunwayEndRecords (SI: radians, metres MSL) and per-end options (approach
// category, approach lighting, PAPI, glide path); ends are paired into runways by their
// designators (28R <-> 10L). Output: a Scene in the frame tangent at the reference point (the
// mean of the runway end positions unless given), with
//   - the ground sphere at the lowest runway-end elevation less 0.3 m (so that every pavement
//     lies on it, drawn over it),
//   - each runway's pavement from end to end (published ends; displaced thresholds inside it),
//     in pieces of at most 50 m along the runway's longitudinal profile,
//   - the markings of runway_markings.hpp 3 cm above the pavement (the float depth buffer
//     resolves that at any range the picture shows),
//   - the lights of light_layout.hpp (none for an end whose record says unlighted; closed
//     runways are left out; both are noted).
// A record with a NaN, an infinity or a value out of range throws std::invalid_argument naming
// the airport, the runway and the field.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "visual/model/scene.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::visual {

struct RunwayEndOptions {
  ApproachCategory category = ApproachCategory::kPrecisionCatI;
  ApproachLighting approach_lighting = ApproachLighting::kIcaoCatI;
  bool papi = true;
  double glide_path_rad = 0.05235987755982989;  // 3 deg [rad]
};

struct AirportSceneOptions {
  RunwayEndOptions default_end;                     // for ends not named in `ends`
  std::map<std::string, RunwayEndOptions> ends;     // by designator, e.g. "28R"
  double unknown_width_m = 45.0;                    // for records with width 0 (unknown) [m]
  std::optional<GeodeticPosition> reference_point;  // lat/lon used; height: the ground's
};

Scene build_airport_scene(const std::vector<nav::RunwayEndRecord>& ends,
                          const AirportSceneOptions& options = {});

/// Throws std::invalid_argument "runway end <airport> <runway>: field '<f>': <problem>".
void validate(const nav::RunwayEndRecord& record);

}  // namespace fedsim::visual
