#include "flight/fly/fly_options.hpp"
#include "common/util/cli_checks.hpp"

#include <cmath>
#include <stdexcept>

namespace fedsim::flight {

void add_fly_options(CLI::App& app, FlyOptions& o) {
  add_flight_options(app, o.flight);
  app.add_option("--inputs", o.inputs, "scripted input profile (CSV of control channels)");
  app.add_flag("--inputs-relative", o.inputs_relative,
               "add the profile's values to the start (trimmed) controls (--controls relative)");
  app.add_option("--duration", o.duration_s, "simulated time [s]")
      ->required()
      ->check(fedsim::util::FiniteRange(0.0, 1.0e6));
  app.add_option("--rate", o.rate_hz, "frame rate [Hz]")
      ->required()
      ->check(fedsim::util::FiniteRange(1.0, 100000.0));
  app.add_option("--out", o.out_dir, "output folder: one CSV per topic, as fedsim record writes")
      ->required();
  app.add_option("--output-every", o.output_every, "record every Nth frame (the first and last always)")
      ->check(fedsim::util::FiniteRange(1, 1000000))
      ->capture_default_str();
  app.add_flag("--quiet", o.quiet, "no progress messages on stderr");
}

void check_fly_options(FlyOptions& o) {
  // NaN and infinities are refused by the options' checks (common/util/cli_checks.hpp).
  if (o.inputs_relative && o.inputs.empty()) {
    throw std::invalid_argument("--inputs-relative needs --inputs");
  }
  if (o.inputs_relative) o.flight.controls = "relative";
  if (o.duration_s * o.rate_hz > 1.0e8) {
    throw std::invalid_argument("--duration x --rate is more than 1e8 frames");
  }
}

}  // namespace fedsim::flight
