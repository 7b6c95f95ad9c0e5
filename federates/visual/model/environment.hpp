// The atmosphere and the light a channel draws with: the sun's direction (time of day), the
// visibility in the haze or fog layer next to the ground, and a cloud layer.
//
// Fog law: Koschmieder. The layer from the ground up to haze_top_agl_m is homogeneous with the
// extinction coefficient sigma = -ln(0.05) / V = 2.996 / V, V the meteorological visibility
// (MOR: the distance at which the contrast of a black object against the horizon sky falls to
// 5 %; ICAO Annex 3, WMO-No. 8). An object's colour C at distance d seen from the eye becomes
//     C' = C T + A (1 - T),  T = exp(-tau),  tau = integral of sigma along the line of sight,
// A the airlight (the horizon sky's colour). Its contrast against the horizon therefore falls as
// T: 5 % of its own at d = V, 0.25 % at 2 V, 22 % at 0.5 V.
// Cloud: the layer [base, top] has the extinction of its in-cloud visibility (60 m by default):
// above the base the eye is in cloud and sees only cloud; above the top the ground is hidden.
// Heights are above the airport's ground elevation (the scene's), as a METAR gives them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace fedsim::visual {

struct CloudLayer {
  double base_agl_m = 300.0;            // cloud base above the ground [m]
  double top_agl_m = 1500.0;            // cloud top above the ground [m]
  double visibility_in_cloud_m = 60.0;  // MOR inside the cloud [m]
};

struct Environment {
  double sun_elevation_rad = 0.7853981633974483;  // above the horizon at the airport [rad]
  double sun_azimuth_rad = 3.141592653589793;     // true, clockwise from north [rad]
  double visibility_m = 20000.0;    // MOR in the haze/fog layer next to the ground [m]
  double haze_top_agl_m = 1500.0;   // top of that layer (capped at the cloud base) [m]
  std::optional<CloudLayer> cloud;  // none: no cloud
  bool airport_lights_on = true;
};

/// Throws std::invalid_argument naming the field: sun elevation +-90 deg, azimuth +-360 deg,
/// visibility 10 m..1000 km, haze top 10..20000 m, cloud base 10..20000 m, top above the base
/// (at most 15000 m thick), in-cloud visibility 5..5000 m.
void validate(const Environment& environment, std::string_view where);

/// Koschmieder: sigma = -ln(0.05) / visibility [1/m].
double extinction_per_m(double visibility_m);

}  // namespace fedsim::visual
