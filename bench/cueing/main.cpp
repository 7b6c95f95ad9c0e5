// fedsim-bench-cueing: step times of the motion platform (classical washout, workspace limiter,
// inverse kinematics, jack actuators, forward kinematics for monitoring) and of the three-axis
// control loader (sub-stepped at >= 1 kHz inside each frame), alone (no DDS), with the
// control loader's achieved inner-loop rate (sub-steps per simulated second, and per wall
// second: how far above real time the inner loop runs on this machine). Back to back in the
// same run, the C172's flight-model step (RK4) as the baseline the figures are quoted against
// (benchmarking.md: absolute times here say more about the neighbours than about the code).
// Each figure is the best of several repeats. The last line is one JSON object.
#include <CLI/CLI.hpp>
#include "common/util/build_paths.hpp"
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "common/units/units.hpp"
#include "common/util/cli_checks.hpp"
#include "control_loading/model/control_loading.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/trim.hpp"
#include "motion/model/motion_platform.hpp"

using namespace fedsim;
using json = nlohmann::json;

namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Best microseconds per call of `step` over `repeats` runs of `calls` calls.
template <class Step>
double best_us(int repeats, int calls, Step&& step) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    const double t0 = now_s();
    for (int i = 0; i < calls; ++i) step(i);
    best = std::min(best, (now_s() - t0) / calls * 1e6);
  }
  return best;
}

/// The motion platform engaged and cueing a 1 Hz sway and a 0.3 Hz surge of specific force.
double motion_step_us(double dt, int repeats, int calls) {
  motion::MotionPlatform platform(motion::MotionPlatformParameters{}, dt);
  platform.engage();
  motion::MotionInputs in;
  for (int i = 0; i < static_cast<int>(10.0 / dt); ++i) platform.step(in);  // rise to neutral
  return best_us(repeats, calls, [&](int i) {
    const double t = i * dt;
    in.specific_force_eye_body_mps2 = {1.5 * std::sin(2.0 * M_PI * 0.3 * t), 1.0 * std::sin(2.0 * M_PI * t), -9.80665};
    in.omega_body_radps = {0.1 * std::sin(2.0 * M_PI * 0.5 * t), 0.05 * std::cos(2.0 * M_PI * 0.4 * t), 0.0};
    platform.step(in);
  });
}

struct LoaderFigures {
  double frame_us = 0.0;
  int substeps = 0;
  double substep_s = 0.0;
};

/// The control loader engaged, a simulated pilot moving the column and wheel in a slow sine.
LoaderFigures loader_step_us(double dt, int repeats, int calls) {
  control_loading::ControlLoading loader{control_loading::ControlLoadingParameters{}};
  control_loading::ControlLoadingInputs in;
  in.pilot_source = control_loading::PilotSource::kSimulatedPilot;
  in.qbar_pa = 2500.0;
  in.alpha_rad = 0.05;
  loader.engage();
  LoaderFigures f;
  f.frame_us = best_us(repeats, calls, [&](int i) {
    const double t = i * dt;
    in.axes[0].pilot_target_norm = 0.5 * std::sin(2.0 * M_PI * 0.5 * t);
    in.axes[1].pilot_target_norm = 0.4 * std::sin(2.0 * M_PI * 0.3 * t);
    loader.step(in, dt);
  });
  f.substeps = loader.outputs().substeps;
  f.substep_s = loader.outputs().substep_s;
  return f;
}

double flight_step_us(double dt, int repeats, int calls) {
  flight::AircraftModel::Options options;
  options.integrator = IntegrationMethod::kRk4;
  flight::AircraftModel model(flight::load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/c172.yaml"), options);
  flight::TrimRequest r;
  r.kind = flight::TrimKind::kLevel;
  r.position = {28.0 * units::kDegToRad, -90.0 * units::kDegToRad, 4000.0 * units::kFtToM};
  r.heading_rad = 90.0 * units::kDegToRad;
  r.airspeed_mps = 100.0 * units::kKtToMps;
  flight::Trim(model).solve(r);
  return best_us(repeats, calls, [&](int) { model.step(dt); });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fedsim-bench-cueing: motion and control-loading step times, inner-loop rate"};
  double rate_hz = 50.0;
  int repeats = 5;
  double simulated_s = 60.0;
  app.add_option("--rate", rate_hz, "frame rate [Hz]")->check(util::FiniteRange(10, 1000))->capture_default_str();
  app.add_option("--repeats", repeats, "repeats (the best is reported)")->check(util::FiniteRange(1, 100))->capture_default_str();
  app.add_option("--seconds", simulated_s, "simulated seconds per repeat")->check(util::FiniteRange(1, 3600))->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  const double dt = 1.0 / rate_hz;
  const int calls = static_cast<int>(simulated_s * rate_hz);
  std::printf("fedsim-bench-cueing: %.0f Hz frames, %d frames per repeat, best of %d\n", rate_hz, calls, repeats);
  const double flight_us = flight_step_us(dt, repeats, calls);
  const double motion_us = motion_step_us(dt, repeats, calls);
  const LoaderFigures loader = loader_step_us(dt, repeats, calls);
  const double inner_hz = loader.substeps / dt;
  const double inner_wall_hz = loader.substeps / (loader.frame_us * 1e-6);
  std::printf("flight model (C172, RK4)  %8.2f us/frame  (baseline)\n", flight_us);
  std::printf("motion platform           %8.2f us/frame  %.2f x the flight step, %.2f %% of the frame\n", motion_us,
              motion_us / flight_us, motion_us / (dt * 1e6) * 100.0);
  std::printf("control loading           %8.2f us/frame  %.2f x the flight step, %.2f %% of the frame; "
              "%d sub-steps of %.3f ms: inner loop %.0f Hz simulated, %.0f Hz of wall time (%.0f x real time)\n",
              loader.frame_us, loader.frame_us / flight_us, loader.frame_us / (dt * 1e6) * 100.0, loader.substeps,
              loader.substep_s * 1e3, inner_hz, inner_wall_hz, inner_wall_hz / inner_hz);
  json j = {{"rate_hz", rate_hz},
            {"flight_step_us", flight_us},
            {"motion_step_us", motion_us},
            {"control_loading_step_us", loader.frame_us},
            {"control_loading_substeps", loader.substeps},
            {"control_loading_inner_hz", inner_hz},
            {"control_loading_inner_wall_hz", inner_wall_hz},
            {"motion_vs_flight", motion_us / flight_us},
            {"control_loading_vs_flight", loader.frame_us / flight_us}};
  std::printf("%s\n", j.dump().c_str());
  return 0;
}
