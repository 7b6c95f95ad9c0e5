#include "visual/model/light_layout.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::visual {

namespace {

using units::kDegToRad;

constexpr float kRedFilter = 0.15f;     // Appendix 2: red = 0.15 x white
constexpr float kYellowFilter = 0.40f;  // Appendix 2: yellow = 0.4 x white
constexpr double kArcMinute = kDegToRad / 60.0;
// Inset lights' lens above the pavement: above the 3 cm the markings are drawn at, so that a
// centreline light on a centreline stripe is not hidden by the paint in the depth test.
constexpr double kInsetHeightM = 0.06;
constexpr double kElevatedHeightM = 0.35;

LightSite site(double along, double right, double height, LightRole role) {
  LightSite s;
  s.along_m = along;
  s.right_m = right;
  s.height_m = height;
  s.role = role;
  return s;
}

// Approach light: inset where it stands on the pavement (a displaced threshold), elevated
// 0.5 m otherwise.
LightSite approach_site(const EndLightingInput& in, double along, double right, LightRole role,
                        const Eigen::Vector3f& colour, float intensity_cd) {
  LightSite s = site(along, right, along >= in.runway_start_m ? kInsetHeightM : 0.5, role);
  s.colour_rgb = colour;
  s.intensity_cd = intensity_cd;
  s.elevation_setting_rad = 6.0 * kDegToRad;
  s.beam_half_width_h_rad = static_cast<float>(10.0 * kDegToRad);
  s.beam_half_width_v_rad = static_cast<float>(7.0 * kDegToRad);
  return s;
}

void add_row(std::vector<LightSite>& out, const EndLightingInput& in, double along,
             const std::vector<double>& rights, LightRole role, const Eigen::Vector3f& colour,
             float intensity_cd) {
  for (double r : rights) out.push_back(approach_site(in, along, r, role, colour, intensity_cd));
}

// Lights from `from` to `to` (both included) at most `spacing` apart, evenly.
std::vector<double> evenly(double from, double to, double spacing) {
  const int gaps = std::max(1, static_cast<int>(std::ceil((to - from) / spacing - 1e-9)));
  std::vector<double> out;
  for (int i = 0; i <= gaps; ++i) out.push_back(from + (to - from) * i / gaps);
  return out;
}

// Symmetric crossbar lights at +-(from, from + step, ... <= to).
std::vector<double> crossbar(double from, double to, double step) {
  std::vector<double> out;
  for (double y = from; y <= to + 1e-9; y += step) {
    out.push_back(y);
    out.push_back(-y);
  }
  return out;
}

void cat_i_approach(std::vector<LightSite>& out, const EndLightingInput& in) {
  const Eigen::Vector3f white = aviation_white();
  for (int k = 1; k <= 30; ++k) {
    const double along = -30.0 * k;
    std::vector<double> sources{0.0};
    if (k > 20)
      sources = {-1.5, 0.0, 1.5};
    else if (k > 10)
      sources = {-0.75, 0.75};
    add_row(out, in, along, sources, LightRole::kApproachCentreline, white, 20000.0f);
  }
  add_row(out, in, -300.0, crossbar(4.0, 15.0, 2.75), LightRole::kApproachCrossbar, white,
          20000.0f);
}

void cat_ii_approach(std::vector<LightSite>& out, const EndLightingInput& in) {
  const Eigen::Vector3f white = aviation_white();
  const std::vector<double> barrette{-2.0, -1.0, 0.0, 1.0, 2.0};
  for (int k = 1; k <= 30; ++k) {
    add_row(out, in, -30.0 * k, barrette, LightRole::kApproachCentreline, white, 20000.0f);
  }
  const double inner = 0.5 * in.touchdown_zone_gauge_m;
  const std::vector<double> side{inner,  inner + 1.5,  inner + 3.0,
                                 -inner, -inner - 1.5, -inner - 3.0};
  for (int k = 1; k <= 9; ++k) {
    add_row(out, in, -30.0 * k, side, LightRole::kApproachSideRow, aviation_red(), 5000.0f);
  }
  add_row(out, in, -150.0, crossbar(3.5, inner - 1.5, 1.5), LightRole::kApproachCrossbar, white,
          20000.0f);
  add_row(out, in, -300.0, crossbar(3.5, 15.0, 1.5), LightRole::kApproachCrossbar, white, 20000.0f);
}

}  // namespace

Eigen::Vector3f aviation_white() { return {1.0f, 0.96f, 0.86f}; }
Eigen::Vector3f aviation_red() { return {1.0f, 0.12f, 0.08f}; }
Eigen::Vector3f aviation_green() { return {0.25f, 1.0f, 0.6f}; }
Eigen::Vector3f aviation_yellow() { return {1.0f, 0.78f, 0.12f}; }

std::vector<LightSite> approach_lights(const EndLightingInput& in) {
  std::vector<LightSite> out;
  if (in.approach == ApproachLighting::kIcaoCatI) cat_i_approach(out, in);
  if (in.approach == ApproachLighting::kIcaoCatIIorIII) cat_ii_approach(out, in);
  return out;
}

std::vector<LightSite> edge_lights(const EndLightingInput& in,
                                   const std::vector<double>& along_positions_m) {
  std::vector<LightSite> out;
  const double caution_m = std::min(600.0, (in.threshold_to_stop_end_m - in.runway_start_m) / 3.0);
  for (double along : along_positions_m) {
    Eigen::Vector3f colour = aviation_white();
    float intensity = 10000.0f;
    if (along < 0.0) {
      colour = aviation_red();
      intensity *= kRedFilter;
    } else if (along > in.threshold_to_stop_end_m - caution_m) {
      colour = aviation_yellow();
      intensity *= kYellowFilter;
    }
    for (double side : {-1.0, 1.0}) {
      LightSite s =
          site(along, side * (0.5 * in.width_m + 0.6), kElevatedHeightM, LightRole::kRunwayEdge);
      s.colour_rgb = colour;
      s.intensity_cd = intensity;
      s.elevation_setting_rad = 3.5 * kDegToRad;
      s.toe_in_rad = 3.5 * kDegToRad;
      s.beam_half_width_h_rad = static_cast<float>(7.0 * kDegToRad);
      s.beam_half_width_v_rad = static_cast<float>(5.0 * kDegToRad);
      out.push_back(s);
    }
  }
  return out;
}

std::vector<LightSite> threshold_lights(const EndLightingInput& in) {
  std::vector<LightSite> out;
  for (double right : evenly(-0.5 * in.width_m, 0.5 * in.width_m, 3.0)) {
    LightSite s = site(0.0, right, kElevatedHeightM, LightRole::kThreshold);
    s.colour_rgb = aviation_green();
    s.intensity_cd = 10000.0f;
    s.elevation_setting_rad = 5.5 * kDegToRad;
    s.toe_in_rad = 3.5 * kDegToRad;
    s.beam_half_width_h_rad = static_cast<float>(7.0 * kDegToRad);
    s.beam_half_width_v_rad = static_cast<float>(5.5 * kDegToRad);
    out.push_back(s);
  }
  return out;
}

std::vector<LightSite> runway_end_lights(const EndLightingInput& in) {
  std::vector<LightSite> out;
  const double spacing = std::min(6.0, in.width_m / 5.0);  // at least 6 lights
  for (double right : evenly(-0.5 * in.width_m, 0.5 * in.width_m, spacing)) {
    LightSite s = site(in.threshold_to_stop_end_m, right, kElevatedHeightM, LightRole::kRunwayEnd);
    s.colour_rgb = aviation_red();
    s.intensity_cd = 2500.0f;
    s.elevation_setting_rad = 2.5 * kDegToRad;
    s.beam_half_width_h_rad = static_cast<float>(6.0 * kDegToRad);
    s.beam_half_width_v_rad = static_cast<float>(4.0 * kDegToRad);
    out.push_back(s);
  }
  return out;
}

bool has_centreline_lights(const EndLightingInput& in) {
  return in.category == ApproachCategory::kPrecisionCatIIorIII ||
         (in.category == ApproachCategory::kPrecisionCatI && in.width_m > 50.0);
}

std::vector<LightSite> centreline_lights(const EndLightingInput& in) {
  std::vector<LightSite> out;
  if (!has_centreline_lights(in)) return out;
  const bool cat_ii = in.category == ApproachCategory::kPrecisionCatIIorIII;
  const double spacing = cat_ii ? 15.0 : 30.0;
  const float white_cd = cat_ii ? 2500.0f : 5000.0f;
  const double stop = in.threshold_to_stop_end_m;
  int index = 0;
  for (double along = spacing; along < stop - 0.5 * spacing; along += spacing, ++index) {
    const double to_go = stop - along;
    LightSite s = site(along, 0.0, kInsetHeightM, LightRole::kRunwayCentreline);
    const bool red = to_go <= 300.0 || (to_go <= 900.0 && index % 2 == 1);
    s.colour_rgb = red ? aviation_red() : aviation_white();
    s.intensity_cd = red ? white_cd * kRedFilter : white_cd;
    s.elevation_setting_rad = 3.0 * kDegToRad;
    s.beam_half_width_h_rad = static_cast<float>(5.0 * kDegToRad);
    s.beam_half_width_v_rad = static_cast<float>(4.0 * kDegToRad);
    out.push_back(s);
  }
  return out;
}

std::vector<LightSite> touchdown_zone_lights(const EndLightingInput& in) {
  std::vector<LightSite> out;
  if (in.category != ApproachCategory::kPrecisionCatIIorIII) return out;
  const double inner = 0.5 * in.touchdown_zone_gauge_m;
  const double last = std::min(900.0, 0.5 * in.threshold_to_stop_end_m);
  for (double along = 30.0; along <= last + 1e-9; along += 30.0) {
    for (double r : {inner, inner + 1.5, inner + 3.0, -inner, -inner - 1.5, -inner - 3.0}) {
      LightSite s = site(along, r, kInsetHeightM, LightRole::kTouchdownZone);
      s.colour_rgb = aviation_white();
      s.intensity_cd = 5000.0f;
      s.elevation_setting_rad = 4.0 * kDegToRad;
      s.toe_in_rad = 4.0 * kDegToRad;
      s.beam_half_width_h_rad = static_cast<float>(5.0 * kDegToRad);
      s.beam_half_width_v_rad = static_cast<float>(4.0 * kDegToRad);
      out.push_back(s);
    }
  }
  return out;
}

std::vector<LightSite> papi_units(const EndLightingInput& in) {
  std::vector<LightSite> out;
  if (!in.papi) return out;
  const double offsets_arcmin[4] = {30.0, 10.0, -10.0, -30.0};
  for (int k = 0; k < 4; ++k) {
    LightSite s =
        site(in.papi_along_m, -(0.5 * in.width_m + 15.0 + 9.0 * k), 0.9, LightRole::kPapi);
    s.beam = BeamKind::kPapi;
    s.colour_rgb = aviation_white();
    s.intensity_cd = 15000.0f;
    s.papi_transition_rad = static_cast<float>(in.glide_path_rad + offsets_arcmin[k] * kArcMinute);
    s.beam_half_width_h_rad = static_cast<float>(10.0 * kDegToRad);
    s.beam_half_width_v_rad = static_cast<float>(8.0 * kDegToRad);
    out.push_back(s);
  }
  return out;
}

}  // namespace fedsim::visual
