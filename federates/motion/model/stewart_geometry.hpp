// Geometry of a 6-6 Stewart platform (Stewart 1965): six jacks, each between a base joint fixed
// to the floor and an upper joint fixed to the platform, with a stroke [min_length_m,
// max_length_m] between the joint centres.
//
// Frames (platform_pose.hpp): base joints in I, upper joints in P; with z down, the base joints
// lie at +neutral height below the MRP.
//
// The symmetric design (the usual synergistic flight-simulator layout): base joints in three
// pairs on a circle of base_radius_m, pair centres at azimuth 0, 120, 240 deg (azimuth from +x
// towards +y, i.e. clockwise seen from above), the joints of a pair base_half_separation_rad
// either side; upper joints in three pairs on top_radius_m, pair centres at 60, 180, 300 deg,
// top_half_separation_rad either side. Jack 2k runs from the base joint at 120k deg -
// base_half_separation to the upper joint at 120k - 60 deg + top_half_separation, jack 2k+1 from
// 120k deg + base_half_separation to 120k + 60 deg - top_half_separation, so every jack spans the
// same azimuth difference 60 deg - (base + top half separations) and all six have the same
// length at neutral. The neutral height is chosen so that they are at mid-stroke there, unless
// the design names one (neutral_height_m > 0: a platform whose neutral sits off mid-stroke).
#pragma once

#include <Eigen/Core>
#include <array>

#include "motion/model/platform_pose.hpp"

namespace fedsim::motion {

struct StewartGeometry {
  std::array<Eigen::Vector3d, kJackCount> base_joints_i_m;  // base joint centres, frame I [m]
  std::array<Eigen::Vector3d, kJackCount> top_joints_p_m;   // upper joint centres, frame P [m]
  double min_length_m = 0.0;  // jack fully retracted, joint centre to joint centre [m]
  double max_length_m = 0.0;  // jack fully extended [m]

  double stroke_m() const { return max_length_m - min_length_m; }
};

struct SymmetricStewartDesign {
  double base_radius_m = 0.0;  // radius of the base joint circle [m]
  double top_radius_m = 0.0;   // radius of the upper joint circle [m]
  double base_half_separation_rad =
      0.0;                               // half the azimuth between the joints of a base pair [rad]
  double top_half_separation_rad = 0.0;  // half the azimuth between an upper pair's joints [rad]
  double min_length_m = 0.0;             // retracted length, joint to joint [m]
  double stroke_m = 0.0;                 // max length - min length [m]
  double neutral_height_m = 0.0;  // MRP above the base joints at neutral [m]; 0: mid-stroke
};

/// The figures of a typical 60-inch (1.524 m) stroke six-jack flight-simulator platform (a
/// representative design, not a manufacturer's data): base radius 2.0 m, upper radius 1.5 m,
/// half separations 10 deg (base) and 10 deg (upper), retracted length 2.21 m, stroke 1.524 m.
/// Neutral (mid-stroke 2.972 m) at a height of 2.679 m above the base joints; single-axis
/// excursions from neutral at the hard stroke: surge +1.36/-1.47 m, sway +-1.32 m, heave
/// +0.88/-0.83 m (+ down), roll +-33.9 deg, pitch +36.3/-34.2 deg (+ nose up), yaw +-54.9 deg.
SymmetricStewartDesign typical_60_inch_design();

/// The geometry of a symmetric design; std::invalid_argument naming the field when a figure is
/// not finite, not positive, a half separation is outside (0, 30 deg), the jacks would not
/// reach (the horizontal span of a jack must be shorter than its mid-stroke length) or, with a
/// named neutral height, a jack is outside its stroke at neutral.
StewartGeometry make_symmetric_geometry(const SymmetricStewartDesign& design);

/// The joints of a symmetric design, the design's figures checked but not the stroke at
/// neutral: for a loader that computes the neutral jack lengths itself to say which field puts
/// them out of reach. make_symmetric_geometry is this plus validate().
StewartGeometry place_symmetric_joints(const SymmetricStewartDesign& design);

/// Checks a geometry (finite joints, 0 < min_length_m < max_length_m, the neutral lengths
/// inside the stroke); std::invalid_argument naming what is wrong.
void validate(const StewartGeometry& geometry);

/// Height of the MRP above the base joints at neutral for a symmetric design [m]: the design's
/// neutral_height_m when set, else the height that puts every jack at mid-stroke.
double neutral_height_m(const SymmetricStewartDesign& design);

}  // namespace fedsim::motion
