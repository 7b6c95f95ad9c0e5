// fedsim-bench-flight: batch speed of the flight model alone (no DDS, no I/O in the loop).
//
// For each aircraft (C172, 737), frame rate (50, 100, 400 Hz) and integrator (Euler, AB2,
// AB3, AB4, RK4): trim in cruise, then step the model hands-off for a fixed simulated time and
// time it with the monotonic clock. Reports microseconds per step, steps per second, simulated
// seconds per wall-clock second and heap allocations per step (operator new is counted: a step
// must not allocate). Each figure is the best of several repeats (this VM's neighbours steal
// CPU at random; the best is the model's own speed). The last line is one JSON object with
// every figure. Target: the C172 at >= 250,000 steps/s with a single-evaluation integrator.
#include <CLI/CLI.hpp>
#include "common/util/build_paths.hpp"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/util/cli_checks.hpp"
#include "common/units/units.hpp"
#include "common/util/allocation_counter.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/trim.hpp"


using namespace fedsim;
using namespace fedsim::flight;
using json = nlohmann::json;

namespace {


struct Options {
  double simulated_s = 120.0;  // per measurement
  int repeats = 3;
  std::string earth = "flat";
};

struct Aircraft {
  std::string name;
  std::string pack;
  TrimRequest cruise;
};

std::vector<Aircraft> aircraft() {
  TrimRequest c172;
  c172.position = {28.0 * units::kDegToRad, -90.0 * units::kDegToRad, 4000.0 * units::kFtToM};
  c172.heading_rad = 90.0 * units::kDegToRad;
  c172.airspeed_mps = 100.0 * units::kKtToMps;
  TrimRequest b737 = c172;
  b737.position.alt_m = 30000.0 * units::kFtToM;
  b737.airspeed_mps = 440.0 * units::kKtToMps;
  b737.controls.gear_down = false;
  return {{"c172", fedsim::util::data_dir() + "/aircraft/c172.yaml", c172},
          {"b737", fedsim::util::data_dir() + "/aircraft/b737.yaml", b737}};
}

struct Figure {
  double us_per_step = 0.0;
  double steps_per_s = 0.0;
  double realtime_factor = 0.0;  // simulated seconds per wall-clock second
  double allocations_per_step = 0.0;
  double altitude_change_m = 0.0;  // sanity: the trimmed aircraft flew level
};

Figure measure(const Aircraft& a, IntegrationMethod method, double rate_hz, const Options& o) {
  AircraftModel::Options options;
  options.integrator = method;
  options.earth = o.earth == "wgs84" ? EarthModelKind::kWgs84 : EarthModelKind::kFlat;
  AircraftModel model(load_aircraft_pack(a.pack), options);
  const TrimResult trim = Trim(model).solve(a.cruise);
  if (!trim.converged) throw std::runtime_error(a.name + ": trim failed: " + trim.reason);
  const AircraftInitialConditions start = trim.initial_conditions;
  const long steps = std::lround(o.simulated_s * rate_hz);
  const double dt = 1.0 / rate_hz;
  Figure best;
  best.us_per_step = 1e300;
  for (int r = 0; r < o.repeats; ++r) {
    model.reset(start, trim.controls);
    const fedsim::util::AllocationScope allocations;
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < steps; ++i) model.step(dt);
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double us = wall_s / static_cast<double>(steps) * 1e6;
    if (us < best.us_per_step) {
      best.us_per_step = us;
      best.steps_per_s = 1e6 / us;
      best.realtime_factor = best.steps_per_s / rate_hz;
    }
    best.allocations_per_step = std::max(
        best.allocations_per_step, static_cast<double>(allocations.allocations()) /
                                       static_cast<double>(steps));
    best.altitude_change_m = model.outputs().geodetic.alt_m - start.position.alt_m;
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"fedsim-bench-flight: batch speed of the flight model (steps per second)"};
  app.add_option("--simulated-s", o.simulated_s, "simulated seconds per measurement")
      ->check(fedsim::util::FiniteRange(1.0, 36000.0))
      ->capture_default_str();
  app.add_option("--repeats", o.repeats, "repeats per figure (the best is kept)")
      ->check(fedsim::util::FiniteRange(1, 100))
      ->capture_default_str();
  app.add_option("--earth", o.earth, "flat | wgs84")
      ->check(CLI::IsMember({"flat", "wgs84"}))
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const std::vector<IntegrationMethod> methods = {IntegrationMethod::kEuler,
                                                  IntegrationMethod::kAb2, IntegrationMethod::kAb3,
                                                  IntegrationMethod::kAb4, IntegrationMethod::kRk4};
  json results = json::object();
  results["earth"] = o.earth;
  results["simulated_s"] = o.simulated_s;
  results["repeats"] = o.repeats;
  std::printf("%-5s %7s %-6s %12s %12s %14s %11s %10s\n", "pack", "rate_hz", "method",
              "us_per_step", "steps_per_s", "sim_s_per_s", "allocs/step", "dalt_m");
  try {
    for (const Aircraft& a : aircraft()) {
      for (const double rate : {50.0, 100.0, 400.0}) {
        for (const IntegrationMethod method : methods) {
          const Figure f = measure(a, method, rate, o);
          const std::string m(to_string(method));
          std::printf("%-5s %7.0f %-6s %12.3f %12.0f %14.0f %11.1f %10.3f\n", a.name.c_str(), rate,
                      m.c_str(), f.us_per_step, f.steps_per_s, f.realtime_factor,
                      f.allocations_per_step, f.altitude_change_m);
          std::fflush(stdout);
          json& entry = results[a.name][std::to_string(static_cast<int>(rate)) + "_hz"][m];
          entry["us_per_step"] = f.us_per_step;
          entry["steps_per_s"] = f.steps_per_s;
          entry["simulated_s_per_wall_s"] = f.realtime_factor;
          entry["allocations_per_step"] = f.allocations_per_step;
          entry["altitude_change_m"] = f.altitude_change_m;
        }
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "fedsim-bench-flight: " << e.what() << "\n";
    return 1;
  }
  const double c172_euler = results["c172"]["100_hz"]["euler"]["steps_per_s"].get<double>();
  const double c172_ab2 = results["c172"]["100_hz"]["ab2"]["steps_per_s"].get<double>();
  results["target_steps_per_s"] = 250000;
  results["c172_single_evaluation_steps_per_s"] = std::max(c172_euler, c172_ab2);
  results["target_met"] = std::max(c172_euler, c172_ab2) >= 250000.0;
  std::cout << results.dump() << std::endl;
  return 0;
}
