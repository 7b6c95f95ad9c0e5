// Geometry of the radio path between a ground antenna and the aircraft (seed 6.2, navigation
// computations), and the VHF/UHF radio horizon.
//
// Inputs: a station antenna (GeoPoint: WGS-84 latitude/longitude [rad], elevation above MSL [m])
// and the aircraft position (latitude/longitude [rad], altitude above MSL [m]).
// Outputs (LinkGeometry): the geodesic distance and azimuths on the WGS-84 ellipsoid
// (GeographicLib::Geodesic, exact to nanometres), the straight-line slant range and the elevation
// angle of the aircraft above the station's local horizontal plane (both through ECEF).
// Heights above MSL are used as heights above the ellipsoid: the geoid undulation is nearly the
// same at both ends of a radio path (it changes by a few metres over 100 km), so the slant range
// and the elevation angle are unaffected to well below the receivers' resolution.
#pragma once

#include "common/math/rotation.hpp"
#include "common/navdb/nav_records.hpp"
#include "common/units/units.hpp"

namespace fedsim::radio {

struct LinkGeometry {
  double ground_distance_m = 0.0;              // geodesic station -> aircraft sub-point [m]
  double azimuth_from_station_true_rad = 0.0;  // at the station, towards the aircraft, [0, 2 pi)
  double azimuth_to_station_true_rad = 0.0;    // at the aircraft, towards the station, [0, 2 pi)
  double slant_range_m = 0.0;                  // straight line antenna -> aircraft [m]
  double height_above_station_m = 0.0;         // aircraft altitude - station elevation [m]
  double elevation_angle_rad = 0.0;            // above the station's local horizontal [rad]
};

/// The path from `station` to an aircraft at (lat_rad, lon_rad, altitude_msl_m).
LinkGeometry link_geometry(const nav::GeoPoint& station, double lat_rad, double lon_rad,
                           double altitude_msl_m);

/// Geodesic distance [m] from `station` to the sub-point of (lat_rad, lon_rad) (no ECEF work).
double ground_distance_m(const nav::GeoPoint& station, double lat_rad, double lon_rad);

/// A lower bound of the geodesic distance [m] for culling far stations cheaply: the great-circle
/// distance on a sphere of the smallest radius of curvature of the ellipsoid, a (1 - e^2) (the
/// meridian radius at the equator), less 0.5%; about 20 times cheaper than the geodesic.
double ground_distance_lower_bound_m(const nav::GeoPoint& station, double lat_rad, double lon_rad);
/// No receiver of this library hears a station farther than this: the radio horizon between
/// 45,000 ft and a 5,000 ft station is 1.23 (sqrt(45000) + sqrt(5000)) = 348 NM, and the largest
/// service range (VOR class H, 130 NM; DME 199 NM; NDB HH 75 NM) is less. Stations beyond it
/// are reported out of their service volume without computing their geometry.
inline constexpr double kReceptionLimitM = 400.0 * units::kNmToM;

/// Radius of the standard effective earth for VHF/UHF propagation: k = 4/3 of the mean earth
/// radius R1 = (2a + b) / 3 of WGS-84 (k from the standard refractivity gradient of
/// -40 N-units/km, ITU-R P.453; k = 1 / (1 + R dN/dh) = 1.34).
inline constexpr double kEffectiveEarthFactor = 4.0 / 3.0;
double effective_earth_radius_m();

/// Radio line-of-sight distance over a smooth 4/3 earth between antennas at heights h1 and h2
/// above MSL: d = sqrt(2 k R h1) + sqrt(2 k R h2) [m]. Negative heights count as 0.
double radio_line_of_sight_m(double height1_msl_m, double height2_msl_m);

/// True when a VHF/UHF signal reaches the aircraft over the ground distance (the path is above
/// the 4/3-earth radio horizon). Terrain is not modelled: the earth is smooth at sea level.
bool within_radio_line_of_sight(double station_msl_m, double aircraft_msl_m,
                                double ground_distance_m);

/// Angle in [0, 2 pi) (the (-pi, pi] wrap is fedsim::wrap_pi of common/math/rotation.hpp).
double wrap_two_pi(double angle_rad);

}  // namespace fedsim::radio
