// Where the lights of a runway end are and how they shine, in the end's coordinates (along from
// the threshold in the landing direction, right of it; metres), after ICAO Annex 14 Vol I
// (8th ed., 2018) Chapter 5.3 and Appendix 2. Each LightSite serves the traffic of this end (it
// faces the aircraft that approaches and lands on it): a bidirectional fitting is two sites.
//
// Approach lighting (choose per end):
//  - ICAO precision approach CAT I (5.3.4.10-5.3.4.19): a centreline of lights at 30 m
//    intervals from 30 m to 900 m before the threshold, coded by distance: one source in the
//    inner 300 m, two in the middle 300 m, three in the outer 300 m (5.3.4.14 a); a crossbar
//    30 m long at 300 m (5.3.4.10), gaps up to 6 m either side of the centreline allowed.
//  - ICAO precision approach CAT II/III (5.3.4.22-5.3.4.39; FAA's ALSF-2 has the same inner
//    layout): centreline barrettes (5 lights over 4 m) at 30 m intervals to 900 m; in the inner
//    270 m red side-row barrettes (3 lights, 1.5 m apart) on the touchdown-zone gauge; crossbars
//    at 150 m (filling between the centreline and the side rows) and 300 m (30 m long).
// Runway lights:
//  - edge (5.3.9): both edges, at most 60 m apart, white; yellow over the last 600 m or third
//    of the runway, whichever is less, towards the stop end (5.3.9.7); red towards the approach
//    between the runway end and a displaced threshold (5.3.9.8).
//  - threshold (5.3.10): green, across the runway at the threshold, at most 3 m apart.
//  - runway end (5.3.11): red, towards the runway, at least 6, at most 6 m apart.
//  - centreline (5.3.12; CAT II/III, and CAT I runways wider than 50 m): 15 m apart on CAT
//    II/III, 30 m otherwise; white, then alternately red and white from 900 m to 300 m before
//    the stop end, red over the last 300 m (5.3.12.7).
//  - touchdown zone (5.3.13; CAT II/III): barrettes of 3 lights 1.5 m apart every 30 m to
//    900 m, inner lights on the touchdown-zone marking's gauge.
//  - PAPI (5.3.6): 4 units on the left, the nearest 15 m from the edge, 9 m apart, abeam the
//    aiming point; transition angles glide path +30', +10', -10', -30' from the runway outwards
//    (for a 3 deg path 3d30', 3d10', 2d50', 2d30': 4 white above 3.5 deg, 2 white 2 red on
//    3 deg, 4 red below 2.5 deg).
// Intensities are the Appendix 2 minimum average main-beam figures (approach centreline and
// crossbars 20 000 cd, side rows 5 000 cd red, threshold 10 000 cd green, edge 10 000 cd,
// centreline 5 000 cd at 30 m / 2 500 cd at 15 m spacing, touchdown zone 5 000 cd, runway end
// 2 500 cd red; colour filters: red x 0.15, yellow x 0.4 of the white), beams simplified to the
// elliptical law of light_point.hpp with the half-angles below; PAPI 15 000 cd white.
#pragma once

#include "visual/model/light_point.hpp"
#include "visual/model/runway_markings.hpp"

#include <vector>

namespace fedsim::visual {

enum class ApproachLighting : std::uint8_t { kNone, kIcaoCatI, kIcaoCatIIorIII };

struct LightSite {
  double along_m = 0.0;                // from the threshold, landing direction [m]
  double right_m = 0.0;                // [m]
  double height_m = 0.35;              // above the runway profile (inset 0.06, elevated 0.35) [m]
  double elevation_setting_rad = 0.0;  // beam axis above the horizontal [rad]
  double toe_in_rad = 0.0;             // beam axis turned towards the centreline [rad]
  Eigen::Vector3f colour_rgb = Eigen::Vector3f::Ones();
  float intensity_cd = 0.0f;
  float beam_half_width_h_rad = 0.1f;
  float beam_half_width_v_rad = 0.1f;
  float papi_transition_rad = 0.0f;
  BeamKind beam = BeamKind::kUnidirectional;
  LightRole role = LightRole::kRunwayEdge;
};

struct EndLightingInput {
  double width_m = 45.0;
  double threshold_to_stop_end_m = 3000.0;  // landing distance available [m]
  double runway_start_m = 0.0;              // where the pavement begins: -displaced [m]
  ApproachCategory category = ApproachCategory::kPrecisionCatI;
  ApproachLighting approach = ApproachLighting::kIcaoCatI;
  bool papi = true;
  double papi_along_m = 400.0;                  // abeam the aiming point [m]
  double glide_path_rad = 0.05235987755982989;  // 3 deg
  double touchdown_zone_gauge_m = 18.0;         // between the inner TDZ lights [m]
};

/// Aviation colours as displayed (Annex 14 Appendix 1 chromaticities, shown in sRGB).
Eigen::Vector3f aviation_white();
Eigen::Vector3f aviation_red();
Eigen::Vector3f aviation_green();
Eigen::Vector3f aviation_yellow();

std::vector<LightSite> approach_lights(const EndLightingInput& input);
/// Edge lights serving this end's traffic at the given along positions (shared with the
/// other end so that one fitting serves both directions).
std::vector<LightSite> edge_lights(const EndLightingInput& input,
                                   const std::vector<double>& along_positions_m);
std::vector<LightSite> threshold_lights(const EndLightingInput& input);
std::vector<LightSite> runway_end_lights(const EndLightingInput& input);
std::vector<LightSite> centreline_lights(const EndLightingInput& input);
std::vector<LightSite> touchdown_zone_lights(const EndLightingInput& input);
/// Units from the runway outwards: [0] has the highest transition angle.
std::vector<LightSite> papi_units(const EndLightingInput& input);
/// Whether the end gets runway centreline lights (5.3.12.1/5.3.12.2).
bool has_centreline_lights(const EndLightingInput& input);

}  // namespace fedsim::visual
