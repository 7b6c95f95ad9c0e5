#include "visual/model/sky_model.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace fedsim::visual {

namespace {

struct SkyRow {
  double sun_elevation_deg;
  float zenith[3];
  float horizon[3];
  float sunward[3];
  float ambient;           // grey level of a white horizontal surface
  double log10_luminance;  // log10 of the background luminance [cd/m^2]
};

// Sun elevation ascending. Night rows tinted blue (scotopic look), day rows neutral.
// clang-format off
constexpr std::array<SkyRow, 13> kRows = {{
    {-90.0, {0.004f, 0.005f, 0.012f}, {0.008f, 0.009f, 0.016f}, {0.008f, 0.009f, 0.016f}, 0.006f, -3.0},
    {-18.0, {0.004f, 0.005f, 0.012f}, {0.008f, 0.009f, 0.016f}, {0.008f, 0.009f, 0.016f}, 0.006f, -3.0},
    {-12.0, {0.008f, 0.012f, 0.030f}, {0.015f, 0.018f, 0.035f}, {0.020f, 0.018f, 0.030f}, 0.010f, -2.0},
    {-8.0, {0.020f, 0.030f, 0.080f}, {0.040f, 0.045f, 0.080f}, {0.100f, 0.060f, 0.060f}, 0.025f, -0.5},
    {-4.0, {0.060f, 0.090f, 0.200f}, {0.130f, 0.120f, 0.170f}, {0.450f, 0.250f, 0.150f}, 0.080f, 1.0},
    {-2.0, {0.100f, 0.150f, 0.320f}, {0.220f, 0.200f, 0.260f}, {0.700f, 0.400f, 0.220f}, 0.150f, 2.0},
    {0.0, {0.160f, 0.240f, 0.450f}, {0.380f, 0.360f, 0.420f}, {0.900f, 0.550f, 0.300f}, 0.280f, 2.7},
    {2.0, {0.200f, 0.320f, 0.580f}, {0.520f, 0.530f, 0.580f}, {0.950f, 0.700f, 0.450f}, 0.420f, 3.2},
    {5.0, {0.220f, 0.380f, 0.680f}, {0.620f, 0.660f, 0.720f}, {0.900f, 0.800f, 0.650f}, 0.550f, 3.5},
    {10.0, {0.220f, 0.400f, 0.740f}, {0.680f, 0.740f, 0.820f}, {0.850f, 0.850f, 0.820f}, 0.680f, 3.7},
    {20.0, {0.220f, 0.420f, 0.780f}, {0.720f, 0.790f, 0.880f}, {0.800f, 0.850f, 0.900f}, 0.820f, 3.85},
    {40.0, {0.210f, 0.410f, 0.790f}, {0.730f, 0.810f, 0.900f}, {0.780f, 0.840f, 0.910f}, 0.950f, 3.95},
    {90.0, {0.200f, 0.400f, 0.800f}, {0.740f, 0.820f, 0.920f}, {0.740f, 0.820f, 0.920f}, 1.000f, 4.0},
}};
// clang-format on

Eigen::Vector3f lerp(const float a[3], const float b[3], float t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

}  // namespace

SkyState sky_state(double sun_elevation_rad) {
  if (std::isnan(sun_elevation_rad)) throw std::invalid_argument("sky_state: sun elevation NaN");
  const double e = std::clamp(sun_elevation_rad * units::kRadToDeg, -90.0, 90.0);
  std::size_t i = 0;
  while (i + 2 < kRows.size() && kRows[i + 1].sun_elevation_deg < e) ++i;
  const SkyRow& a = kRows[i];
  const SkyRow& b = kRows[i + 1];
  const auto t =
      static_cast<float>((e - a.sun_elevation_deg) / (b.sun_elevation_deg - a.sun_elevation_deg));
  SkyState s;
  s.zenith_rgb = lerp(a.zenith, b.zenith, t);
  s.horizon_rgb = lerp(a.horizon, b.horizon, t);
  s.horizon_sunward_rgb = lerp(a.sunward, b.sunward, t);
  const float grey = a.ambient + t * (b.ambient - a.ambient);
  // Moonlight and twilight look bluish, daylight neutral to slightly warm.
  const float day = std::clamp(static_cast<float>((e + 6.0) / 12.0), 0.0f, 1.0f);
  const Eigen::Vector3f tint = Eigen::Vector3f(0.75f, 0.85f, 1.15f) * (1.0f - day) +
                               Eigen::Vector3f(1.0f, 1.0f, 0.97f) * day;
  s.ambient_rgb = grey * tint;
  const float sun_up = std::clamp(static_cast<float>((e + 1.0) / 2.0), 0.0f, 1.0f);
  const float white = std::clamp(static_cast<float>(e / 15.0), 0.0f, 1.0f);
  s.sun_rgb = sun_up * (Eigen::Vector3f(1.0f, 0.55f, 0.25f) * (1.0f - white) +
                        Eigen::Vector3f(1.0f, 0.97f, 0.90f) * white);
  s.background_luminance_cd_per_m2 =
      std::pow(10.0, a.log10_luminance + t * (b.log10_luminance - a.log10_luminance));
  return s;
}

double light_threshold_lux(double background_luminance_cd_per_m2) {
  if (std::isnan(background_luminance_cd_per_m2)) {
    throw std::invalid_argument("light_threshold_lux: background luminance NaN");
  }
  const double log_b = std::log10(std::clamp(background_luminance_cd_per_m2, 1.0, 1.0e5));
  return std::pow(10.0, 0.57 * log_b + 0.05 * log_b * log_b - 6.66);
}

}  // namespace fedsim::visual
