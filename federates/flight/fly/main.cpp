// fedsim-fly: the flight model in batch mode. Starts an aircraft from an initial-condition file
// or a trim, flies it for a given time at a given frame rate with controls from a scripted
// profile, and writes one CSV row per frame. No DDS, no wall clock in the loop.
//
// Exit codes: 0 done; 2 bad input (unknown pack or option, bad profile or IC file: nothing is
// written); 3 the trim did not converge (its JSON and the reason are printed, nothing written);
// 1 a failure while running (the partial CSV is removed).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "common/util/config_node.hpp"
#include "flight/fly/batch_flight.hpp"
#include "flight/fly/fly_options.hpp"
#include "io/model/input_profile.hpp"

using namespace fedsim;
using namespace fedsim::flight;

namespace {
constexpr int kBadInput = 2;
constexpr int kTrimFailed = 3;
constexpr int kRunFailed = 1;

struct Prepared {
  std::unique_ptr<AircraftModel> model;
  StartState start;
  std::optional<io::InputProfile> profile;
};

Turbulence::Severity severity_named(const std::string& name) {
  if (name == "light") return Turbulence::Severity::kLight;
  if (name == "moderate") return Turbulence::Severity::kModerate;
  if (name == "severe") return Turbulence::Severity::kSevere;
  return Turbulence::Severity::kNone;
}

/// Reads and checks everything the run needs; throws for bad input.
Prepared prepare(const FlyOptions& o) {
  if (o.inputs_relative && o.inputs.empty()) {
    throw std::invalid_argument("--inputs-relative needs --inputs");
  }
  Prepared p;
  p.model = std::make_unique<AircraftModel>(load_aircraft_pack(resolve_pack_path(o.aircraft)),
                                            model_options(o));
  if (!o.inputs.empty()) p.profile = io::InputProfile::load_file(o.inputs);
  p.start = establish_start(o.start, *p.model);
  if (!o.turbulence.empty()) {
    WeatherSettings weather = p.model->weather();
    weather.turbulence = severity_named(o.turbulence);
    p.model->set_weather(weather);
  }
  return p;
}

int fly(const FlyOptions& o, Prepared& p) {
  CsvRecorder recorder(p.model->engine_count(), p.model->pack().landing_gear.contacts.size());
  recorder.open(o.out);
  BatchFlight flight(*p.model, p.start.controls, std::move(p.profile), o.inputs_relative);
  BatchFlight::Progress progress;
  if (!o.quiet) {
    progress = [](double simulated_s, double total_s) {
      std::fprintf(stderr, "fedsim-fly: %.1f of %.1f s simulated (%.0f %%)\n", simulated_s, total_s,
                   100.0 * simulated_s / total_s);
    };
  }
  const auto start = std::chrono::steady_clock::now();
  flight.run(o.duration_s, o.rate_hz, o.output_every, recorder, progress);
  recorder.close();
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet) {
    std::fprintf(stderr, "fedsim-fly: %.1f s flown in %.2f s (%.0fx real time) -> %s\n",
                 o.duration_s, wall_s, o.duration_s / std::max(wall_s, 1e-9), o.out.c_str());
  }
  if (p.model->outputs().numerical_fault) {
    std::fprintf(stderr, "fedsim-fly: warning: the model dropped a non-finite step\n");
  }
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  FlyOptions options;
  CLI::App app{"fedsim-fly: fly an aircraft pack in batch mode and write a CSV time history"};
  add_fly_options(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kBadInput;  // --help is not an error
  }

  Prepared prepared;
  try {
    prepared = prepare(options);
  } catch (const std::exception& e) {
    std::cerr << "fedsim-fly: " << e.what() << "\n";
    return kBadInput;
  }
  if (prepared.start.trim) {
    std::cout << trim_json(*prepared.start.trim) << std::endl;
    if (!prepared.start.trim->converged) {
      std::cerr << "fedsim-fly: trim failed: " << prepared.start.trim->reason << "\n";
      return kTrimFailed;
    }
  }
  try {
    return fly(options, prepared);
  } catch (const std::exception& e) {
    std::cerr << "fedsim-fly: " << e.what() << "\n";
    std::error_code ignored;
    std::filesystem::remove(options.out, ignored);
    return kRunFailed;
  }
}
