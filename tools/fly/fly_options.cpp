#include "tools/fly/fly_options.hpp"
#include "common/util/cli_checks.hpp"
#include "io/model/input_profile.hpp"

#include <cmath>
#include <stdexcept>

namespace fedsim::fly {

void add_fly_options(CLI::App& app, FlyOptions& o) {
  add_flight_options(app, o.flight);
  app.add_option("--inputs", o.inputs, "scripted input profile (CSV of control channels)");
  app.add_flag("--inputs-relative", o.inputs_relative,
               "add the profile's values to the start (trimmed) controls (--controls relative)");
  app.add_option("--pilot", o.pilot,
                 "a closed-loop test pilot: stall-entry (wings level, airspeed down at --entry-rate-kt-s at "
                 "--pilot-throttle until the stall is identified, then the recovery; over --inputs if given)")
      ->check(CLI::IsMember({"stall-entry"}));
  app.add_option("--entry-rate-kt-s", o.stall_entry.entry_rate_kt_per_s,
                 "stall entry: airspeed decrease [kt/s]")
      ->check(fedsim::util::FiniteRange(0.1, 5.0))
      ->capture_default_str();
  app.add_option("--pilot-throttle", o.stall_entry.throttle, "stall entry: throttle of every engine, 0 (idle)..1")
      ->check(fedsim::util::FiniteRange(0.0, 1.0))
      ->capture_default_str();
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
  if (!o.pilot.empty() && o.flight.controls == "relative") {
    throw std::invalid_argument("--pilot flies absolute controls: drop --inputs-relative / --controls relative");
  }
  if (!o.pilot.empty() && o.flight.autopilot) {
    throw std::invalid_argument("--pilot and --autopilot both fly the aircraft: give one");
  }
  io::check(o.stall_entry);
  if (o.duration_s * o.rate_hz > 1.0e8) {
    throw std::invalid_argument("--duration x --rate is more than 1e8 frames");
  }
}

io::ControlInputs cockpit_at_start(const flight::AircraftControls& start, bool relative_controls) {
  using io::Channel;
  io::ControlInputs c = io::default_controls();
  const double primaries = relative_controls ? 0.0 : 1.0;
  c[Channel::kElevator] = primaries * start.elevator;
  c[Channel::kAileron] = primaries * start.aileron;
  c[Channel::kRudder] = primaries * start.rudder;
  c[Channel::kElevatorTrim] = start.elevator_trim;
  c[Channel::kAileronTrim] = start.aileron_trim;
  c[Channel::kRudderTrim] = start.rudder_trim;
  for (int e = 0; e < io::kMaxEngines; ++e) {
    const auto i = static_cast<std::size_t>(e);
    c[static_cast<Channel>(static_cast<int>(Channel::kThrottle1) + e)] = primaries * start.throttle[i];
    c[static_cast<Channel>(static_cast<int>(Channel::kMixture1) + e)] = start.mixture[i];
    c[static_cast<Channel>(static_cast<int>(Channel::kPropeller1) + e)] = start.propeller[i];
  }
  c[Channel::kFlaps] = start.flaps;
  c[Channel::kSpeedbrake] = start.speedbrake;
  c[Channel::kGearDown] = start.gear_down ? 1.0 : 0.0;
  c[Channel::kBrakeLeft] = start.brake_left;
  c[Channel::kBrakeRight] = start.brake_right;
  c[Channel::kNosewheelSteering] = start.steering;
  c.clamp();
  return c;
}

std::unique_ptr<io::InputSource> make_fly_input_source(const FlyOptions& o, const io::StallEntryPilot** pilot) {
  std::vector<std::unique_ptr<io::InputSource>> layers;
  if (!o.inputs.empty()) layers.push_back(std::make_unique<io::InputProfile>(io::InputProfile::load_file(o.inputs)));
  if (o.pilot == "stall-entry") {
    auto stall_entry = std::make_unique<io::StallEntryPilot>(o.stall_entry);
    if (pilot) *pilot = stall_entry.get();
    layers.push_back(std::move(stall_entry));
  }
  if (layers.empty()) return nullptr;
  if (layers.size() == 1) return std::move(layers.front());
  return std::make_unique<io::LayeredSource>(std::move(layers));
}

}  // namespace fedsim::fly
