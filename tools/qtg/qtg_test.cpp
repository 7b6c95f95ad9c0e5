#include "tools/qtg/qtg_test.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "common/airports/runway_centreline.hpp"
#include "common/util/config_node.hpp"
#include "tools/qtg/channels.hpp"
#include "tools/qtg/measures.hpp"

namespace fedsim::qtg {
namespace fs = std::filesystem;
using util::ConfigNode;

double Tolerance::band(double reference) const {
  return kind == Kind::absolute ? amount : std::fabs(reference) * amount / 100.0;
}

std::string Tolerance::text() const {
  std::ostringstream s;
  s << "±" << amount << (kind == Kind::percent ? " %" : (unit == "1" ? "" : " " + unit));
  return s.str();
}

std::string measure_name(Measure m) {
  switch (m) {
    case Measure::time_history: return "time_history";
    case Measure::period: return "period";
    case Measure::damping_ratio: return "damping_ratio";
    case Measure::time_to: return "time_to";
    case Measure::value_at: return "value_at";
    case Measure::value_when: return "value_when";
    case Measure::minimum: return "minimum";
    case Measure::maximum: return "maximum";
    case Measure::max_abs: return "max_abs";
    case Measure::stall_speed_1g: return "stall_speed_1g";
  }
  return "?";
}

std::string measure_unit(const Check& check) {
  switch (check.measure) {
    case Measure::period:
    case Measure::time_to: return "s";
    case Measure::damping_ratio: return "1";
    default: return channel_unit(check.channel);
  }
}

namespace {

const std::vector<std::string> kMeasures = {"time_history", "period",     "damping_ratio",
                                            "time_to",      "value_at",   "value_when",
                                            "minimum",      "maximum",    "max_abs",
                                            "stall_speed_1g"};

Measure parse_measure(const std::string& s) {
  for (std::size_t i = 0; i < kMeasures.size(); ++i)
    if (kMeasures[i] == s) return static_cast<Measure>(i);
  return Measure::time_history;  // unreachable: choice() validated it
}

std::string known_channel(const ConfigNode& node, const std::string& key) {
  const std::string name = node.string(key);
  if (!is_known_channel(name)) {
    std::string list;
    for (const auto& c : known_channels()) list += (list.empty() ? "" : ", ") + c.name;
    node.fail_at(key, "unknown channel '" + name + "' (channels: " + list + ")");
  }
  return name;
}

/// A channel the test's run records: navigation and autopilot state only in a federation test,
/// the runway channels only with `runway:`.
std::string recorded_channel(const ConfigNode& node, const std::string& key, const QtgTest& test) {
  const std::string name = known_channel(node, key);
  const ChannelSource source = channel_source(name);
  if (!test.federation && (source == ChannelSource::navigation_state ||
                           source == ChannelSource::autopilot_state))
    node.fail_at(key, "channel '" + name + "' is recorded by a federation test only (" +
                          source_file(source) + "; fedsim-fly records the aircraft state)");
  if (source == ChannelSource::runway && !test.runway)
    node.fail_at(key, "channel '" + name + "' is measured from the runway: give runway: {airport, runway}");
  return name;
}

StartCondition parse_start(const ConfigNode& n) {
  n.reject_unknown_keys({"trim", "alt_ft", "ktas", "kcas", "heading_deg", "gamma_deg", "bank_deg",
                         "flaps", "throttle", "runway_elevation_m", "gear_down"});
  StartCondition s;
  s.trim = n.choice("trim", {"level", "climb", "turn", "ground"});
  s.alt_ft = n.number_or("alt_ft", 4000, -1000, 60000);
  if (n.has("ktas")) s.ktas = n.number("ktas", 10, 600);
  if (n.has("kcas")) s.kcas = n.number("kcas", 10, 600);
  const bool flight = s.trim != "ground";
  if (flight && s.ktas.has_value() == s.kcas.has_value())
    n.fail("a flight trim needs exactly one of ktas and kcas");
  if (!flight && (s.ktas || s.kcas)) n.fail("a ground start takes no airspeed");
  s.heading_deg = n.number_or("heading_deg", 0, -360, 360);
  s.gamma_deg = n.number_or("gamma_deg", 0, -30, 30);
  if (s.gamma_deg != 0 && s.trim != "climb") n.fail_at("gamma_deg", "only for trim: climb");
  s.bank_deg = n.number_or("bank_deg", 0, -80, 80);
  if (s.bank_deg != 0 && s.trim != "turn") n.fail_at("bank_deg", "only for trim: turn");
  s.flaps = n.number_or("flaps", 0, 0, 1);
  s.throttle = n.number_or("throttle", 0, 0, 1);
  if (s.throttle != 0 && flight) n.fail_at("throttle", "only for trim: ground (flight trims solve it)");
  s.runway_elevation_m = n.number_or("runway_elevation_m", 0, -500, 5000);
  s.gear_down = n.boolean_or("gear_down", false);
  if (s.gear_down && !flight) n.fail_at("gear_down", "only for flight trims (a ground start has its gear down)");
  return s;
}

/// A relative path against the test file's folder first, then each search folder.
std::string resolve(const ConfigNode& n, const std::string& key, const fs::path& base,
                    const std::vector<std::string>& search_dirs) {
  const fs::path p = n.string(key);
  if (p.is_absolute()) {
    if (!fs::exists(p)) n.fail_at(key, "no such file: " + p.string());
    return p.string();
  }
  std::vector<fs::path> tried = {base / p};
  for (const auto& d : search_dirs) tried.push_back(fs::path(d) / p);
  for (const auto& t : tried)
    if (fs::exists(t)) return fs::weakly_canonical(t).string();
  std::string where;
  for (const auto& t : tried) where += (where.empty() ? "" : ", ") + t.string();
  n.fail_at(key, "no such file (looked in " + where + ")");
}

Tolerance parse_tolerance(const ConfigNode& n, const std::string& unit) {
  n.reject_unknown_keys({"plus_minus", "unit", "percent"});
  Tolerance t;
  if (n.has("percent") == n.has("plus_minus"))
    n.fail("exactly one of plus_minus (with unit) and percent");
  if (n.has("percent")) {
    t.kind = Tolerance::Kind::percent;
    t.amount = n.number("percent", 0, 100);
    if (t.amount <= 0) n.fail_at("percent", "must be positive");
    if (n.has("unit")) n.fail_at("unit", "a percentage takes no unit");
    return t;
  }
  t.amount = n.number("plus_minus", 0, 1e6);
  if (t.amount <= 0) n.fail_at("plus_minus", "must be positive");
  t.unit = n.string("unit");
  if (t.unit != unit)
    n.fail_at("unit", "'" + t.unit + "' but the compared quantity is in '" + unit +
                          "' (\"1\" for dimensionless)");
  return t;
}

Condition parse_condition(const ConfigNode& n, const QtgTest& test) {
  n.reject_unknown_keys({"channel", "min", "max"});
  Condition w;
  w.channel = recorded_channel(n, "channel", test);
  w.min = n.number("min");
  w.max = n.number("max");
  if (!(w.max > w.min)) n.fail_at("max", "must be above min");
  return w;
}

/// limits: {max, [min,] unit}. A one-sided limit is an upper one above zero (its share used is
/// what the report shows: 2.6 of 6 ft/s is 43 %).
void parse_limits(const ConfigNode& n, Check& c) {
  n.reject_unknown_keys({"min", "max", "unit"});
  c.limit_max = n.number("max");
  if (n.has("min")) {
    c.limit_min = n.number("min");
    if (!(*c.limit_max > *c.limit_min)) n.fail_at("max", "must be above min");
  } else if (!(*c.limit_max > 0)) {
    n.fail_at("max", "a limit without min must be above 0 (give min for a range)");
  }
  const std::string unit = measure_unit(c);
  if (n.string("unit") != unit)
    n.fail_at("unit", "'" + n.string("unit") + "' but the compared quantity is in '" + unit +
                          "' (\"1\" for dimensionless)");
  c.tolerance.kind = Tolerance::Kind::absolute;
  c.tolerance.unit = unit;
}

Check parse_check(const ConfigNode& n, const QtgTest& test) {
  n.reject_unknown_keys({"name", "channel", "measure", "from_s", "to_s", "at_s", "threshold",
                         "when_channel", "reference_value", "reference_formula",
                         "reference_column", "tolerance", "limits", "while"});
  Check c;
  c.line = n.line();
  c.name = n.string("name");
  c.channel = recorded_channel(n, "channel", test);
  c.measure = parse_measure(n.choice("measure", kMeasures));
  c.from_s = n.number_or("from_s", 0, 0, test.duration_s);
  if (n.has("to_s")) {
    c.to_s = n.number("to_s", 0, test.duration_s);
    if (*c.to_s <= c.from_s) n.fail_at("to_s", "must be after from_s");
  }
  const auto needs = [&](const std::string& key, bool present) {
    if (present && !n.has(key)) n.fail("measure " + measure_name(c.measure) + " needs " + key);
    if (!present && n.has(key))
      n.fail_at(key, "not used by measure " + measure_name(c.measure));
  };
  if (n.has("at_s") && c.measure != Measure::value_at)
    n.fail_at("at_s", "not used by measure " + measure_name(c.measure));
  if (n.has("at_s")) c.at_s = n.number("at_s", 0, test.duration_s);
  const bool crossing = c.measure == Measure::time_to || c.measure == Measure::value_when;
  needs("threshold", crossing);
  if (crossing) c.threshold = n.number("threshold");
  needs("when_channel", c.measure == Measure::value_when);
  if (c.measure == Measure::value_when) c.when_channel = recorded_channel(n, "when_channel", test);
  if (c.measure == Measure::stall_speed_1g && c.channel != "cas_kt")
    n.fail_at("channel", "stall_speed_1g is a calibrated airspeed: channel cas_kt (it reads nz_g too)");
  if (n.has("while")) {
    if (c.measure != Measure::minimum && c.measure != Measure::maximum && c.measure != Measure::max_abs)
      n.fail_at("while", "only for the measures minimum, maximum and max_abs");
    c.while_condition = parse_condition(n.child("while"), test);
  }
  if (n.has("limits")) {
    if (c.measure == Measure::time_history) n.fail_at("limits", "not for a time_history check");
    for (const char* k : {"reference_value", "reference_formula", "tolerance", "reference_column"})
      if (n.has(k)) n.fail_at(k, "a check has either limits or a reference and tolerance");
    parse_limits(n.child("limits"), c);
    return c;
  }
  if (c.measure == Measure::time_history) {
    needs("reference_value", false);
    needs("reference_formula", false);
    if (test.reference.file.empty())
      n.fail("a time_history check needs reference.file (a CSV with time_s and the channel)");
    c.reference_column = n.has("reference_column") ? known_channel(n, "reference_column")
                                                   : c.channel;
    if (channel_unit(c.reference_column) != channel_unit(c.channel))
      n.fail_at("reference_column", "its unit differs from the channel's");
  } else {
    needs("reference_column", false);
    if (n.has("reference_value") == n.has("reference_formula"))
      n.fail("exactly one of reference_value and reference_formula");
    if (n.has("reference_value")) {
      c.reference_value = n.number("reference_value");
    } else {
      n.choice("reference_formula", {"lanchester_period"});
      if (c.measure != Measure::period)
        n.fail_at("reference_formula", "lanchester_period is a period");
      if (!test.start.ktas)
        n.fail_at("reference_formula", "lanchester_period needs start.ktas (true airspeed)");
      c.reference_value = lanchester_period_s(*test.start.ktas * 1852.0 / 3600.0);
    }
  }
  c.tolerance = parse_tolerance(n.child("tolerance"), measure_unit(c));
  return c;
}

}  // namespace

QtgTest load_test(const std::string& path, const std::vector<std::string>& search_dirs) {
  const ConfigNode root = ConfigNode::load_file(path);
  root.reject_unknown_keys({"fedsim_qtg_test", "title", "part60_item", "aircraft", "start",
                            "inputs", "federation", "runway", "duration_s", "rate_hz", "reference",
                            "checks"});
  if (root.integer("fedsim_qtg_test", 1, 1) != 1) root.fail("unsupported format version");
  const fs::path base = fs::path(path).parent_path();
  QtgTest t;
  t.path = path;
  t.name = fs::path(path).stem().string();
  t.title = root.string("title");
  t.part60_item = root.string("part60_item");
  t.aircraft = root.string("aircraft");
  if (t.aircraft.empty() || t.aircraft.find_first_of(" \t/\\") != std::string::npos)
    root.fail_at("aircraft", "a pack name such as c172 or b737");
  if (root.has("federation")) {
    for (const char* k : {"start", "inputs"})
      if (root.has(k)) root.fail_at(k, "a federation test starts as its deployment says (no start or inputs)");
    const ConfigNode f = root.child("federation");
    f.reject_unknown_keys({"deployment", "scenario"});
    Federation fed;
    fed.deployment = resolve(f, "deployment", base, search_dirs);
    if (f.has("scenario")) fed.scenario = resolve(f, "scenario", base, search_dirs);
    t.federation = fed;
  } else {
    t.start = parse_start(root.child("start"));
  }
  if (root.has("runway")) {
    const ConfigNode r = root.child("runway");
    r.reject_unknown_keys({"airport", "runway"});
    RunwaySpec spec{r.string("airport"), r.string("runway")};
    try {
      // both ends in the table (the runway channels' centreline), now rather than after the flight
      RunwayCentreline::from_table(RunwayTable::load_default(), spec.airport, spec.runway);
    } catch (const std::exception& e) {
      r.fail(e.what());
    }
    t.runway = spec;
  }
  if (root.has("inputs")) {
    const ConfigNode in = root.child("inputs");
    in.reject_unknown_keys({"profile", "relative", "pilot", "entry_rate_kt_per_s", "throttle"});
    if (in.has("pilot")) {
      t.pilot = in.choice("pilot", {"stall_entry"});
      t.pilot_entry_rate_kt_per_s = in.number_or("entry_rate_kt_per_s", 1.0, 0.1, 5.0);
      t.pilot_throttle = in.number_or("throttle", 0.0, 0.0, 1.0);
    } else {
      for (const char* k : {"entry_rate_kt_per_s", "throttle"})
        if (in.has(k)) in.fail_at(k, "a setting of the test pilot: needs pilot: stall_entry");
      if (!in.has("profile")) in.fail("inputs needs a profile, a pilot, or both");
    }
    if (in.has("profile")) t.inputs = resolve(in, "profile", base, search_dirs);
    t.inputs_relative = in.boolean_or("relative", t.pilot.empty());
    if (!t.pilot.empty() && t.inputs_relative)
      in.fail_at("relative", "the test pilot flies absolute controls (relative: false)");
  }
  t.duration_s = root.number("duration_s", 0.1, 3600);
  t.rate_hz = root.number("rate_hz", 1, 1000);
  if (t.duration_s * t.rate_hz > 1e6) root.fail_at("rate_hz", "more than a million frames");
  const ConfigNode ref = root.child("reference");
  ref.reject_unknown_keys({"kind", "source", "file"});
  t.reference.kind = ref.choice("kind", {"handbook", "analytic", "criteria", "regression", "flight_test"});
  t.reference.source = ref.string("source");
  if (t.reference.source.size() < 10) ref.fail_at("source", "name the source (what and where)");
  // not required to exist: a missing file fails its checks by name (and --record-regression
  // writes it)
  if (ref.has("file")) {
    const fs::path f = ref.string("file");
    t.reference.file = (f.is_absolute() ? f : fs::weakly_canonical(base / f)).string();
  }
  const auto checks = root.child("checks").items();
  if (checks.empty()) root.fail_at("checks", "at least one check");
  for (const auto& c : checks) t.checks.push_back(parse_check(c, t));
  return t;
}

std::vector<std::string> find_tests(const std::string& dir) {
  std::vector<std::string> out;
  if (!fs::is_directory(dir)) throw util::ConfigError(dir + ": not a folder");
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace fedsim::qtg
