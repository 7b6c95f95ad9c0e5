// A light of the airport as the image generator draws it: a point source with a main beam.
//
// Intensity model (ICAO Annex 14 Vol I, Appendix 2, whose isocandela diagrams give each light's
// minimum average main-beam intensity inside an ellipse about the beam axis): the intensity
// towards the eye is I = I0 exp(-ln 2 ((a / a50)^2 + (e / e50)^2)), a and e the horizontal and
// vertical angles between the eye's direction and the beam axis, a50 and e50 the half-angles at
// which it falls to half (so the Appendix's ellipse is roughly the a50 x e50 one). Nothing is
// emitted backwards. Omnidirectional lights have I = I0 every way.
// A PAPI unit (Annex 14 5.3.6) shows white when the eye is above its transition angle and red
// below, the colour changing over 3 arcmin (5.3.6.18: the transition shall appear over not more
// than 3'); its red beam is the white one through the red filter.
#pragma once

#include <Eigen/Core>

#include <cstdint>

namespace fedsim::visual {

enum class BeamKind : std::uint8_t { kOmnidirectional = 0, kUnidirectional = 1, kPapi = 2 };

enum class LightRole : std::uint8_t {
  kApproachCentreline,
  kApproachCrossbar,
  kApproachSideRow,
  kThreshold,
  kRunwayEnd,
  kRunwayEdge,
  kRunwayCentreline,
  kTouchdownZone,
  kPapi,
  kMarker,  // test and calibration points
};

struct LightPoint {
  Eigen::Vector3f position_scene_m = Eigen::Vector3f::Zero();  // in S [m]
  Eigen::Vector3f beam_axis_scene = Eigen::Vector3f::UnitX();  // main-beam direction, unit, S
  Eigen::Vector3f up_scene = -Eigen::Vector3f::UnitZ();        // local vertical, unit, S
  Eigen::Vector3f colour_rgb = Eigen::Vector3f::Ones();        // display colour [0..1]
  float intensity_cd = 0.0f;            // main-beam intensity I0 (PAPI: white beam) [cd]
  float beam_half_width_h_rad = 0.17f;  // a50: horizontal half-angle at half intensity [rad]
  float beam_half_width_v_rad = 0.12f;  // e50: vertical half-angle at half intensity [rad]
  float papi_transition_rad = 0.0f;     // PAPI: elevation of the red/white transition [rad]
  BeamKind beam = BeamKind::kOmnidirectional;
  LightRole role = LightRole::kMarker;
  int runway_end = -1;  // index into Scene::runway_ends (-1: none)
};

}  // namespace fedsim::visual
