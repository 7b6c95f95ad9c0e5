// Validated access to YAML configuration files: every error names file, line and field.
#pragma once

#include <yaml-cpp/yaml.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::util {

/// Thrown for any invalid configuration; what() reads "file:line: field: problem".
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A whole text file; throws ConfigError "<path>: cannot open file".
std::string read_whole_file(const std::string& path);

/// A YAML node plus where it came from (file, dotted field path), so that callers can fail with
/// a message that points at the offending line. Reading is strict: unknown keys can be rejected,
/// numbers are range-checked and units are part of the key names (e.g. `wing_area_m2`).
class ConfigNode {
 public:
  /// Loads a YAML file; throws ConfigError naming the file (and line) if it is unreadable.
  static ConfigNode load_file(const std::string& path);
  /// Parses YAML text; `origin` is used as the file name in error messages.
  static ConfigNode parse(const std::string& text, const std::string& origin);

  ConfigNode(YAML::Node node, std::string file, std::string field_path);

  bool has(const std::string& key) const;
  ConfigNode child(const std::string& key) const;  ///< required map entry
  std::vector<ConfigNode> items() const;           ///< elements of a required sequence
  std::vector<std::string> keys() const;           ///< keys of a map, in file order

  double number(const std::string& key, double min = -std::numeric_limits<double>::infinity(),
                double max = std::numeric_limits<double>::infinity()) const;
  double number_or(const std::string& key, double fallback,
                   double min = -std::numeric_limits<double>::infinity(),
                   double max = std::numeric_limits<double>::infinity()) const;
  int integer(const std::string& key, int min = std::numeric_limits<int>::min(),
              int max = std::numeric_limits<int>::max()) const;
  int integer_or(const std::string& key, int fallback, int min = std::numeric_limits<int>::min(),
                 int max = std::numeric_limits<int>::max()) const;
  bool boolean(const std::string& key) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  std::string string_or(const std::string& key, const std::string& fallback) const;
  /// One of `allowed`; the error lists the allowed values.
  std::string choice(const std::string& key, const std::vector<std::string>& allowed) const;
  std::string choice_or(const std::string& key, const std::vector<std::string>& allowed,
                        const std::string& fallback) const;
  /// A flow or block sequence of numbers; `expected_size` 0 means any length.
  std::vector<double> numbers(const std::string& key, std::size_t expected_size = 0) const;
  std::vector<std::string> strings(const std::string& key) const;

  /// This node read as a scalar number (for sequences of numbers).
  double as_number() const;
  /// This node read as a sequence of numbers.
  std::vector<double> as_numbers(std::size_t expected_size = 0) const;
  std::string as_string() const;

  /// Fails on any map key not in `allowed` (catches typos such as `wing_area_ft2`).
  void reject_unknown_keys(const std::vector<std::string>& allowed) const;

  [[noreturn]] void fail(const std::string& problem) const;
  [[noreturn]] void fail_at(const std::string& key, const std::string& problem) const;

  const YAML::Node& yaml() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& field_path() const { return path_; }
  int line() const;  ///< 1-based line of this node in its file (0 if unknown)

 private:
  std::string location(const YAML::Node& at) const;
  std::string child_path(const std::string& key) const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
};

}  // namespace fedsim::util
