#include "common/scenario/condition.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>
#include <tuple>
#include <utility>

namespace fedsim::scenario {

namespace {

constexpr std::string_view kOperatorChars = "<>=!";

bool is_blank(char c) { return c == ' ' || c == '\t'; }

/// A little cursor over the comparison text: the grammar is three or four words, so a
/// hand-written scanner states it more plainly than a regular expression would.
struct Scanner {
  std::string_view rest;

  void skip_blanks() {
    while (!rest.empty() && is_blank(rest.front())) rest.remove_prefix(1);
  }
  /// Characters up to a blank or an operator character.
  std::string_view word() {
    skip_blanks();
    std::size_t n = 0;
    while (n < rest.size() && !is_blank(rest[n]) && kOperatorChars.find(rest[n]) == std::string_view::npos) ++n;
    const auto out = rest.substr(0, n);
    rest.remove_prefix(n);
    return out;
  }
  /// The operator: two-character forms first, so "<=" is not read as "<" then "=".
  std::string_view op() {
    skip_blanks();
    for (std::string_view candidate : {"<=", ">=", "==", "!=", "<", ">"}) {
      if (rest.substr(0, candidate.size()) == candidate) {
        rest.remove_prefix(candidate.size());
        return candidate;
      }
    }
    return {};
  }
};

Comparator comparator_of(std::string_view op) {
  if (op == "<") return Comparator::kLess;
  if (op == "<=") return Comparator::kLessEqual;
  if (op == ">") return Comparator::kGreater;
  if (op == ">=") return Comparator::kGreaterEqual;
  if (op == "==") return Comparator::kEqual;
  return Comparator::kNotEqual;
}

bool valid_topic_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/' || c == '-';
}
bool valid_field_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '[' || c == ']';
}

/// Splits "fedsim/aircraft_state.velocity_ned_mps[2]" at the first dot: topic names hold no
/// dots, flattened field paths do (nested structs).
std::pair<std::string, std::string> split_field(std::string_view path) {
  const auto dot = path.find('.');
  if (dot == std::string_view::npos || dot == 0) {
    throw ConditionError("'" + std::string(path) +
                         "' has no topic: write <topic>.<field>, e.g. fedsim/aircraft_state.height_agl_m");
  }
  const auto topic = path.substr(0, dot), field = path.substr(dot + 1);
  // A keyed topic's instance may follow its name in brackets: fedsim/engine_state[0] (one per
  // engine), fedsim/visual_status[1] (per channel), as the instructor station names them.
  std::string_view name = topic;
  if (const auto open = topic.find('['); open != std::string_view::npos && topic.back() == ']' && open + 2 < topic.size()) {
    const auto index = topic.substr(open + 1, topic.size() - open - 2);
    if (std::all_of(index.begin(), index.end(), [](char c) { return c >= '0' && c <= '9'; })) name = topic.substr(0, open);
  }
  const bool bad_topic = name.empty() || std::find_if_not(name.begin(), name.end(), valid_topic_char) != name.end();
  const bool bad_field = field.empty() || field.front() == '.' || field.back() == '.' ||
                         field.find("..") != std::string_view::npos ||
                         std::find_if_not(field.begin(), field.end(), valid_field_char) != field.end();
  if (bad_topic) {
    throw ConditionError("topic '" + std::string(topic) + "': letters, digits, _ - / only (and an instance: [0])");
  }
  if (bad_field) {
    throw ConditionError("field '" + std::string(field) + "': a flattened path such as air.tas_mps or velocity_ned_mps[2]");
  }
  return {std::string(topic), std::string(field)};
}

/// A finite decimal number filling `word` (from_chars also reads "nan" and "inf": refused).
double finite_number(std::string_view word) {
  double value = 0.0;
  const auto* end = word.data() + word.size();
  const auto [ptr, ec] = std::from_chars(word.data(), end, value);
  if (word.empty()) throw ConditionError("a comparison needs a number after the operator");
  if (ec == std::errc::result_out_of_range || (ec == std::errc{} && ptr == end && !std::isfinite(value))) {
    throw ConditionError("'" + std::string(word) + "' is not a finite number");
  }
  if (ec != std::errc{} || ptr != end) throw ConditionError("'" + std::string(word) + "' is not a number");
  return value;
}

bool compare(double value, Comparator op, double threshold) {
  switch (op) {
    case Comparator::kLess: return value < threshold;
    case Comparator::kLessEqual: return value <= threshold;
    case Comparator::kGreater: return value > threshold;
    case Comparator::kGreaterEqual: return value >= threshold;
    case Comparator::kEqual: return value == threshold;
    case Comparator::kNotEqual: return value != threshold;
  }
  return false;
}

}  // namespace

std::optional<double> unit_factor(const std::string& unit) {
  // Only the units instructors type; SI words are accepted so a threshold can say what it means.
  static const std::pair<const char*, double> kUnits[] = {
      {"ft", units::kFtToM}, {"kt", units::kKtToMps}, {"deg", units::kDegToRad},
      {"nm", units::kNmToM}, {"fpm", units::kFpmToMps}, {"m", 1.0}, {"mps", 1.0}, {"s", 1.0}};
  for (const auto& [name, factor] : kUnits) {
    if (unit == name) return factor;
  }
  return std::nullopt;
}

Comparison parse_comparison(const std::string& text) {
  Scanner scan{text};
  Comparison out;
  out.text = text;
  std::tie(out.topic, out.field) = split_field(scan.word());
  const auto op = scan.op();
  if (op.empty()) {
    throw ConditionError("'" + text + "': expected an operator (< <= > >= == !=) after the field");
  }
  out.op = comparator_of(op);
  out.threshold = finite_number(scan.word());
  const auto unit = scan.word();
  if (!unit.empty()) {
    const auto factor = unit_factor(std::string(unit));
    if (!factor) throw ConditionError("unknown unit '" + std::string(unit) + "' (ft, kt, deg, nm, fpm, m, mps, s)");
    out.threshold *= *factor;
  }
  scan.skip_blanks();
  if (!scan.rest.empty()) throw ConditionError("'" + text + "': unexpected '" + std::string(scan.rest) + "' at the end");
  return out;
}

Condition Condition::parse(const util::ConfigNode& node) {
  Condition out;
  if (node.yaml().IsScalar()) {
    try {
      out.compare_ = parse_comparison(node.as_string());
    } catch (const ConditionError& e) {
      node.fail(e.what());
    }
    return out;
  }
  if (!node.yaml().IsMap() || node.yaml().size() != 1) {
    node.fail("a condition is a comparison (\"<topic>.<field> < 500 ft\") or {all: [...]} / {any: [...]}");
  }
  node.reject_unknown_keys({"all", "any"});
  const bool all = node.has("all");
  const auto list = node.child(all ? "all" : "any");
  if (!list.yaml().IsSequence() || list.yaml().size() == 0) list.fail("expected a non-empty list of conditions");
  out.kind_ = all ? Kind::kAll : Kind::kAny;
  for (const auto& item : list.items()) out.children_.push_back(parse(item));
  return out;
}

bool Condition::holds(const FieldLookup& lookup, std::vector<std::string>& missing) const {
  if (kind_ == Kind::kCompare) {
    const auto value = lookup(compare_.topic, compare_.field);
    if (!value) missing.push_back(compare_.topic + "." + compare_.field);
    return value && compare(*value, compare_.op, compare_.threshold);
  }
  // No short cut: every field is looked up so that missing_fields() names them all.
  std::size_t true_count = 0;
  for (const auto& child : children_) true_count += child.holds(lookup, missing) ? 1 : 0;
  return kind_ == Kind::kAll ? true_count == children_.size() : true_count > 0;
}

void Condition::collect_fields(std::vector<std::string>& out) const {
  if (kind_ == Kind::kCompare) out.push_back(compare_.topic + "." + compare_.field);
  for (const auto& child : children_) child.collect_fields(out);
}

}  // namespace fedsim::scenario
