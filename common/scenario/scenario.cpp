#include "common/scenario/scenario.hpp"

#include "common/instructor/request_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace fedsim::scenario {

namespace {

using util::ConfigError;
using util::ConfigNode;
using nlohmann::json;

bool present(const ConfigNode& node, const std::string& key) {
  return node.yaml().IsMap() && node.yaml()[key].IsDefined();
}

/// The value of `key` as a ConfigNode whose field path names it.
ConfigNode sub(const ConfigNode& node, const std::string& key) {
  const std::string path = node.field_path().empty() ? key : node.field_path() + "." + key;
  return ConfigNode(node.yaml()[key], node.file(), path);
}

/// yaml-cpp keeps both of two equal keys and reads the first (nlohmann the last): a second
/// `do:` or `system:` would be ignored in silence.
void reject_duplicate_keys(const ConfigNode& node) {
  std::set<std::string> seen;
  for (const auto& kv : node.yaml()) {
    const std::string key = kv.first.Scalar();
    if (!seen.insert(key).second) {
      throw ConfigError(node.file() + ":" + std::to_string(kv.first.Mark().line + 1) + ": " +
                        sub(node, key).field_path() + ": given twice");
    }
  }
}

/// A key with nothing after it ("at_s:"): named at the key's line (a null value's own mark is
/// where the next token starts, often the line below).
void reject_empty_values(const ConfigNode& node) {
  for (const auto& kv : node.yaml()) {
    if (kv.second.IsNull()) {
      throw ConfigError(node.file() + ":" + std::to_string(kv.first.Mark().line + 1) + ": " +
                        sub(node, kv.first.Scalar()).field_path() + ": no value");
    }
  }
}

void check_keys(const ConfigNode& node, const std::vector<std::string>& allowed) {
  node.reject_unknown_keys(allowed);
  reject_duplicate_keys(node);
  reject_empty_values(node);
}

/// A time in seconds: finite, >= 0 (> 0 where `positive`).
double seconds(const ConfigNode& node, bool positive) {
  const double value = node.as_number();  // refuses NaN and inf
  if (positive ? value <= 0.0 : value < 0.0) {
    std::ostringstream why;
    why << value << " s: must be " << (positive ? "> 0" : ">= 0");
    node.fail(why.str());
  }
  return value;
}

/// A plain YAML scalar read as a number, as YAML 1.2's core schema does (".inf", ".nan" too);
/// nullopt for text. Words such as "nan" stay text, as YAML has it.
std::optional<double> plain_number(const std::string& s) {
  for (const char* inf : {".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF"}) {
    if (s == inf) return HUGE_VAL;
  }
  for (const char* inf : {"-.inf", "-.Inf", "-.INF"}) {
    if (s == inf) return -HUGE_VAL;
  }
  if (s == ".nan" || s == ".NaN" || s == ".NAN") return std::nan("");
  std::string_view digits = s;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);  // from_chars takes no '+'
  const std::size_t body = digits.substr(0, 1) == "-" ? 1 : 0;
  if (digits.size() <= body || !(std::isdigit(static_cast<unsigned char>(digits[body])) || digits[body] == '.')) {
    return std::nullopt;
  }
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ptr != digits.data() + digits.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) return HUGE_VAL;  // "1e999": refused as not finite
  return ec == std::errc{} ? std::optional<double>(value) : std::nullopt;
}

json scalar_to_json(const ConfigNode& node) {
  const std::string& s = node.yaml().Scalar();
  if (node.yaml().Tag() == "!") return s;  // quoted: text, even "10"
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  const auto number = plain_number(s);
  if (!number) return s;
  if (!std::isfinite(*number)) node.fail(s + " is not a finite number");
  return *number;
}

/// The action's YAML as the JSON the instructor station would send, typed as YAML 1.2 reads it.
json to_json(const ConfigNode& node) {
  const YAML::Node& y = node.yaml();
  if (y.IsNull()) return nullptr;
  if (y.IsSequence()) {
    json list = json::array();
    for (const auto& item : node.items()) list.push_back(to_json(item));
    return list;
  }
  if (y.IsMap()) {
    reject_duplicate_keys(node);
    json object = json::object();
    for (const auto& key : node.keys()) object[key] = to_json(sub(node, key));
    return object;
  }
  return scalar_to_json(node);
}

/// The line of the key a RequestError names ("reposition: lat_deg: 95 ..." or "unknown field
/// 'x'"), so a block-style action points at its bad line; else the action's own line.
int line_of_named_key(const ConfigNode& action, const std::string& message) {
  for (const auto& kv : action.yaml()) {
    const std::string key = kv.first.Scalar();
    if (key == "command") continue;
    if (message.find(": " + key + ":") != std::string::npos || message.find("'" + key + "'") != std::string::npos) {
      return kv.first.Mark().line + 1;
    }
  }
  return action.line();
}

Action command_action(const ConfigNode& node, int event_line) {
  const json body = to_json(node);
  try {
    Action action{Action::Kind::kCommand, instructor::request_from_json(body), {}, event_line};
    action.text = instructor::describe(action.command);
    return action;
  } catch (const instructor::RequestError& e) {
    throw ConfigError(node.file() + ":" + std::to_string(line_of_named_key(node, e.what())) + ": " +
                      node.field_path() + ": " + e.what());
  }
}

Action parse_action(const ConfigNode& node, int event_line) {
  const YAML::Node& y = node.yaml();
  if (y.IsScalar() && y.Scalar() == "stop") return Action{Action::Kind::kStop, {}, "stop", event_line};
  if (y.IsMap() && present(node, "log")) {
    check_keys(node, {"log"});
    const std::string text = node.string("log");
    if (text.empty()) node.fail_at("log", "the message is empty");
    return Action{Action::Kind::kLog, {}, text, event_line};
  }
  if (!y.IsMap()) node.fail("expected stop, {log: \"text\"} or an instructor command {command: ...}");
  return command_action(node, event_line);
}

std::vector<std::string> sorted_unique(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace

Scenario Scenario::load_file(const std::string& path) { return parse(util::read_whole_file(path), path); }

Scenario Scenario::parse(const std::string& text, const std::string& origin) {
  const auto root = ConfigNode::parse(text, origin);
  if (root.yaml().IsNull()) throw ConfigError(origin + ":1: (top level): the scenario is empty");
  if (!root.yaml().IsMap()) root.fail("a scenario is a map with name and events");
  check_keys(root, {"name", "description", "events"});
  Scenario out;
  out.name_ = root.string("name");
  if (out.name_.empty()) root.fail_at("name", "the name is empty");
  if (present(root, "description")) root.string("description");  // text, if given
  const auto events = root.child("events");
  if (!events.yaml().IsSequence() || events.yaml().size() == 0) events.fail("expected a non-empty list of events");
  for (const auto& item : events.items()) out.events_.push_back(parse_event(item));
  out.rearm();
  return out;
}

Scenario::Event Scenario::parse_event(const ConfigNode& node) {
  if (!node.yaml().IsMap()) node.fail("an event is a map: at_s, every_s or when; for_s; do");
  check_keys(node, {"at_s", "every_s", "when", "for_s", "do"});
  const bool at = present(node, "at_s"), every = present(node, "every_s"), when = present(node, "when");
  if (when && (at || every)) node.fail_at("when", "give at_s/every_s or when, not both");
  if (!at && !every && !when) node.fail("an event needs at_s, every_s or when");
  if (present(node, "for_s") && !when) node.fail_at("for_s", "for_s goes with when (how long it must hold)");
  if (!present(node, "do")) node.fail("an event needs do: stop, {log: text} or an instructor command");

  Event event;
  event.line = node.line();
  if (at) event.at_s = seconds(sub(node, "at_s"), false);
  if (every) event.every_s = seconds(sub(node, "every_s"), true);
  if (when) event.when = Condition::parse(sub(node, "when"));
  if (present(node, "for_s")) event.for_s = seconds(sub(node, "for_s"), false);
  event.action = parse_action(sub(node, "do"), event.line);
  return event;
}

void Scenario::set_frame_period(double period_s) {
  if (!std::isfinite(period_s) || period_s <= 0.0) throw std::invalid_argument("scenario: frame period must be > 0");
  frame_period_s_ = period_s;
}

void Scenario::rearm() {
  for (auto& event : events_) {
    event.done = false;
    event.held_since_s.reset();
    event.next_s = event.at_s.value_or(event.every_s);  // every_s alone: first at every_s
  }
  finished_ = false;
}

std::vector<Action> Scenario::step(double sim_time_s, const FieldLookup& lookup) {
  if (!std::isfinite(sim_time_s)) throw std::invalid_argument("scenario: sim time is not finite");
  // Time going back is a RESET or a restored snapshot: the exercise starts again.
  if (last_time_s_ && sim_time_s < *last_time_s_ - half_frame()) rearm();
  last_time_s_ = sim_time_s;
  missing_.clear();
  std::vector<Action> fired;
  if (finished_) return fired;
  for (auto& event : events_) {
    if (event.done || !due(event, sim_time_s, lookup)) continue;
    fired.push_back(event.action);
    if (event.action.kind == Action::Kind::kStop) {
      finished_ = true;
      break;
    }
  }
  return fired;
}

bool Scenario::due(Event& event, double t, const FieldLookup& lookup) {
  if (event.when) {
    if (!event.when->holds(lookup, missing_)) {
      event.held_since_s.reset();  // a break restarts the for_s count
      return false;
    }
    if (!event.held_since_s) event.held_since_s = t;
    if (t - *event.held_since_s < event.for_s - half_frame()) return false;
    event.done = true;
    return true;
  }
  if (t < event.next_s - half_frame()) return false;
  if (event.every_s > 0.0) {
    // The next multiple after this frame, counted from the first time so rounding cannot drift.
    const double first = event.at_s.value_or(event.every_s);
    const double periods = std::floor((t + half_frame() - first) / event.every_s) + 1.0;
    event.next_s = first + periods * event.every_s;
  } else {
    event.done = true;
  }
  return true;
}

std::vector<std::string> Scenario::fields() const {
  std::vector<std::string> out;
  for (const auto& event : events_) {
    if (event.when) event.when->collect_fields(out);
  }
  return sorted_unique(std::move(out));
}

std::vector<std::string> Scenario::missing_fields() const { return sorted_unique(missing_); }

}  // namespace fedsim::scenario
