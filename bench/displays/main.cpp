// fedsim-bench-displays: render time per frame of the cockpit displays (displays_model) and the
// head-up display (common/hud): the PFD and ND at 800x800 and the HUD at 800x600 (--pfd-size, --nd-size, --hud-size), on an ILS
// approach to KSFO 28R (localizer and glide slope captured, flight director and autopilot on,
// outer marker, SFO and OAK on the ND). Every frame moves the aircraft a little (pitch, bank,
// heading, speed, altitude), so that no two frames are alike.
//
// For each display it renders --frames frames after --warmup and reports the wall time of the
// render_*() call (steady_clock around it: drawing list, upload, draw, multisample resolve and
// read-back) and the time the renderer measures with the clock lent to it, as median, p99 and
// max. --png DIR writes the last frame of each as pfd.png, nd.png, hud.png, and
// hud_over_ksfo.png: the HUD composited over the image generator's picture of KSFO from the
// same eye (visual_model, the same ChannelConfig), its flight-path vector on the aiming point.
// The last line is one JSON object with every figure. Runs on OSMesa (llvmpipe, the CPU). A
// benchmark beside the federates (bench/): it composes two of them, as fedsim-visual --hud does.
#include "common/gl/egl_context.hpp"
#include "common/hud/composite.hpp"
#include "common/hud/hud_renderer.hpp"
#include "common/units/units.hpp"
#include "common/util/timing_summary.hpp"
#include "displays/model/display_renderer.hpp"
#include "visual/model/airport_scene.hpp"
#include "visual/model/renderer.hpp"
#include "visual/model/test/ksfo_runways.hpp"

#include <CLI/CLI.hpp>
#include <GeographicLib/Geodesic.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using fedsim::units::kDegToRad;
using fedsim::units::kFtToM;
using fedsim::units::kKtToMps;
using fedsim::units::kNmToM;
using namespace fedsim::displays;
using fedsim::picture::Image;
using Clock = std::chrono::steady_clock;

constexpr double kVariationRad = 13.0 * kDegToRad;  // KSFO, east (the ILS 28R course is 284 M)
constexpr double kPathRad = 3.0 * kDegToRad;
constexpr double kAimingPointM = 400.0;  // beyond the threshold (visual_model's scene)

// One summary for both benchmarks (common/util/timing_summary.hpp).
using Stats = fedsim::util::TimingSummary;
Stats stats_of(std::vector<double> ms) { return fedsim::util::summarize_ms(std::move(ms)); }

nlohmann::json to_json(const Stats& s) {
  return {{"median_ms", s.median_ms}, {"p99_ms", s.p99_ms}, {"max_ms", s.max_ms}};
}

// The approach at frame i: a slow wander about the 3 deg path, 5 NM out at 140 kt.
struct Approach {
  double distance_m, pitch_rad, roll_rad, heading_true_rad, ias_mps, height_m, vs_mps;
};

Approach approach_at(int i, double runway_heading_true_rad) {
  const double t = i / 60.0;
  Approach a;
  a.distance_m = 5.0 * kNmToM - 140.0 * kKtToMps * t;
  a.pitch_rad = (2.5 + 0.8 * std::sin(0.7 * t)) * kDegToRad;
  a.roll_rad = 4.0 * std::sin(0.5 * t) * kDegToRad;
  a.heading_true_rad = runway_heading_true_rad + 1.5 * std::sin(0.3 * t) * kDegToRad;
  a.ias_mps = (140.0 + 3.0 * std::sin(0.4 * t)) * kKtToMps;
  a.height_m = (a.distance_m + kAimingPointM) * std::tan(kPathRad);
  a.vs_mps = -140.0 * kKtToMps * std::sin(kPathRad);
  return a;
}

PfdInputs pfd_inputs(const Approach& a) {
  PfdInputs in;
  in.pitch_rad = a.pitch_rad;
  in.roll_rad = a.roll_rad;
  in.lateral_specific_force_mps2 = 0.4;
  in.heading_true_rad = a.heading_true_rad;
  in.heading_magnetic_rad = a.heading_true_rad - kVariationRad;
  in.ias_mps = a.ias_mps;
  in.ias_trend_mps = -2.5;
  in.altitude_m = a.height_m + 4.0;  // KSFO 28R threshold elevation 13 ft
  in.altitude_trend_m = a.vs_mps * 6.0;
  in.vertical_speed_mps = a.vs_mps;
  in.baro_setting_pa = 29.92 * fedsim::units::kInHgToPa;
  in.selected_speed_mps = 140.0 * kKtToMps;
  in.selected_altitude_m = 3000.0 * kFtToM;
  in.selected_heading_rad = 284.0 * kDegToRad;
  in.localizer = NavSignal::kValid;
  in.localizer_deviation_dots = 0.3 * std::sin(a.distance_m / 900.0);
  in.glideslope = NavSignal::kValid;
  in.glideslope_deviation_dots = -0.4;
  in.flight_director = {true, true, true, 2.8 * kDegToRad, 2.0 * kDegToRad};
  in.modes = {"MCP SPD", "", "VOR/LOC", "", "G/S", "", "CMD"};
  in.radio_altitude_m = a.height_m;
  in.marker = MarkerBeacon::kOuter;
  return in;
}

NdInputs nd_inputs(const Approach& a) {
  NdInputs in;
  in.heading_rad = a.heading_true_rad - kVariationRad;
  in.track_rad = in.heading_rad + 2.0 * kDegToRad;
  in.selected_heading_rad = 284.0 * kDegToRad;
  in.selected_course_rad = 284.0 * kDegToRad;
  in.course = NavSignal::kValid;
  in.course_is_localizer = true;
  in.course_ident = "ISFO";
  in.course_deviation_dots = 0.3 * std::sin(a.distance_m / 900.0);
  in.dme_valid = true;
  in.dme_distance_m = a.distance_m + 2500.0;
  in.bearing1 = {BearingSource::kVor, true, 320.0 * kDegToRad - in.heading_rad, "SFO"};
  in.bearing2 = {BearingSource::kAdf, false, 0.0, ""};  // not tuned: no pointer
  in.navaids = {{"SFO", NavaidKind::kVorDme, 320.0 * kDegToRad, 9.0 * kNmToM},
                {"OAK", NavaidKind::kVorDme, 20.0 * kDegToRad, 10.5 * kNmToM},
                {"KSFO", NavaidKind::kAirport, 284.0 * kDegToRad, 5.2 * kNmToM},
                {"KOAK", NavaidKind::kAirport, 350.0 * kDegToRad, 7.5 * kNmToM},
                {"OSI", NavaidKind::kVorDme, 215.0 * kDegToRad, 8.5 * kNmToM},
                {"PIRAT", NavaidKind::kDme, 250.0 * kDegToRad, 13.0 * kNmToM},
                {"LAF", NavaidKind::kNdb, 60.0 * kDegToRad, 16.0 * kNmToM}};
  in.range_nm = 20.0;
  in.ground_speed_mps = a.ias_mps - 8.0;
  in.true_airspeed_mps = a.ias_mps * 1.02;
  return in;
}

fedsim::hud::HudInputs hud_inputs(const Approach& a) {
  fedsim::hud::HudInputs in;
  in.pitch_rad = a.pitch_rad;
  in.roll_rad = a.roll_rad;
  in.heading_true_rad = a.heading_true_rad;
  in.magnetic_variation_rad = kVariationRad;
  const double v = a.ias_mps;
  in.velocity_ned_mps = {v * std::cos(kPathRad) * std::cos(a.heading_true_rad),
                         v * std::cos(kPathRad) * std::sin(a.heading_true_rad),
                         v * std::sin(kPathRad)};
  in.ias_mps = a.ias_mps;
  in.altitude_m = a.height_m + 4.0;
  in.vertical_speed_mps = a.vs_mps;
  in.flight_director = {true, true, true, 2.8 * kDegToRad, 2.0 * kDegToRad};
  return in;
}

bool parse_size(const std::string& text, int& w, int& h) {
  char x = 0;
  std::istringstream in(text);
  return static_cast<bool>(in >> w >> x >> h) && x == 'x' && w >= 16 && h >= 16 && w <= 4096 &&
         h <= 4096;
}

struct Measured {
  Stats wall, inner;
  std::size_t triangles = 0;
};

Measured measure(int warmup, int frames, const std::function<DisplayStats(int, fedsim::picture::Image&)>& render,
                 fedsim::picture::Image& image) {
  std::vector<double> wall, inner;
  Measured m;
  for (int i = 0; i < warmup + frames; ++i) {
    const auto start = Clock::now();
    const DisplayStats s = render(i, image);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (i >= warmup) {
      wall.push_back(ms);
      inner.push_back(s.render_time_ms);
      m.triangles = s.triangles;
    }
  }
  m.wall = stats_of(wall);
  m.inner = stats_of(inner);
  return m;
}

// The eye on the 28R approach (as fedsim-bench-visual places it), for the HUD-over-scene picture.
fedsim::visual::EyePose eye_on_approach(const fedsim::nav::RunwayEndRecord& end,
                                        const Approach& a) {
  const auto& earth = GeographicLib::Geodesic::WGS84();
  double lat = 0.0, lon = 0.0;
  earth.Direct(end.threshold.lat_rad / kDegToRad, end.threshold.lon_rad / kDegToRad,
               end.heading_true_rad / kDegToRad + 180.0, a.distance_m, lat, lon);
  fedsim::visual::EyePose p;
  p.lat_rad = lat * kDegToRad;
  p.lon_rad = lon * kDegToRad;
  p.alt_msl_m = end.threshold.elevation_m + a.height_m;
  p.phi_rad = a.roll_rad;
  p.theta_rad = a.pitch_rad;
  p.psi_rad = a.heading_true_rad;
  return p;
}

void write_hud_over_ksfo(const fedsim::view::ChannelConfig& channel, fedsim::hud::HudRenderer& huds,
                         const std::string& path) {
  using namespace fedsim::visual;
  const auto ends = test::ksfo_runway_ends();
  AirportSceneOptions options;
  RunwayEndOptions cat3;
  cat3.category = ApproachCategory::kPrecisionCatIIorIII;
  cat3.approach_lighting = ApproachLighting::kIcaoCatIIorIII;
  options.ends["28R"] = cat3;
  Renderer visual(build_airport_scene(ends, options));
  const auto& end28r =
      *std::find_if(ends.begin(), ends.end(), [](const auto& e) { return e.runway == "28R"; });
  // 1 NM out, wings level, on the path: the FPV falls on the aiming point.
  Approach a = approach_at(0, end28r.heading_true_rad);
  a.distance_m = 1.0 * kNmToM;
  a.height_m = (a.distance_m + kAimingPointM) * std::tan(kPathRad);
  a.roll_rad = 0.0;
  a.heading_true_rad = end28r.heading_true_rad;
  Environment environment;
  environment.sun_elevation_rad = 35.0 * kDegToRad;
  environment.sun_azimuth_rad = 200.0 * kDegToRad;
  fedsim::picture::Image scene, hud;
  visual.render(channel, eye_on_approach(end28r, a), environment, scene);
  huds.render(hud_inputs(a), channel, hud);
  fedsim::hud::composite_over(scene, hud);
  fedsim::picture::write_png(scene, path);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fedsim-bench-displays: PFD, ND and HUD render time (ILS approach, KSFO 28R)"};
  int frames = 60, warmup = 5, samples = DisplayRenderer::kDefaultSamples;
  std::string pfd_size = "800x800", nd_size = "800x800", hud_size = "800x600", png_dir;
  double hfov_deg = 48.0;
  app.add_option("--frames", frames, "frames measured per display")->check(CLI::Range(1, 100000));
  app.add_option("--warmup", warmup, "frames rendered first, not measured")
      ->check(CLI::Range(0, 1000));
  app.add_option("--pfd-size", pfd_size, "PFD picture WxH")->capture_default_str();
  app.add_option("--nd-size", nd_size, "ND picture WxH")->capture_default_str();
  app.add_option("--hud-size", hud_size, "HUD (centre channel) picture WxH")->capture_default_str();
  app.add_option("--hfov-deg", hfov_deg, "the channel's horizontal field of view [deg]")
      ->check(CLI::Range(1.0, 150.0));
  app.add_option("--samples", samples, "multisampling 1, 2 or 4")->check(CLI::IsMember({1, 2, 4}));
  app.add_option("--png", png_dir, "write pfd.png, nd.png, hud.png, hud_over_ksfo.png here");
  std::string gl = "osmesa";
  app.add_option("--gl", gl, "OpenGL context: osmesa, egl (a GPU's device, else Mesa surfaceless), auto")
      ->check(CLI::IsMember({"osmesa", "egl", "auto"}))->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    int pw = 0, ph = 0, nw = 0, nh = 0, hw = 0, hh = 0;
    if (!parse_size(pfd_size, pw, ph) || !parse_size(nd_size, nw, nh) ||
        !parse_size(hud_size, hw, hh)) {
      throw std::invalid_argument("a size is not WxH (16..4096)");
    }
    const auto ends = fedsim::visual::test::ksfo_runway_ends();
    const double runway_heading = std::find_if(ends.begin(), ends.end(), [](const auto& e) {
                                    return e.runway == "28R";
                                  })->heading_true_rad;
    std::string fallback;
    const fedsim::gl::GlBackend backend = *fedsim::gl::parse_gl_backend(gl);
    DisplayRenderer renderer(fedsim::gl::make_gl_context(backend, &fallback),
                             fedsim::symbology::default_font_paths(), samples);
    fedsim::hud::HudRenderer huds(fedsim::gl::make_gl_context(backend), fedsim::symbology::default_font_paths(),
                                  samples);
    if (!fallback.empty()) std::printf("--gl auto: %s\n", fallback.c_str());
    const auto steady_ns = [] {
      return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch())
          .count();
    };
    renderer.set_clock(steady_ns);
    huds.set_clock(steady_ns);
    fedsim::view::ChannelConfig channel;
    channel.width_px = hw;
    channel.height_px = hh;
    channel.horizontal_fov_rad = hfov_deg * kDegToRad;
    channel.vertical_fov_rad =
        2.0 * std::atan(std::tan(0.5 * channel.horizontal_fov_rad) * hh / hw);
    std::printf("fedsim-bench-displays: %s; %d frames each, %d samples\n",
                renderer.description().c_str(), frames, samples);

    fedsim::picture::Image pfd, nd, hud;
    const Measured mp = measure(
        warmup, frames,
        [&](int i, fedsim::picture::Image& image) {
          return renderer.render_pfd(pfd_inputs(approach_at(i, runway_heading)), pw, ph, image);
        },
        pfd);
    const Measured mn = measure(
        warmup, frames,
        [&](int i, fedsim::picture::Image& image) {
          return renderer.render_nd(nd_inputs(approach_at(i, runway_heading)), nw, nh, image);
        },
        nd);
    const Measured mh = measure(
        warmup, frames,
        [&](int i, fedsim::picture::Image& image) {
          return huds.render(hud_inputs(approach_at(i, runway_heading)), channel, image);
        },
        hud);

    nlohmann::json results = nlohmann::json::array();
    const struct {
      const char* name;
      const std::string& size;
      const Measured& m;
    } rows[] = {{"pfd", pfd_size, mp}, {"nd", nd_size, mn}, {"hud", hud_size, mh}};
    for (const auto& r : rows) {
      std::printf(
          "%-3s %-9s render_%s() median %6.2f ms  p99 %6.2f ms  max %6.2f ms  (%.0f frames/s)"
          "  [lent clock: median %.2f ms; %zu triangles]\n",
          r.name, r.size.c_str(), r.name, r.m.wall.median_ms, r.m.wall.p99_ms, r.m.wall.max_ms,
          1000.0 / r.m.wall.median_ms, r.m.inner.median_ms, r.m.triangles);
      results.push_back({{"display", r.name},
                         {"size", r.size},
                         {"render_call", to_json(r.m.wall)},
                         {"render_time", to_json(r.m.inner)},
                         {"triangles", r.m.triangles},
                         {"frames_per_s_at_median", 1000.0 / r.m.wall.median_ms}});
    }
    if (!png_dir.empty()) {
      std::filesystem::create_directories(png_dir);
      const std::filesystem::path dir(png_dir);
      fedsim::picture::write_png(pfd, (dir / "pfd.png").string());
      fedsim::picture::write_png(nd, (dir / "nd.png").string());
      fedsim::picture::write_png(hud, (dir / "hud.png").string());
      write_hud_over_ksfo(channel, huds, (dir / "hud_over_ksfo.png").string());
      std::printf("wrote pfd.png, nd.png, hud.png, hud_over_ksfo.png in %s\n", png_dir.c_str());
    }
    const nlohmann::json figures = {{"bench", "displays"},
                                    {"renderer", renderer.description()},
                                    {"samples", samples},
                                    {"frames", frames},
                                    {"results", results}};
    std::cout << figures.dump() << std::endl;
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "fedsim-bench-displays: " << e.what() << '\n';
    return 2;
  }
}
