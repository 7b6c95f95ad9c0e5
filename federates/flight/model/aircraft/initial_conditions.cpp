// Initial conditions: validation and the strict YAML initial-condition file reader.
#include "flight/model/aircraft/initial_conditions.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "common/util/config_node.hpp"

namespace fedsim::flight {

namespace {
using util::ConfigNode;

constexpr int kFormatVersion = 1;

void require_finite(const Eigen::Vector3d& v, const char* field) {
  if (!v.allFinite())
    throw std::invalid_argument(std::string("initial conditions: ") + field + " must be finite");
}

// Exactly one of two alternative keys (e.g. alt_m / alt_ft).
std::string one_of(const ConfigNode& node, const std::string& a, const std::string& b) {
  const bool has_a = node.has(a), has_b = node.has(b);
  if (has_a == has_b) {
    node.fail(has_a ? "give either '" + a + "' or '" + b + "', not both"
                    : "one of '" + a + "' or '" + b + "' is required");
  }
  return has_a ? a : b;
}

GeodeticPosition read_position(const ConfigNode& node) {
  node.reject_unknown_keys({"lat_deg", "lon_deg", "alt_m", "alt_ft"});
  GeodeticPosition p;
  p.lat_rad = node.number("lat_deg", -90.0, 90.0) * units::kDegToRad;
  p.lon_rad = node.number("lon_deg", -180.0, 360.0) * units::kDegToRad;
  const std::string alt_key = one_of(node, "alt_m", "alt_ft");
  const double scale = alt_key == "alt_m" ? 1.0 : units::kFtToM;
  p.alt_m = node.number(alt_key, -1000.0 / scale, 100000.0 / scale) * scale;
  return p;
}

EulerAngles read_attitude(const ConfigNode& node) {
  node.reject_unknown_keys({"phi", "theta", "psi"});
  EulerAngles a;
  a.phi_rad = node.number_or("phi", 0.0, -180.0, 180.0) * units::kDegToRad;
  a.theta_rad = node.number_or("theta", 0.0, -90.0, 90.0) * units::kDegToRad;
  a.psi_rad = node.number_or("psi", 0.0, -360.0, 360.0) * units::kDegToRad;
  return a;
}

// A per-engine lever: one number for every engine or a list of up to four.
void read_levers(const ConfigNode& node, const std::string& key,
                 std::array<double, AircraftControls::kMaxEngines>& levers) {
  if (!node.has(key)) return;
  const ConfigNode value = node.child(key);
  if (value.yaml().IsSequence()) {
    const std::vector<double> list = value.as_numbers();
    if (list.empty() || list.size() > levers.size()) {
      value.fail("expected 1 to " + std::to_string(levers.size()) + " numbers");
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (list[i] < 0.0 || list[i] > 1.0) value.fail("levers are 0..1");
      levers[i] = list[i];
    }
    return;
  }
  levers.fill(node.number(key, 0.0, 1.0));
}

AircraftControls read_controls(const ConfigNode& node) {
  node.reject_unknown_keys({"elevator", "aileron", "rudder", "elevator_trim", "aileron_trim",
                            "rudder_trim", "throttle", "mixture", "propeller", "flaps",
                            "speedbrake", "spoilers", "gear_down", "brake_left", "brake_right",
                            "brakes", "steering"});
  AircraftControls c;
  c.elevator = node.number_or("elevator", 0.0, -1.0, 1.0);
  c.aileron = node.number_or("aileron", 0.0, -1.0, 1.0);
  c.rudder = node.number_or("rudder", 0.0, -1.0, 1.0);
  c.elevator_trim = node.number_or("elevator_trim", 0.0, -1.0, 1.0);
  c.aileron_trim = node.number_or("aileron_trim", 0.0, -1.0, 1.0);
  c.rudder_trim = node.number_or("rudder_trim", 0.0, -1.0, 1.0);
  read_levers(node, "throttle", c.throttle);
  read_levers(node, "mixture", c.mixture);
  read_levers(node, "propeller", c.propeller);
  c.flaps = node.number_or("flaps", 0.0, 0.0, 1.0);
  c.speedbrake = node.number_or("speedbrake", 0.0, 0.0, 1.0);
  c.spoilers = node.number_or("spoilers", 0.0, 0.0, 1.0);
  c.gear_down = node.boolean_or("gear_down", true);
  const double brakes = node.number_or("brakes", 0.0, 0.0, 1.0);
  c.brake_left = node.number_or("brake_left", brakes, 0.0, 1.0);
  c.brake_right = node.number_or("brake_right", brakes, 0.0, 1.0);
  c.steering = node.number_or("steering", 0.0, -1.0, 1.0);
  return c;
}

WindProfile::Params read_wind(const ConfigNode& node) {
  WindProfile::Params wind;
  for (const ConfigNode& layer : node.items()) {
    layer.reject_unknown_keys({"alt_m", "speed_mps", "from_deg"});
    const double alt_m = layer.number("alt_m", -1000.0, 100000.0);
    if (!wind.altitude_m.empty() && !(alt_m > wind.altitude_m.back())) {
      layer.fail_at("alt_m", "layers must be in strictly increasing altitude");
    }
    wind.altitude_m.push_back(alt_m);
    wind.speed_mps.push_back(layer.number("speed_mps", 0.0, 200.0));
    wind.from_direction_rad.push_back(layer.number("from_deg", 0.0, 360.0) * units::kDegToRad);
  }
  return wind;
}

WindShear::Params read_microburst(const ConfigNode& node) {
  node.reject_unknown_keys({"centre_north_m", "centre_east_m", "downdraft_radius_m",
                            "max_outflow_mps", "outflow_height_scale_m",
                            "boundary_layer_height_scale_m"});
  WindShear::Params p;
  p.centre_north_m = node.number("centre_north_m");
  p.centre_east_m = node.number("centre_east_m");
  p.downdraft_radius_m = node.number_or("downdraft_radius_m", p.downdraft_radius_m, 1.0, 1e5);
  p.max_outflow_mps = node.number("max_outflow_mps", 0.0, 100.0);
  p.outflow_height_scale_m =
      node.number_or("outflow_height_scale_m", p.outflow_height_scale_m, 1.0, 1e4);
  p.boundary_layer_height_scale_m =
      node.number_or("boundary_layer_height_scale_m", p.boundary_layer_height_scale_m, 0.1, 1e4);
  if (!(p.outflow_height_scale_m > p.boundary_layer_height_scale_m)) {
    node.fail("outflow_height_scale_m must exceed boundary_layer_height_scale_m");
  }
  return p;
}

Turbulence::Severity read_severity(const ConfigNode& node) {
  const std::string s = node.choice("turbulence", {"none", "light", "moderate", "severe"});
  if (s == "light") return Turbulence::Severity::kLight;
  if (s == "moderate") return Turbulence::Severity::kModerate;
  if (s == "severe") return Turbulence::Severity::kSevere;
  return Turbulence::Severity::kNone;
}

WeatherSettings read_weather(const ConfigNode& node) {
  node.reject_unknown_keys({"temperature_offset_k", "sea_level_pressure_pa", "wind", "microburst",
                            "turbulence", "turbulence_seed"});
  WeatherSettings w;
  w.atmosphere.sea_level_temperature_offset_k =
      node.number_or("temperature_offset_k", 0.0, -60.0, 60.0);
  w.atmosphere.sea_level_pressure_pa =
      node.number_or("sea_level_pressure_pa", us1976::kSeaLevelPressure, 85000.0, 110000.0);
  if (node.has("wind")) w.wind = read_wind(node.child("wind"));
  if (node.has("microburst")) w.microburst = read_microburst(node.child("microburst"));
  if (node.has("turbulence")) w.turbulence = read_severity(node);
  if (node.has("turbulence_seed")) {
    w.turbulence_seed = static_cast<std::uint64_t>(node.integer("turbulence_seed", 0));
  }
  return w;
}

InitialConditionFile read_file(const ConfigNode& root) {
  root.reject_unknown_keys({"fedsim_initial_conditions", "position", "velocity_ned_mps",
                            "velocity_body_mps", "attitude_deg", "body_rates_dps",
                            "body_rates_relative_to", "engines_running", "settle_engines",
                            "fuel_kg", "controls", "weather", "runway_elevation_m"});
  const int version = root.integer("fedsim_initial_conditions");
  if (version != kFormatVersion) {
    root.fail_at("fedsim_initial_conditions",
                 "unsupported format version " + std::to_string(version));
  }
  InitialConditionFile file;
  AircraftInitialConditions& ic = file.initial;
  ic.position = read_position(root.child("position"));
  const std::string velocity_key = one_of(root, "velocity_ned_mps", "velocity_body_mps");
  const std::vector<double> v = root.numbers(velocity_key, 3);
  ic.velocity_mps = Eigen::Vector3d(v[0], v[1], v[2]);
  ic.velocity_frame = velocity_key == "velocity_ned_mps"
                          ? AircraftInitialConditions::VelocityFrame::kNed
                          : AircraftInitialConditions::VelocityFrame::kBody;
  if (root.has("attitude_deg")) ic.attitude = read_attitude(root.child("attitude_deg"));
  if (root.has("body_rates_dps")) {
    const std::vector<double> w = root.numbers("body_rates_dps", 3);
    ic.omega_body_radps = Eigen::Vector3d(w[0], w[1], w[2]) * units::kDegToRad;
  }
  ic.omega_relative_to_earth =
      root.choice_or("body_rates_relative_to", {"earth", "inertial"}, "earth") == "earth";
  ic.engines_running = root.boolean_or("engines_running", true);
  ic.settle_engines = root.boolean_or("settle_engines", true);
  if (root.has("fuel_kg")) {
    ic.fuel_kg = root.numbers("fuel_kg");
    for (double kg : ic.fuel_kg) {
      if (kg < 0.0) root.fail_at("fuel_kg", "fuel must be >= 0");
    }
  }
  if (root.has("controls")) file.controls = read_controls(root.child("controls"));
  if (root.has("weather")) file.weather = read_weather(root.child("weather"));
  if (root.has("runway_elevation_m")) {
    file.runway_elevation_m = root.number("runway_elevation_m", -1000.0, 10000.0);
  }
  try {
    file.weather.validate();
  } catch (const std::invalid_argument& e) {
    root.fail_at("weather", e.what());
  }
  return file;
}
}  // namespace

void AircraftInitialConditions::validate() const {
  if (!std::isfinite(position.lat_rad) || std::abs(position.lat_rad) > std::numbers::pi / 2) {
    throw std::invalid_argument("initial conditions: latitude must be within +-90 deg");
  }
  if (!std::isfinite(position.lon_rad) || !std::isfinite(position.alt_m)) {
    throw std::invalid_argument("initial conditions: longitude and altitude must be finite");
  }
  require_finite(velocity_mps, "velocity_mps");
  require_finite(omega_body_radps, "omega_body_radps");
  if (!std::isfinite(attitude.phi_rad) || !std::isfinite(attitude.theta_rad) ||
      !std::isfinite(attitude.psi_rad)) {
    throw std::invalid_argument("initial conditions: Euler angles must be finite");
  }
  for (double kg : fuel_kg) {
    if (!(kg >= 0.0) || !std::isfinite(kg)) {
      throw std::invalid_argument("initial conditions: fuel_kg must be finite and >= 0");
    }
  }
}

InitialConditionFile load_initial_condition_file(const std::string& path) {
  return read_file(ConfigNode::load_file(path));
}

InitialConditionFile parse_initial_condition_file(const std::string& yaml_text,
                                                  const std::string& origin) {
  return read_file(ConfigNode::parse(yaml_text, origin));
}

}  // namespace fedsim::flight
