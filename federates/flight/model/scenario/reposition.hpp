// Repositioning (an instructor's job, seed 9.4.5): move the aircraft to a point in flight, onto
// a runway threshold, or to an approach gate, trimmed there. Above the model: each is a trim
// request built from the target, solved on the model.
//
// Each keeps fuel, weather and failures, re-pins the flat-earth origin at the new position,
// trims there and leaves the model in the trimmed state with the trimmed controls (check the
// result: if the trim fails the model is in the best state found).
#pragma once

#include "common/airports/runway_table.hpp"
#include "common/units/units.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/trim.hpp"

namespace fedsim::flight {

/// A runway end: threshold position on the centreline (lat, lon in rad; alt_m = the runway's
/// elevation) and the true heading of the landing direction.
struct Runway {
  GeodeticPosition threshold;
  double heading_rad = 0.0;
};

/// The runway end of the shared runway table.
Runway runway_of(const RunwayEnd& end);

/// In flight at a point: wings level, straight and level at the true airspeed.
TrimResult reposition_to_point(AircraftModel& model, const GeodeticPosition& position,
                               double heading_rad, double tas_mps);
/// On the runway centreline at the threshold, aligned, at rest, brakes set, gear down, the
/// engines settled at `throttle` (0 idle .. 1 full: a take-off from a standing start; NaN or a
/// value outside 0..1 throws std::invalid_argument); the terrain becomes the threshold's
/// elevation.
TrimResult reposition_to_runway(AircraftModel& model, const Runway& runway, double throttle = 0.0);
/// On the extended centreline distance_m before the threshold, on a glide path of
/// glide_path_rad through 50 ft over the threshold, established in a steady descent at the true
/// airspeed with the current flaps and gear.
TrimResult reposition_to_approach_gate(AircraftModel& model, const Runway& runway,
                                       double distance_m, double tas_mps,
                                       double glide_path_rad = 3.0 * units::kDegToRad);

/// Where an approach starts: `distance_m` before the threshold along the extended centreline,
/// `left_m` to the left of it (seen landing; negative: right), at `altitude_msl_m`, heading
/// towards the centreline at `intercept_rad` to the runway heading (0: parallel to it).
struct InterceptStart {
  double distance_m = 0.0;      // [m], 0..100 km
  double left_m = 0.0;          // [m], within +-20 km
  double intercept_rad = 0.0;   // [rad], 0..90 deg
  double altitude_msl_m = 0.0;  // [m], above the runway, below 20 km
  double airspeed_mps = 0.0;    // true airspeed, or calibrated if airspeed_is_cas [m/s], > 0
  bool airspeed_is_cas = false;
};

/// In level flight at the intercept start, wings level, with the current configuration
/// (flaps, gear) held; the terrain becomes the threshold's elevation. Throws
/// std::invalid_argument naming the field for a value outside its range (NaN included).
TrimResult reposition_to_intercept(AircraftModel& model, const Runway& runway, const InterceptStart& start);

}  // namespace fedsim::flight
