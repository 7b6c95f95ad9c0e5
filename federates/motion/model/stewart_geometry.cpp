#include "motion/model/stewart_geometry.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/control/parameter_checks.hpp"
#include "common/units/units.hpp"

namespace fedsim::motion {
namespace {

constexpr const char* kDesign = "SymmetricStewartDesign";

double half_stroke_length_m(const SymmetricStewartDesign& design) {
  return design.min_length_m + 0.5 * design.stroke_m;
}

// Horizontal distance between a jack's two joints at neutral (law of cosines over the azimuth
// difference 60 deg - both half separations).
double horizontal_span_m(const SymmetricStewartDesign& d) {
  const double azimuth_difference_rad =
      units::kPi / 3.0 - d.base_half_separation_rad - d.top_half_separation_rad;
  return std::sqrt(d.base_radius_m * d.base_radius_m + d.top_radius_m * d.top_radius_m -
                   2.0 * d.base_radius_m * d.top_radius_m * std::cos(azimuth_difference_rad));
}

void validate_design(const SymmetricStewartDesign& d) {
  using control::require_positive;
  require_positive(kDesign, "base_radius_m", d.base_radius_m);
  require_positive(kDesign, "top_radius_m", d.top_radius_m);
  require_positive(kDesign, "base_half_separation_rad", d.base_half_separation_rad);
  require_positive(kDesign, "top_half_separation_rad", d.top_half_separation_rad);
  require_positive(kDesign, "min_length_m", d.min_length_m);
  require_positive(kDesign, "stroke_m", d.stroke_m);
  control::require_non_negative(kDesign, "neutral_height_m", d.neutral_height_m);
  const double max_half_separation_rad = units::kPi / 6.0;
  if (d.base_half_separation_rad >= max_half_separation_rad ||
      d.top_half_separation_rad >= max_half_separation_rad) {
    throw std::invalid_argument(std::string(kDesign) +
                                ": half separations must be below 30 deg (pairs would overlap)");
  }
}

// The height at which every jack is at mid-stroke; none when the jacks cannot span the gap.
double mid_stroke_height_m(const SymmetricStewartDesign& d) {
  const double length_m = half_stroke_length_m(d);
  const double span_m = horizontal_span_m(d);
  if (!(span_m < length_m)) {
    std::ostringstream message;
    message << kDesign << ": the horizontal span of a jack (" << span_m
            << " m) must be shorter than its mid-stroke length (" << length_m << " m)";
    throw std::invalid_argument(message.str());
  }
  return std::sqrt(length_m * length_m - span_m * span_m);
}

Eigen::Vector3d on_circle(double radius_m, double azimuth_rad, double z_m) {
  return {radius_m * std::cos(azimuth_rad), radius_m * std::sin(azimuth_rad), z_m};
}

}  // namespace

SymmetricStewartDesign typical_60_inch_design() {
  SymmetricStewartDesign design;
  design.base_radius_m = 2.0;
  design.top_radius_m = 1.5;
  design.base_half_separation_rad = 10.0 * units::kDegToRad;
  design.top_half_separation_rad = 10.0 * units::kDegToRad;
  design.min_length_m = 2.21;
  design.stroke_m = 60.0 * units::kInToM;
  return design;
}

double neutral_height_m(const SymmetricStewartDesign& design) {
  validate_design(design);
  if (design.neutral_height_m > 0.0) return design.neutral_height_m;
  return mid_stroke_height_m(design);
}

StewartGeometry make_symmetric_geometry(const SymmetricStewartDesign& design) {
  StewartGeometry geometry = place_symmetric_joints(design);
  validate(geometry);
  return geometry;
}

StewartGeometry place_symmetric_joints(const SymmetricStewartDesign& d) {
  const double height_m = neutral_height_m(d);
  StewartGeometry geometry;
  const double pair_spacing_rad = 2.0 * units::kPi / 3.0;
  for (int k = 0; k < 3; ++k) {
    const double base_centre_rad = pair_spacing_rad * k;
    const double top_before_rad = base_centre_rad - units::kPi / 3.0;
    const double top_after_rad = base_centre_rad + units::kPi / 3.0;
    geometry.base_joints_i_m[2 * k] =
        on_circle(d.base_radius_m, base_centre_rad - d.base_half_separation_rad, height_m);
    geometry.base_joints_i_m[2 * k + 1] =
        on_circle(d.base_radius_m, base_centre_rad + d.base_half_separation_rad, height_m);
    geometry.top_joints_p_m[2 * k] =
        on_circle(d.top_radius_m, top_before_rad + d.top_half_separation_rad, 0.0);
    geometry.top_joints_p_m[2 * k + 1] =
        on_circle(d.top_radius_m, top_after_rad - d.top_half_separation_rad, 0.0);
  }
  geometry.min_length_m = d.min_length_m;
  geometry.max_length_m = d.min_length_m + d.stroke_m;
  return geometry;
}

void validate(const StewartGeometry& geometry) {
  constexpr const char* kBlock = "StewartGeometry";
  control::require_positive(kBlock, "min_length_m", geometry.min_length_m);
  control::require_positive(kBlock, "max_length_m", geometry.max_length_m);
  if (!(geometry.min_length_m < geometry.max_length_m)) {
    throw std::invalid_argument("StewartGeometry: min_length_m must be below max_length_m");
  }
  for (int k = 0; k < kJackCount; ++k) {
    if (!geometry.base_joints_i_m[k].allFinite() || !geometry.top_joints_p_m[k].allFinite()) {
      throw std::invalid_argument("StewartGeometry: joint " + std::to_string(k) + " is not finite");
    }
    const double neutral_length_m =
        (geometry.top_joints_p_m[k] - geometry.base_joints_i_m[k]).norm();
    if (!(neutral_length_m > geometry.min_length_m && neutral_length_m < geometry.max_length_m)) {
      std::ostringstream message;
      message << "StewartGeometry: jack " << k << " is " << neutral_length_m
              << " m long at neutral, outside its stroke [" << geometry.min_length_m << ", "
              << geometry.max_length_m << "] m";
      throw std::invalid_argument(message.str());
    }
  }
}

}  // namespace fedsim::motion
