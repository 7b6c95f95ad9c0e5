// Runway markings of ICAO Annex 14 Vol I (8th ed., 2018) Chapter 5.2, as painted quads in a
// runway end's coordinates (x: along from the threshold in the landing direction, y: to the
// right; metres). What is painted depends on the approach category of the end:
//   every end:      designation (5.2.2), threshold stripes (5.2.4), centreline (5.2.3)
//   instrument:     + aiming point (5.2.5)
//   precision:      + touchdown zone (5.2.6, pattern A), side stripes (5.2.7)
//   displaced thr.: + transverse stripe and arrows (5.2.4.10, Figure 5-4)
// Dimensions, with the clause they come from:
//   threshold: stripes from 6 m to 36 m beyond the threshold (5.2.4.5: at least 30 m long,
//     beginning 6 m from the threshold); their number by runway width 18/23/30/45/60 m ->
//     4/6/8/12/16 (5.2.4.6); they reach to 3 m from the edge or 27 m from the centreline,
//     whichever is less, each stripe and gap of equal width ("approximately 1.80 m") and a
//     double gap at the centreline (5.2.4.7).
//   designation: 9 m characters (Figure 5-3), beginning 12 m beyond the threshold stripes,
//     the letter of a parallel runway nearer the threshold, the number beyond it.
//   centreline: 30 m stripes and 20 m gaps (5.2.3.4: stripe + gap 50..75 m, the stripe at
//     least the gap and 30 m), 0.90 m wide on CAT II/III runways, 0.45 m on CAT I and
//     non-precision ones, 0.30 m otherwise (5.2.3.5), between the designations.
//   aiming point: Table 5-1 by landing distance available (LDA): beginning 150/250/300/400 m
//     from the threshold for LDA < 800 / < 1200 / < 2400 / >= 2400 m; where the table gives a
//     range, its lower value: 30/30/45/45 m long, 4/6/6/6 m wide, 6/9/18/18 m between the
//     inner sides.
//   touchdown zone: pairs 22.5 m x 3 m (pattern A) at 150 m intervals from the threshold,
//     1/2/3/4/6 pairs for LDA < 900 / < 1200 / < 1500 / < 2400 / >= 2400 m (Table 5-2), the
//     inner sides as far apart as the aiming point's; a pair within 50 m of the aiming point
//     is left out, and none reaches the middle of the runway (the other end's zone).
//   side stripes: along both edges between the thresholds, 0.90 m wide on runways 30 m wide
//     or more, 0.45 m otherwise (5.2.7.4), the outer side on the runway edge.
#pragma once

#include "visual/model/designation_font.hpp"
#include "visual/model/runway_designator.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace fedsim::visual {

enum class ApproachCategory : std::uint8_t {
  kVisual,
  kNonPrecision,
  kPrecisionCatI,
  kPrecisionCatIIorIII,
};

struct AimingPointLayout {
  double start_m = 0.0;          // from the threshold to the beginning of the marking [m]
  double length_m = 0.0;         // [m]
  double width_m = 0.0;          // of each of the two stripes [m]
  double inner_spacing_m = 0.0;  // between their inner sides [m]
};

/// Threshold stripes for a runway width (Annex 14 5.2.4.6).
int threshold_stripe_count(double width_m);
/// Table 5-1 by landing distance available.
AimingPointLayout aiming_point_layout(double landing_distance_m);
/// Table 5-2 by landing distance available.
int touchdown_zone_pair_count(double landing_distance_m);
/// Centreline width by approach category (5.2.3.5) [m].
double centreline_width_m(ApproachCategory category);

struct EndMarkingInput {
  RunwayDesignator designator;
  double width_m = 45.0;               // [m]
  double landing_distance_m = 3000.0;  // LDA: threshold to the far runway end [m]
  double displaced_threshold_m = 0.0;  // runway end to threshold [m]
  ApproachCategory category = ApproachCategory::kPrecisionCatI;
};

struct EndMarkings {
  std::vector<Quad2> quads;  // (x along, y right) of the end [m]
  int threshold_stripes = 0;
  double threshold_stripe_width_m = 0.0;
  double designation_end_m = 0.0;  // where the designation ends, along [m]
  std::optional<AimingPointLayout> aiming_point;
  std::vector<double> touchdown_zone_starts_m;  // each pair's beginning, along [m]
};

/// The markings of one end (all but the centreline and side stripes, which the runway shares
/// between its ends). Throws std::invalid_argument for a width outside 5..200 m or an LDA
/// outside 100..10000 m.
EndMarkings end_markings(const EndMarkingInput& input);

/// Centreline stripes between two along positions of one end's frame, centred in the span.
std::vector<Quad2> centreline_stripes(double from_m, double to_m, double width_m);
/// Side stripes along both edges between two along positions, in pieces of at most 50 m (so
/// that each lies flat on the curved earth within 0.1 mm).
std::vector<Quad2> side_stripes(double from_m, double to_m, double runway_width_m);
/// The clear space between a designation and the first centreline stripe [m].
double centreline_clearance_m();

}  // namespace fedsim::visual
