// Shared helpers of the visual model's tests: eye poses on an approach computed straight from
// the runway records with GeographicLib (independently of the model's runway frames), pixel
// statistics, and where test pictures go.
#pragma once

#include "common/picture/image.hpp"
#include "common/units/units.hpp"
#include "visual/model/airport_scene.hpp"
#include "visual/model/eye_pose.hpp"
#include "visual/model/test/ksfo_runways.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace fedsim::visual::test {

using units::kDegToRad;

inline const nav::RunwayEndRecord& ksfo_end(const std::string& runway) {
  static const std::vector<nav::RunwayEndRecord> ends = ksfo_runway_ends();
  for (const auto& e : ends) {
    if (e.runway == runway) return e;
  }
  throw std::invalid_argument("no KSFO runway end " + runway);
}

/// The KSFO scene with 28R a CAT II/III end (its real ALSF-2 and centreline lights).
inline AirportSceneOptions ksfo_options() {
  AirportSceneOptions o;
  RunwayEndOptions cat3;
  cat3.category = ApproachCategory::kPrecisionCatIIorIII;
  cat3.approach_lighting = ApproachLighting::kIcaoCatIIorIII;
  o.ends["28R"] = cat3;
  return o;
}

/// An eye on the extended centreline of `end`, `before_threshold_m` before its threshold
/// (negative: past it), `height_m` above the threshold's elevation, looking along the landing
/// direction with pitch `pitch_rad`.
inline EyePose approach_eye(const nav::RunwayEndRecord& end, double before_threshold_m,
                            double height_m, double pitch_rad) {
  const auto& earth = GeographicLib::Geodesic::WGS84();
  double lat = 0.0, lon = 0.0, azimuth = 0.0;
  earth.Direct(end.threshold.lat_rad * units::kRadToDeg, end.threshold.lon_rad * units::kRadToDeg,
               end.heading_true_rad * units::kRadToDeg + 180.0, before_threshold_m, lat, lon,
               azimuth);
  EyePose p;
  p.lat_rad = lat * kDegToRad;
  p.lon_rad = lon * kDegToRad;
  p.alt_msl_m = end.threshold.elevation_m + height_m;
  p.psi_rad = end.heading_true_rad;
  p.theta_rad = pitch_rad;
  return p;
}

inline double luminance_at(const picture::Image& image, int column, int row) {
  return image.at(column, row).luminance();
}

/// Mean luminance (0..1) over a block of pixels, clipped to the image.
inline double mean_luminance(const picture::Image& image, int column0, int row0, int columns, int rows) {
  double sum = 0.0;
  int n = 0;
  for (int r = std::max(0, row0); r < std::min(image.height_px, row0 + rows); ++r) {
    for (int c = std::max(0, column0); c < std::min(image.width_px, column0 + columns); ++c) {
      sum += luminance_at(image, c, r);
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

/// Where test pictures are written: $FEDSIM_VISUAL_TEST_OUTPUT or <tmp>/fedsim_visual_tests.
inline std::filesystem::path output_dir() {
  const char* env = std::getenv("FEDSIM_VISUAL_TEST_OUTPUT");
  std::filesystem::path dir = env != nullptr
                                  ? std::filesystem::path(env)
                                  : std::filesystem::temp_directory_path() / "fedsim_visual_tests";
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace fedsim::visual::test
