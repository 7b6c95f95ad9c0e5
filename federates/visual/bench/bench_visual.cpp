// fedsim-bench-visual: render time per frame of the image generator's model (visual_model) for
// the KSFO scene seen from the 28R approach (CAT II/III: ALSF-2-like approach lights, PAPI,
// edge, centreline and touchdown-zone lights; 4 runways with their Annex 14 markings).
//
// The eye flies down the 3 deg path from 3 NM (--distance-nm) at 70 m/s, one frame every 1/60 s, so
// that no two frames are alike. For each picture size it renders --frames frames after --warmup,
// and reports per frame the wall time of Renderer::render() (steady_clock around the call: set-up,
// draw and read-back into an Image), the render time the renderer measures with the clock lent
// to it (clear to image in memory) and when its draws were issued, as median, p99 and max, and
// the frame rate the median allows. --png writes the last frame of the last size. The last line is
// one JSON object with every figure. Runs on OSMesa (llvmpipe, the CPU): LP_NUM_THREADS sets its
// rasteriser threads (default: the cores).
#include "common/gl/egl_context.hpp"
#include "common/units/units.hpp"
#include "common/util/timing_summary.hpp"
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
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using fedsim::units::kDegToRad;
using namespace fedsim::visual;
using Clock = std::chrono::steady_clock;

// One summary for both benchmarks (common/util/timing_summary.hpp).
using Stats = fedsim::util::TimingSummary;
Stats stats_of(std::vector<double> ms) { return fedsim::util::summarize_ms(std::move(ms)); }

nlohmann::json to_json(const Stats& s) {
  return {{"median_ms", s.median_ms},
          {"p99_ms", s.p99_ms},
          {"max_ms", s.max_ms},
          {"mean_ms", s.mean_ms}};
}

// The eye `distance_m` before the 28R threshold on a 3 deg path to the aiming point (400 m in).
EyePose approach_eye(const fedsim::nav::RunwayEndRecord& end, double distance_m) {
  const auto& earth = GeographicLib::Geodesic::WGS84();
  double lat = 0.0, lon = 0.0;
  earth.Direct(end.threshold.lat_rad / kDegToRad, end.threshold.lon_rad / kDegToRad,
               end.heading_true_rad / kDegToRad + 180.0, distance_m, lat, lon);
  EyePose p;
  p.lat_rad = lat * kDegToRad;
  p.lon_rad = lon * kDegToRad;
  p.alt_msl_m = end.threshold.elevation_m + (distance_m + 400.0) * std::tan(3.0 * kDegToRad);
  p.psi_rad = end.heading_true_rad;
  p.theta_rad = -2.0 * kDegToRad;
  return p;
}

bool parse_size(const std::string& text, int& w, int& h) {
  char x = 0;
  std::istringstream in(text);
  return static_cast<bool>(in >> w >> x >> h) && x == 'x' && w >= 16 && h >= 16 && w <= 8192 &&
         h <= 8192;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fedsim-bench-visual: image generator render time (KSFO, 28R approach)"};
  int frames = 60, warmup = 5, samples = 1;
  std::vector<std::string> sizes{"800x600", "1280x720"};
  std::string png;
  double visibility_m = 30000.0, sun_elevation_deg = 35.0, hfov_deg = 48.0, distance_nm = 3.0;
  app.add_option("--frames", frames, "frames measured per size")->check(CLI::Range(1, 100000));
  app.add_option("--warmup", warmup, "frames rendered first, not measured")
      ->check(CLI::Range(0, 1000));
  app.add_option("--size", sizes, "picture sizes WxH")->capture_default_str();
  app.add_option("--samples", samples, "multisampling 1, 2 or 4")->check(CLI::IsMember({1, 2, 4}));
  app.add_option("--visibility-m", visibility_m, "meteorological visibility [m]")
      ->check(CLI::Range(10.0, 1.0e6));
  app.add_option("--sun-elevation-deg", sun_elevation_deg, "sun elevation [deg]")
      ->check(CLI::Range(-90.0, 90.0));
  app.add_option("--hfov-deg", hfov_deg, "horizontal field of view [deg]")
      ->check(CLI::Range(1.0, 150.0));
  app.add_option("--distance-nm", distance_nm, "start before the 28R threshold [NM]")
      ->check(CLI::Range(0.2, 20.0));
  app.add_option("--png", png, "write the last frame of the last size to this PNG");
  std::string gl = "osmesa";
  app.add_option("--gl", gl, "OpenGL context: osmesa, egl (a GPU's device, else Mesa surfaceless), auto")
      ->check(CLI::IsMember({"osmesa", "egl", "auto"}))->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    const auto ends = fedsim::visual::test::ksfo_runway_ends();
    AirportSceneOptions options;
    RunwayEndOptions cat3;
    cat3.category = ApproachCategory::kPrecisionCatIIorIII;
    cat3.approach_lighting = ApproachLighting::kIcaoCatIIorIII;
    options.ends["28R"] = cat3;
    const auto build_start = Clock::now();
    Scene scene = build_airport_scene(ends, options);
    const double build_ms =
        std::chrono::duration<double, std::milli>(Clock::now() - build_start).count();
    const std::size_t triangles = scene.triangles.size() / 3, lights = scene.lights.size();
    std::string fallback;
    Renderer renderer(std::move(scene), fedsim::gl::make_gl_context(*fedsim::gl::parse_gl_backend(gl), &fallback));
    if (!fallback.empty()) std::printf("--gl auto: %s\n", fallback.c_str());
    renderer.set_clock([] {
      return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch())
          .count();
    });
    const auto& end28r =
        *std::find_if(ends.begin(), ends.end(), [](const auto& e) { return e.runway == "28R"; });

    Environment environment;
    environment.visibility_m = visibility_m;
    environment.sun_elevation_rad = sun_elevation_deg * kDegToRad;
    environment.sun_azimuth_rad = 200.0 * kDegToRad;
    std::printf("fedsim-bench-visual: %s\n", renderer.description().c_str());
    std::printf(
        "KSFO scene: %zu triangles, %zu lights, built in %.1f ms; %d frames per size, "
        "samples %d\n",
        triangles, lights, build_ms, frames, samples);

    nlohmann::json results = nlohmann::json::array();
    fedsim::picture::Image image;
    for (const std::string& size : sizes) {
      int w = 0, h = 0;
      if (!parse_size(size, w, h)) throw std::invalid_argument("--size '" + size + "': not WxH");
      fedsim::view::ChannelConfig channel;
      channel.width_px = w;
      channel.height_px = h;
      channel.samples = samples;
      channel.horizontal_fov_rad = hfov_deg * kDegToRad;
      channel.vertical_fov_rad =
          2.0 * std::atan(std::tan(0.5 * channel.horizontal_fov_rad) * h / w);
      std::vector<double> wall_ms, inner_ms, submit_ms;
      for (int i = 0; i < warmup + frames; ++i) {
        const double distance_m = distance_nm * fedsim::units::kNmToM - 70.0 / 60.0 * i;
        const EyePose eye = approach_eye(end28r, distance_m);
        const auto start = Clock::now();
        const RenderStats s = renderer.render(channel, eye, environment, image);
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (i >= warmup) {
          wall_ms.push_back(ms);
          inner_ms.push_back(s.render_time_ms);
          submit_ms.push_back(s.submit_time_ms);
        }
      }
      const Stats wall = stats_of(wall_ms), inner = stats_of(inner_ms),
                  submit = stats_of(submit_ms);
      std::printf(
          "%5dx%-5d render() median %7.2f ms  p99 %7.2f ms  max %7.2f ms  (%.1f frames/s)"
          "  [inside: %.2f ms, draws issued after %.2f ms]\n",
          w, h, wall.median_ms, wall.p99_ms, wall.max_ms, 1000.0 / wall.median_ms, inner.median_ms,
          submit.median_ms);
      results.push_back({{"size", size},
                         {"render_call", to_json(wall)},
                         {"render_time", to_json(inner)},
                         {"submit_time", to_json(submit)},
                         {"frames_per_s_at_median", 1000.0 / wall.median_ms}});
    }
    if (!png.empty()) {
      fedsim::picture::write_png(image, png);
      std::printf("wrote %s\n", png.c_str());
    }
    const nlohmann::json figures = {{"bench", "visual"},
                                    {"renderer", renderer.description()},
                                    {"scene",
                                     {{"airport", "KSFO"},
                                      {"triangles", triangles},
                                      {"lights", lights},
                                      {"build_ms", build_ms}}},
                                    {"samples", samples},
                                    {"frames", frames},
                                    {"results", results}};
    std::cout << figures.dump() << std::endl;
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "fedsim-bench-visual: " << e.what() << '\n';
    return 2;
  }
}
