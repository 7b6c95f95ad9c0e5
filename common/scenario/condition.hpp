// A scenario condition: a comparison of one recorded field with a number, or an all:/any: list of
// conditions (scenario.hpp describes the file format). Pure: values come from the host through a
// FieldLookup, so the same condition runs live, on a replayed recording or in a test.
#pragma once

#include "common/util/config_node.hpp"

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::scenario {

/// The current value of `field` (flattened as the recorder names its columns, e.g.
/// "velocity_ned_mps[2]", "nav[0].course_deviation") on `topic` (e.g. "fedsim/aircraft_state"),
/// in SI as published (booleans 1/0); nullopt while no sample has arrived.
using FieldLookup =
    std::function<std::optional<double>(const std::string& topic, const std::string& field)>;

/// A condition's text is wrong; what() is the problem alone (the caller adds file:line: field:).
class ConditionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

enum class Comparator { kLess, kLessEqual, kGreater, kGreaterEqual, kEqual, kNotEqual };

/// "<topic>.<field> <op> <number> [unit]", the number already converted to SI.
struct Comparison {
  std::string topic;
  std::string field;
  Comparator op = Comparator::kLess;
  double threshold = 0.0;  // SI
  std::string text;        // as written, for messages
};

/// Parses one comparison; throws ConditionError naming the problem.
Comparison parse_comparison(const std::string& text);

/// The SI factor of a unit word ("ft" -> 0.3048); nullopt if fedsim does not know it.
std::optional<double> unit_factor(const std::string& unit);

class Condition {
 public:
  /// A string (one comparison) or a map {all: [...]} / {any: [...]}; throws util::ConfigError
  /// with the node's file:line.
  static Condition parse(const util::ConfigNode& node);

  /// Whether it holds now. A comparison whose field has no value is false, and its
  /// "topic.field" is appended to `missing` (every comparison is evaluated, so the list is whole).
  bool holds(const FieldLookup& lookup, std::vector<std::string>& missing) const;

  /// Appends every "topic.field" this condition reads.
  void collect_fields(std::vector<std::string>& out) const;

 private:
  enum class Kind { kCompare, kAll, kAny };
  Kind kind_ = Kind::kCompare;
  Comparison compare_;
  std::vector<Condition> children_;
};

}  // namespace fedsim::scenario
