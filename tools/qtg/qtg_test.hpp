// A QTG test as a validated value: what to fly (aircraft, start, input profile, duration, rate;
// or a deployment flown as a whole federation in-process, closed loop through the autopilot),
// what the reference is (handbook, analytic, certification criteria or fedsim's own regression
// run) and which channels to compare within which Part 60 tolerance or limits. Format:
// data/qtg/README.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace fedsim::qtg {

/// How the run starts; the fields map one to one onto fedsim-fly's trim options.
struct StartCondition {
  std::string trim;  // level | climb | turn | ground
  double alt_ft = 4000;
  std::optional<double> ktas, kcas;
  double heading_deg = 0, gamma_deg = 0, bank_deg = 0, flaps = 0, throttle = 0;
  double runway_elevation_m = 0;
  bool gear_down = false;  // flight trims: the gear lever down (fedsim-fly --gear-down)
};

/// A Part 60 tolerance: +/- an absolute amount in the compared quantity's unit, or a percentage
/// of the reference value.
struct Tolerance {
  enum class Kind { absolute, percent } kind = Kind::absolute;
  double amount = 0;
  std::string unit;  // absolute: must equal the compared quantity's unit ("1" dimensionless)
  /// The allowed deviation at a reference value.
  double band(double reference) const;
  std::string text() const;  // e.g. "±3 kt", "±10 %"
};

enum class Measure {
  time_history,   // the channel against the reference CSV's column, interpolated in time
  period,         // oscillation period from the channel's extrema (s)
  damping_ratio,  // from successive half-cycle amplitudes (dimensionless)
  time_to,        // first time the channel crosses `threshold` after `from_s` (s)
  value_at,       // the channel at `at_s` (or the last frame when at_s is absent)
  value_when,     // the channel when `when_channel` first crosses `threshold`
  minimum,
  maximum,
  max_abs,        // the largest |channel| over the window (deviations in dots)
  stall_speed_1g, // 14 CFR 25.103: V_CLmax / sqrt(n_z) at the first maximum of n_z / V^2
};

/// Samples a check keeps: those where `channel` (interpolated at the sample's time) lies within
/// [min, max], e.g. the approach below 1000 ft (`while:` in the test file).
struct Condition {
  std::string channel;
  double min = 0, max = 0;
};

struct Check {
  std::string name;
  std::string channel;
  Measure measure = Measure::time_history;
  double from_s = 0;                    // window start (all measures)
  std::optional<double> to_s;           // window end (default: end of run)
  std::optional<double> at_s;           // value_at
  std::optional<double> threshold;      // time_to, value_when
  std::string when_channel;             // value_when
  std::optional<double> reference_value;  // derived measures
  std::string reference_column;         // time_history (default: the channel)
  Tolerance tolerance;
  /// `limits: {max, [min,] unit}` instead of a reference value and tolerance: acceptance
  /// criteria such as "touchdown 200 to 2700 ft beyond the threshold" or "sink rate at most
  /// 6 ft/s" (then tolerance.unit holds the unit). The check passes when min <= measured <= max.
  std::optional<double> limit_min, limit_max;
  bool is_limit() const { return limit_max.has_value(); }
  std::optional<Condition> while_condition;
  int line = 0;  // where the check is in its file
};

struct Reference {
  std::string kind;    // handbook | analytic | criteria | regression | flight_test
  std::string source;  // what it is, named (never presented as flight data unless it is)
  std::string file;    // a time-history CSV, absolute (resolved against the test file)
};

/// A test flown as a whole federation: `fedsim run DEPLOYMENT --in-process [--scenario FILE]`
/// (the deployment's federates composed in one process, byte-identical to its DDS lockstep run),
/// its checks evaluated on what the deployment's `fedsim record` member recorded.
struct Federation {
  std::string deployment;  // resolved path
  std::string scenario;    // resolved path, or empty (an instructor scenario: weather, failures)
};

/// The runway the landing channels are measured from (data/nav/runways.csv).
struct RunwaySpec {
  std::string airport, runway;  // e.g. KSFO, 28R
};

struct QtgTest {
  std::string path;  // the YAML file
  std::string name;  // file stem, unique key for --only
  std::string title;
  std::string part60_item;
  std::string aircraft;
  StartCondition start;              // fedsim-fly tests
  std::optional<Federation> federation;  // federation tests (then no start or inputs)
  std::optional<RunwaySpec> runway;  // needed by the runway channels
  std::string inputs;  // resolved profile path, or empty
  bool inputs_relative = true;
  /// A closed-loop test pilot flown by fedsim-fly (`inputs: {pilot: stall_entry, ...}`): empty,
  /// or "stall_entry" with its entry rate and throttle.
  std::string pilot;
  double pilot_entry_rate_kt_per_s = 1.0;
  double pilot_throttle = 0.0;
  double duration_s = 0, rate_hz = 0;
  Reference reference;
  std::vector<Check> checks;
};

std::string measure_name(Measure m);
/// The unit of what a check compares: s for period and time_to, "1" for the damping ratio,
/// otherwise the channel's unit (the suffix of its name).
std::string measure_unit(const Check& check);

/// Loads and validates one test; throws util::ConfigError "file:line: field: problem".
/// `search_dirs` are where a relative profile path is looked up after the test file's folder.
QtgTest load_test(const std::string& path, const std::vector<std::string>& search_dirs = {});
/// Every *.yaml under `dir` (recursively), sorted by path.
std::vector<std::string> find_tests(const std::string& dir);

}  // namespace fedsim::qtg
