#include "tools/qtg/channels.hpp"

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/airports/runway_centreline.hpp"
#include "common/airports/runway_table.hpp"
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
      {{"sink_rate_fps", "CG rate of descent (+ down)"}, {"climb_rate_mps"},
       [](V v) { return -v[0] / kMPerFt; }},
  };
  return table;
}

// ILS deviations in dots: the recorded deviation is -1..1 of full scale (150 uA, DDM 0.155
// localizer / 0.175 glide slope, common/radio) and full scale is two dots on the
// 737's PFD and on a standard CDI (one dot 75 uA: DDM 0.0775 localizer, 0.0875 glide slope).
constexpr double kDotsPerFullScale = 2.0;

const std::vector<ChannelInfo>& federation_channels() {
  using S = ChannelSource;
  static const std::vector<ChannelInfo> table = {
      {"loc_dots", "NAV1 localizer deviation, dots (+ fly right; only while the localizer is received)",
       S::navigation_state},
      {"gs_dots", "NAV1 glide-slope deviation, dots (+ fly up; only while the glide slope is received)",
       S::navigation_state},
      {"ap_engaged", "1 while the autopilot is engaged (CMD)", S::autopilot_state},
      {"ap_roll_mode", "FMA roll mode (idl/autopilot.idl FmaRollMode: 5 VOR/LOC, 6 ALIGN, 7 ROLLOUT)",
       S::autopilot_state},
      {"ap_pitch_mode", "FMA pitch mode (FmaPitchMode: 6 G/S, 7 FLARE, 8 ROLLOUT)", S::autopilot_state},
      {"height_above_runway_ft", "CG height above the runway threshold's elevation", S::runway},
      {"beyond_threshold_ft", "distance beyond the runway threshold along the centreline (- before it)",
       S::runway},
      {"left_of_centreline_ft", "distance left of the runway centreline, seen landing (- right)",
       S::runway},
  };
  return table;
}

}  // namespace

const std::vector<ChannelInfo>& known_channels() {
  static const std::vector<ChannelInfo> infos = [] {
    std::vector<ChannelInfo> out;
    for (const auto& d : derivations()) out.push_back(d.info);
    out.push_back({"distance_ft", "horizontal distance from the start point"});
    for (const auto& c : federation_channels()) out.push_back(c);
    return out;
  }();
  return infos;
}

ChannelSource channel_source(const std::string& name) {
  for (const auto& c : known_channels())
    if (c.name == name) return c.source;
  return ChannelSource::aircraft_state;
}

std::string source_file(ChannelSource source) {
  switch (source) {
    case ChannelSource::navigation_state: return "fedsim_navigation_state.csv";
    case ChannelSource::autopilot_state: return "fedsim_autopilot_state.csv";
    default: return "fedsim_aircraft_state.csv";
  }
}

bool is_known_channel(const std::string& name) {
  const auto& all = known_channels();
  return std::any_of(all.begin(), all.end(), [&](const ChannelInfo& c) { return c.name == name; });
}

std::string channel_unit(const std::string& name) {
  static const std::set<std::string> units = {"kt", "ft", "deg", "dps", "fpm",  "g",
                                              "s",  "m",  "lbf", "n",   "dots", "fps"};
  const auto underscore = name.rfind('_');
  if (underscore == std::string::npos) return "1";
  const std::string suffix = name.substr(underscore + 1);
  return units.count(suffix) ? suffix : "1";
}

namespace {

void append(Channels& out, const std::string& name, double t, double x) {
  auto& s = out[name];
  s.t.push_back(t);
  s.x.push_back(x);
}

/// The aircraft-state channels, and with `runway` the runway channels, in one pass (heights
/// above `runway_elevation_m`, the landing threshold's).
Channels read_aircraft_state(const std::string& path, const RunwayCentreline* runway,
                             double runway_elevation_m = 0.0) {
  auto reader = csv::CsvReader::open(path);
  const auto time_col = reader.column("sim_time_s");
  std::vector<std::vector<std::size_t>> cols;
  for (const auto& d : derivations()) {
    std::vector<std::size_t> idx;
    for (const auto& c : d.columns) idx.push_back(reader.column(c));
    cols.push_back(std::move(idx));
  }
  std::size_t lat_col = 0, lon_col = 0, alt_col = 0;
  if (runway) {
    lat_col = reader.column("latitude_rad");
    lon_col = reader.column("longitude_rad");
    alt_col = reader.column("altitude_msl_m");
  }
  Channels out;
  csv::CsvRow row;
  std::vector<double> args;
  double north0 = 0, east0 = 0;
  bool first = true;
  while (reader.next(row)) {
    const double t = row.number(time_col);
    if (!out.empty() && t < out.begin()->second.t.back())
      row.fail("column 'sim_time_s': time goes backwards");
    for (std::size_t i = 0; i < derivations().size(); ++i) {
      args.clear();
      for (auto c : cols[i]) args.push_back(row.number(c));
      append(out, derivations()[i].info.name, t, derivations()[i].value(args));
    }
    const double n = out["north_ft"].x.back(), e = out["east_ft"].x.back();
    if (first) north0 = n, east0 = e, first = false;
    append(out, "distance_ft", t, std::hypot(n - north0, e - east0));
    if (runway) {
      const double lat = row.number(lat_col), lon = row.number(lon_col);
      append(out, "height_above_runway_ft", t, (row.number(alt_col) - runway_elevation_m) / kMPerFt);
      append(out, "beyond_threshold_ft", t, runway->beyond_threshold_m(lat, lon) / kMPerFt);
      append(out, "left_of_centreline_ft", t, runway->left_m(lat, lon) / kMPerFt);
    }
  }
  if (first) throw csv::CsvError(path, 0, "no data rows");
  return out;
}

/// NAV1's localizer and glide-slope deviations in dots, each only while its signal is valid
/// (SignalStatus SIGNAL_VALID = 0, idl/navigation.idl).
std::vector<double> read_navigation_state(const std::string& path, Channels& out) {
  auto reader = csv::CsvReader::open(path);
  const auto t_col = reader.column("sim_time_s");
  const auto loc = reader.column("nav[0].course_deviation");
  const auto loc_status = reader.column("nav[0].status");
  const auto gs = reader.column("nav[0].glideslope_deviation");
  const auto gs_status = reader.column("nav[0].glideslope_status");
  out["loc_dots"], out["gs_dots"];  // present (perhaps empty: never received)
  csv::CsvRow row;
  std::vector<double> times;
  while (reader.next(row)) {
    const double t = row.number(t_col);
    times.push_back(t);
    if (row.number(loc_status) == 0) append(out, "loc_dots", t, kDotsPerFullScale * row.number(loc));
    if (row.number(gs_status) == 0) append(out, "gs_dots", t, kDotsPerFullScale * row.number(gs));
  }
  if (times.empty()) throw csv::CsvError(path, 0, "no data rows");
  return times;
}

std::vector<double> read_autopilot_state(const std::string& path, Channels& out) {
  auto reader = csv::CsvReader::open(path);
  const auto t_col = reader.column("sim_time_s");
  const auto engaged = reader.column("fma.autopilot_engaged");
  const auto roll = reader.column("fma.roll");
  const auto pitch = reader.column("fma.pitch");
  csv::CsvRow row;
  std::vector<double> times;
  while (reader.next(row)) {
    const double t = row.number(t_col);
    times.push_back(t);
    append(out, "ap_engaged", t, row.number(engaged));
    append(out, "ap_roll_mode", t, row.number(roll));
    append(out, "ap_pitch_mode", t, row.number(pitch));
  }
  if (times.empty()) throw csv::CsvError(path, 0, "no data rows");
  return times;
}

}  // namespace

Channels channels_from_state_csv(const std::string& path) { return read_aircraft_state(path, nullptr); }

Channels channels_from_recording(const std::string& dir, const std::set<ChannelSource>& sources,
                                 const std::optional<RunwaySpec>& runway,
                                 std::vector<RecordedFile>* files) {
  namespace fs = std::filesystem;
  const auto file = [&](ChannelSource s) {
    const std::string path = (fs::path(dir) / source_file(s)).string();
    if (!fs::is_regular_file(path))
      throw std::runtime_error(path + ": missing: the recording has no " + source_file(s) +
                               " (record its topic: fedsim record --topics ...)");
    return path;
  };
  std::optional<RunwayCentreline> centreline;
  double elevation_m = 0.0;
  if (sources.count(ChannelSource::runway)) {
    if (!runway) throw std::runtime_error("the runway channels need the test's runway");
    const RunwayTable table = RunwayTable::load_default();
    centreline = RunwayCentreline::from_table(table, runway->airport, runway->runway);
    elevation_m = table.at(runway->airport, runway->runway).elevation_m;
  }
  const std::string state = file(ChannelSource::aircraft_state);
  Channels out = read_aircraft_state(state, centreline ? &*centreline : nullptr, elevation_m);
  if (files) files->push_back({state, out.at("tas_kt").t});
  if (sources.count(ChannelSource::navigation_state)) {
    const std::string path = file(ChannelSource::navigation_state);
    auto times = read_navigation_state(path, out);
    if (files) files->push_back({path, std::move(times)});
  }
  if (sources.count(ChannelSource::autopilot_state)) {
    const std::string path = file(ChannelSource::autopilot_state);
    auto times = read_autopilot_state(path, out);
    if (files) files->push_back({path, std::move(times)});
  }
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
