#include "tools/qtg/channels.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/csv/csv_reader.hpp"

namespace fedsim::qtg {
namespace {

constexpr double kMpsPerKt = 1852.0 / 3600.0;
constexpr double kMPerFt = 0.3048;
constexpr double kDegPerRad = 180.0 / M_PI;
constexpr double kNPerLbf = 4.4482216152605;

/// How one channel is computed from one state row (columns by name via `col`).
struct Derivation {
  ChannelInfo info;
  std::vector<std::string> columns;  // state CSV columns it reads, in argument order
  std::function<double(const std::vector<double>&)> value;
};

const std::vector<Derivation>& derivations() {
  using V = const std::vector<double>&;
  static const std::vector<Derivation> table = {
      {{"tas_kt", "true airspeed"}, {"air.tas_mps"}, [](V v) { return v[0] / kMpsPerKt; }},
      {{"cas_kt", "calibrated airspeed"}, {"air.cas_mps"}, [](V v) { return v[0] / kMpsPerKt; }},
      {{"ground_speed_kt", "ground speed"}, {"ground_speed_mps"},
       [](V v) { return v[0] / kMpsPerKt; }},
      {{"alt_ft", "CG altitude above MSL"}, {"altitude_msl_m"}, [](V v) { return v[0] / kMPerFt; }},
      {{"height_agl_ft", "CG height above the terrain"}, {"height_agl_m"},
       [](V v) { return v[0] / kMPerFt; }},
      {{"climb_rate_fpm", "rate of climb"}, {"climb_rate_mps"},
       [](V v) { return v[0] / kMPerFt * 60.0; }},
      {{"pitch_deg", "pitch attitude theta"}, {"theta_rad"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"roll_deg", "bank angle phi"}, {"phi_rad"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"heading_deg", "true heading psi"}, {"psi_rad"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"alpha_deg", "angle of attack"}, {"air.alpha_rad"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"beta_deg", "sideslip angle"}, {"air.beta_rad"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"p_dps", "roll rate"}, {"omega_body_radps[0]"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"q_dps", "pitch rate"}, {"omega_body_radps[1]"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"r_dps", "yaw rate"}, {"omega_body_radps[2]"}, [](V v) { return v[0] * kDegPerRad; }},
      {{"nz_g", "normal load factor"}, {"load_factor_z"}, [](V v) { return v[0]; }},
      {{"north_ft", "distance flown north"}, {"north_m"}, [](V v) { return v[0] / kMPerFt; }},
      {{"east_ft", "distance flown east"}, {"east_m"}, [](V v) { return v[0] / kMPerFt; }},
      {{"elevator", "elevator command (+1 stick forward)"}, {"controls.elevator"},
       [](V v) { return v[0]; }},
      {{"aileron", "aileron command (+1 stick right)"}, {"controls.aileron"},
       [](V v) { return v[0]; }},
      {{"rudder", "rudder command (+1 right pedal)"}, {"controls.rudder"},
       [](V v) { return v[0]; }},
      {{"throttle", "engine 1 throttle 0..1"}, {"controls.throttle[0]"},
       [](V v) { return v[0]; }},
      {{"elevator_deg", "elevator deflection (trailing edge down +)"}, {"elevator_rad"},
       [](V v) { return v[0] * kDegPerRad; }},
      {{"thrust_lbf", "total thrust"}, {"total_thrust_n"}, [](V v) { return v[0] / kNPerLbf; }},
      {{"on_ground", "1 while any gear carries weight"}, {"on_ground"}, [](V v) { return v[0]; }},
  };
  return table;
}

}  // namespace

const std::vector<ChannelInfo>& known_channels() {
  static const std::vector<ChannelInfo> infos = [] {
    std::vector<ChannelInfo> out;
    for (const auto& d : derivations()) out.push_back(d.info);
    out.push_back({"distance_ft", "horizontal distance from the start point"});
    return out;
  }();
  return infos;
}

bool is_known_channel(const std::string& name) {
  const auto& all = known_channels();
  return std::any_of(all.begin(), all.end(), [&](const ChannelInfo& c) { return c.name == name; });
}

std::string channel_unit(const std::string& name) {
  static const std::set<std::string> units = {"kt", "ft", "deg", "dps", "fpm", "g",
                                              "s",  "m",  "lbf", "n"};
  const auto underscore = name.rfind('_');
  if (underscore == std::string::npos) return "1";
  const std::string suffix = name.substr(underscore + 1);
  return units.count(suffix) ? suffix : "1";
}

Channels channels_from_state_csv(const std::string& path) {
  auto reader = csv::CsvReader::open(path);
  const auto time_col = reader.column("sim_time_s");
  std::vector<std::vector<std::size_t>> cols;
  for (const auto& d : derivations()) {
    std::vector<std::size_t> idx;
    for (const auto& c : d.columns) idx.push_back(reader.column(c));
    cols.push_back(std::move(idx));
  }
  Channels out;
  csv::CsvRow row;
  std::vector<double> args;
  double north0 = 0, east0 = 0;
  bool first = true;
  while (reader.next(row)) {
    const double t = row.number(time_col);
    for (std::size_t i = 0; i < derivations().size(); ++i) {
      args.clear();
      for (auto c : cols[i]) args.push_back(row.number(c));
      auto& s = out[derivations()[i].info.name];
      s.t.push_back(t);
      s.x.push_back(derivations()[i].value(args));
    }
    const double n = out["north_ft"].x.back(), e = out["east_ft"].x.back();
    if (first) north0 = n, east0 = e, first = false;
    auto& d = out["distance_ft"];
    d.t.push_back(t);
    d.x.push_back(std::hypot(n - north0, e - east0));
  }
  if (first) throw csv::CsvError(path, 0, "no data rows");
  return out;
}

Series read_reference_column(const std::string& path, const std::string& column) {
  auto reader = csv::CsvReader::open(path);
  reader.require_columns({"time_s", column});
  for (const auto& name : reader.header()) {
    if (name != "time_s" && !is_known_channel(name))
      throw csv::CsvError(path, 1, "column '" + name +
                                       "': not a channel name (units in the header, e.g. tas_kt; "
                                       "see data/qtg/README.md)");
  }
  Series s;
  csv::CsvRow row;
  while (reader.next(row)) {
    const double t = row.number("time_s");
    if (!s.t.empty() && t < s.t.back()) row.fail("column 'time_s': time goes backwards");
    s.t.push_back(t);
    s.x.push_back(row.number(column));
  }
  if (s.t.size() < 2) throw csv::CsvError(path, 0, "fewer than two data rows");
  return s;
}

double interpolate(const Series& s, double t) {
  if (s.t.empty()) throw std::invalid_argument("interpolate: empty series");
  if (t <= s.t.front()) return s.x.front();
  if (t >= s.t.back()) return s.x.back();
  const auto it = std::upper_bound(s.t.begin(), s.t.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - s.t.begin());
  const double t0 = s.t[i - 1], t1 = s.t[i];
  if (t1 <= t0) return s.x[i];
  return s.x[i - 1] + (s.x[i] - s.x[i - 1]) * (t - t0) / (t1 - t0);
}

void write_reference_csv(const std::string& path, const Channels& channels,
                         const std::vector<std::string>& names, const std::string& comment,
                         int every) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write");
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << '\n';
  out << "time_s";
  for (const auto& n : names) out << ", " << n;
  out << '\n';
  const Series& base = channels.at(names.front());
  for (std::size_t i = 0; i < base.t.size(); ++i) {
    if (i % static_cast<std::size_t>(every) != 0 && i + 1 != base.t.size()) continue;
    out << std::setprecision(10) << base.t[i];
    for (const auto& n : names) out << ", " << std::setprecision(8) << channels.at(n).x[i];
    out << '\n';
  }
  if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace fedsim::qtg
