// What an image generator draws: the scene frame, the airport's surfaces as triangles and its
// lights as points, all in scene coordinates (S: NED at the airport reference point), plus the
// facts about each runway end that a test or a display needs. Built once per airport
// (airport_scene.hpp) and shared by every channel; the renderer uploads it to the GL context.
#pragma once

#include "visual/model/light_layout.hpp"
#include "visual/model/light_point.hpp"
#include "visual/model/runway_markings.hpp"
#include "visual/model/scene_frame.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace fedsim::visual {

enum class SurfaceMaterial : std::uint8_t { kPavement = 0, kPaint = 1 };

struct SurfaceVertex {
  Eigen::Vector3f position_scene_m = Eigen::Vector3f::Zero();  // S [m]
  Eigen::Vector2f texture_m = Eigen::Vector2f::Zero();         // (along, right) on the runway [m]
  SurfaceMaterial material = SurfaceMaterial::kPavement;
};

struct RunwayEndInfo {
  std::string airport;                                          // e.g. "KSFO"
  std::string designator;                                       // e.g. "28R"
  Eigen::Vector3d threshold_scene_m = Eigen::Vector3d::Zero();  // centre of the threshold, S
  double threshold_elevation_m = 0.0;  // runway profile at the threshold [m MSL]
  double heading_true_rad = 0.0;       // landing direction [rad]
  double width_m = 0.0;                // [m]
  double landing_distance_m = 0.0;     // threshold to the stop end [m]
  double aiming_point_m = 0.0;         // threshold to the aiming point marking (0: none)
  double papi_along_m = 0.0;           // threshold to abeam the PAPI (0: none) [m]
  int threshold_stripes = 0;
  ApproachCategory category = ApproachCategory::kPrecisionCatI;
  ApproachLighting approach_lighting = ApproachLighting::kNone;
};

struct Scene {
  explicit Scene(const SceneFrame& scene_frame) : frame(scene_frame) {}

  SceneFrame frame;
  double ground_elevation_m = 0.0;       // the ground sphere's elevation [m MSL]
  std::vector<SurfaceVertex> triangles;  // three vertices per triangle
  std::vector<LightPoint> lights;
  std::vector<RunwayEndInfo> runway_ends;
  std::vector<std::string> notes;  // what the builder assumed or left out

  /// The index of an end in runway_ends, or -1.
  int find_end(const std::string& designator) const;
  /// Lights of a role serving one end.
  std::vector<LightPoint> lights_of(int runway_end, LightRole role) const;
};

}  // namespace fedsim::visual
