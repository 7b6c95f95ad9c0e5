// Sky and daylight by the sun's elevation: the colours the picture uses for the zenith and the
// horizon (away from and towards the sun), the illumination of the ground, and the background
// luminance the pilot's eye adapts to, which sets the threshold at which a light point is seen.
//
// The colours are a hand-made table in display units (0..1, like the picture), interpolated in
// sun elevation: day above ~10 deg, sunset/sunrise colours towards the sun between -8 and +5
// deg, civil twilight to -6 deg, night below -12 deg (the twilight definitions of the US Naval
// Observatory). It is not a radiative-transfer sky (Preetham et al. 1999 would be); it gives a
// horizon that warms towards the sun at sunset and darkens through twilight.
// The background luminance [cd/m^2] is of the order of measured horizon-sky luminances: clear day
// ~1e4, sunset ~500, the RVR day/night switch (2 foot-lamberts, 6.85 cd/m^2; FAA/ICAO) a few
// degrees below the horizon, night ~1e-3.
#pragma once

#include <Eigen/Core>

namespace fedsim::visual {

struct SkyState {
  Eigen::Vector3f zenith_rgb;             // sky colour overhead [0..1]
  Eigen::Vector3f horizon_rgb;            // at the horizon away from the sun [0..1]
  Eigen::Vector3f horizon_sunward_rgb;    // at the horizon below the sun [0..1]
  Eigen::Vector3f ambient_rgb;            // illumination of a horizontal white surface [0..1]
  Eigen::Vector3f sun_rgb;                // the sun's disc (0 when below the horizon) [0..1]
  double background_luminance_cd_per_m2;  // horizon-sky luminance the eye adapts to [cd/m^2]
};

/// The sky for a sun elevation (clamped to +-90 deg); throws std::invalid_argument for NaN.
SkyState sky_state(double sun_elevation_rad);

/// Illuminance threshold of a point light for an eye adapted to background luminance B, as RVR
/// assessment uses it with Allard's law (ICAO Doc 9328, 3rd ed. 2005, Appendix A; WMO-No. 8 Part
/// II Chapter 2): log10 E_T = 0.57 log10 B + 0.05 (log10 B)^2 - 6.66 (E_T in lux, B in cd/m^2),
/// with B kept in [1, 1e5] cd/m^2: at B = 1 the fit gives 2.2e-7 lux, the threshold of point
/// vision in dark conditions that signal lighting uses (0.2 microlux, IALA / IES "nominal
/// range"), and a darker background does not lower it further. 2.6e-4 lux on a bright day.
double light_threshold_lux(double background_luminance_cd_per_m2);

}  // namespace fedsim::visual
