// NASA check-case reference data loader.
#include "nasa_reference.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <regex>
#include <stdexcept>

#include "common/geodesy/wgs84.hpp"
#include "common/math/rotation.hpp"

namespace fedsim::flight::nasa {

namespace {
constexpr double kFt = units::kFtToM;
constexpr double kDeg = units::kDegToRad;

struct Conversion {
  const char* nasa_column;
  const char* channel;
  double scale;
};

// NASA column -> SI channel (the lat/lon arc lengths are added separately).
constexpr Conversion kConversions[] = {
    {"altitudeMsl_ft", "altitude_m", kFt},
    {"latitude_deg", "lat_rad", kDeg},
    {"longitude_deg", "lon_rad", kDeg},
    {"feVelocity_ft_s_X", "v_north_mps", kFt},
    {"feVelocity_ft_s_Y", "v_east_mps", kFt},
    {"feVelocity_ft_s_Z", "v_down_mps", kFt},
    {"eulerAngle_deg_Roll", "phi_rad", kDeg},
    {"eulerAngle_deg_Pitch", "theta_rad", kDeg},
    {"eulerAngle_deg_Yaw", "psi_rad", kDeg},
    {"bodyAngularRateWrtEi_deg_s_Roll", "p_radps", kDeg},
    {"bodyAngularRateWrtEi_deg_s_Pitch", "q_radps", kDeg},
    {"bodyAngularRateWrtEi_deg_s_Yaw", "r_radps", kDeg},
};
}  // namespace

TimeHistory NasaReference::read_nasa_csv(const std::string& path) {
  const TimeHistory raw = TimeHistory::read_csv(path);
  std::vector<std::string> names;
  std::vector<const std::vector<double>*> sources;
  std::vector<double> scales;
  for (const Conversion& c : kConversions) {
    if (!raw.has(c.nasa_column)) continue;
    names.emplace_back(c.channel);
    sources.push_back(&raw.channel(c.nasa_column));
    scales.push_back(c.scale);
  }
  const bool has_position = raw.has("latitude_deg") && raw.has("longitude_deg");
  if (has_position) {
    names.emplace_back("north_m");
    names.emplace_back("east_m");
  }
  TimeHistory history(names);
  const double lat0 = has_position ? raw.channel("latitude_deg").front() * kDeg : 0.0;
  for (std::size_t k = 0; k < raw.times().size(); ++k) {
    std::vector<double> values;
    for (std::size_t i = 0; i < sources.size(); ++i) values.push_back((*sources[i])[k] * scales[i]);
    if (has_position) {
      values.push_back(raw.channel("latitude_deg")[k] * kDeg * wgs84::kSemiMajorAxisM);
      values.push_back(raw.channel("longitude_deg")[k] * kDeg * wgs84::kSemiMajorAxisM *
                       std::cos(lat0));
    }
    history.append(raw.times()[k], values);
  }
  return history;
}

NasaReference NasaReference::load(const std::string& case_folder) {
  NasaReference reference;
  const std::regex pattern(R"(Atmos_\d\d_(sim_\d\d)\.csv)");
  std::map<std::string, std::string> files;  // sorted by run name
  for (const auto& entry : std::filesystem::directory_iterator(case_folder)) {
    std::smatch match;
    const std::string file = entry.path().filename().string();
    if (std::regex_match(file, match, pattern)) files[match[1]] = entry.path().string();
  }
  if (files.empty()) throw std::runtime_error("no NASA runs in " + case_folder);
  for (const auto& [name, path] : files) reference.runs_.push_back({name, read_nasa_csv(path)});
  return reference;
}

Envelope NasaReference::envelope(const std::string& channel, double t_s, bool is_angle,
                                 double angle_reference_rad) const {
  Envelope e{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0};
  for (const NasaRun& run : runs_) {
    if (!run.history.has(channel) || excluded(run.name, channel)) continue;
    double value = is_angle ? run.history.angle_at(channel, t_s) : run.history.at(channel, t_s);
    if (is_angle) value = angle_reference_rad + wrap_pi(value - angle_reference_rad);
    e.low = std::min(e.low, value);
    e.high = std::max(e.high, value);
    ++e.runs;
  }
  return e;
}

void NasaReference::exclude(const std::string& run_name, const std::string& channel) {
  const bool known = std::any_of(runs_.begin(), runs_.end(),
                                 [&](const NasaRun& run) { return run.name == run_name; });
  if (!known) throw std::invalid_argument("no NASA run " + run_name + " to exclude");
  exclusions_.emplace_back(run_name, channel);
}

bool NasaReference::excluded(const std::string& run_name, const std::string& channel) const {
  return std::find(exclusions_.begin(), exclusions_.end(), std::make_pair(run_name, channel)) !=
         exclusions_.end();
}

}  // namespace fedsim::flight::nasa
