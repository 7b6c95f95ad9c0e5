#include "common/util/config_node.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace fedsim::util {

std::string read_whole_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path + ": cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

namespace {

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

int line_of(const YAML::Node& node) { return node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }

std::string kind_of(const YAML::Node& node) {
  if (node.IsMap()) return "a map";
  if (node.IsSequence()) return "a list";
  return "empty";
}

// yaml-cpp takes any node as a map key and keeps every duplicate key (a lookup finds the first,
// so a later value was silently ignored). Both are refused once, for the whole file, so that
// every reader of a config gets "file:line: field: problem" instead of a yaml-cpp conversion
// error without file or field, or a value that is never used.
void check_keys(const YAML::Node& node, const std::string& file, const std::string& path) {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      check_keys(node[i], file, path + "[" + std::to_string(i) + "]");
    }
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> first_line;
  for (const auto& kv : node) {
    const std::string where = file + ":" + std::to_string(line_of(kv.first)) + ": ";
    if (!kv.first.IsScalar()) {
      throw ConfigError(where + (path.empty() ? "(top level)" : path) +
                        ": a key must be plain text, not " + kind_of(kv.first));
    }
    const std::string key = kv.first.Scalar();
    const std::string field = path.empty() ? key : path + "." + key;
    if (const auto [first, fresh] = first_line.emplace(key, line_of(kv.first)); !fresh) {
      throw ConfigError(where + field + ": given twice (first on line " +
                        std::to_string(first->second) + ")");
    }
    check_keys(kv.second, file, field);
  }
}
}  // namespace

ConfigNode ConfigNode::load_file(const std::string& path) {
  return parse(read_whole_file(path), path);
}

ConfigNode ConfigNode::parse(const std::string& text, const std::string& origin) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(origin + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " +
                      e.msg);
  }
  check_keys(root, origin, "");
  return ConfigNode(root, origin, "");
}

ConfigNode::ConfigNode(YAML::Node node, std::string file, std::string field_path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(field_path)) {}

int ConfigNode::line() const {
  const auto mark = node_.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

std::string ConfigNode::location(const YAML::Node& at) const {
  const auto mark = at.Mark();
  const int line_no = mark.line >= 0 ? mark.line + 1 : line();
  return file_ + ":" + std::to_string(line_no);
}

std::string ConfigNode::child_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void ConfigNode::fail(const std::string& problem) const {
  throw ConfigError(location(node_) + ": " + (path_.empty() ? "(top level)" : path_) + ": " +
                    problem);
}

void ConfigNode::fail_at(const std::string& key, const std::string& problem) const {
  if (node_.IsMap() && node_[key]) {
    throw ConfigError(location(node_[key]) + ": " + child_path(key) + ": " + problem);
  }
  throw ConfigError(location(node_) + ": " + child_path(key) + ": " + problem);
}

bool ConfigNode::has(const std::string& key) const {
  return node_.IsMap() && node_[key] && !node_[key].IsNull();
}

ConfigNode ConfigNode::child(const std::string& key) const {
  if (!node_.IsMap()) fail("expected a map with field '" + key + "'");
  if (!has(key)) fail_at(key, "required field is missing");
  return ConfigNode(node_[key], file_, child_path(key));
}

std::vector<ConfigNode> ConfigNode::items() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<ConfigNode> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    out.emplace_back(node_[i], file_, path_ + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::vector<std::string> ConfigNode::keys() const {
  if (!node_.IsMap()) fail("expected a map");
  std::vector<std::string> out;
  for (const auto& kv : node_) out.push_back(kv.first.as<std::string>());
  return out;
}

double ConfigNode::as_number() const {
  if (!node_.IsScalar()) fail("expected a number");
  double value = 0;
  try {
    value = node_.as<double>();
  } catch (const YAML::Exception&) {
    fail("expected a number, got '" + node_.Scalar() + "'");
  }
  if (!std::isfinite(value)) fail("value must be finite");
  return value;
}

std::vector<double> ConfigNode::as_numbers(std::size_t expected_size) const {
  if (!node_.IsSequence()) fail("expected a list of numbers");
  std::vector<double> out;
  out.reserve(node_.size());
  for (const auto& item : items()) out.push_back(item.as_number());
  if (expected_size != 0 && out.size() != expected_size) {
    fail("expected " + std::to_string(expected_size) + " numbers, got " +
         std::to_string(out.size()));
  }
  return out;
}

std::string ConfigNode::as_string() const {
  if (!node_.IsScalar()) fail("expected a text value");
  return node_.Scalar();
}

double ConfigNode::number(const std::string& key, double min, double max) const {
  const double value = child(key).as_number();
  if (value < min || value > max) {
    std::ostringstream why;
    why << "value " << value << " is outside the allowed range [" << min << ", " << max << "]";
    fail_at(key, why.str());
  }
  return value;
}

double ConfigNode::number_or(const std::string& key, double fallback, double min,
                             double max) const {
  return has(key) ? number(key, min, max) : fallback;
}

int ConfigNode::integer(const std::string& key, int min, int max) const {
  const auto node = child(key);
  int value = 0;
  try {
    value = node.yaml().as<int>();
  } catch (const YAML::Exception&) {
    node.fail("expected a whole number, got '" + node.yaml().Scalar() + "'");
  }
  if (value < min || value > max) {
    fail_at(key, "value " + std::to_string(value) + " is outside the allowed range [" +
                     std::to_string(min) + ", " + std::to_string(max) + "]");
  }
  return value;
}

int ConfigNode::integer_or(const std::string& key, int fallback, int min, int max) const {
  return has(key) ? integer(key, min, max) : fallback;
}

bool ConfigNode::boolean(const std::string& key) const {
  const auto node = child(key);
  try {
    return node.yaml().as<bool>();
  } catch (const YAML::Exception&) {
    node.fail("expected true or false, got '" + node.yaml().Scalar() + "'");
  }
}

bool ConfigNode::boolean_or(const std::string& key, bool fallback) const {
  return has(key) ? boolean(key) : fallback;
}

std::string ConfigNode::string(const std::string& key) const { return child(key).as_string(); }

std::string ConfigNode::string_or(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::string ConfigNode::choice(const std::string& key,
                               const std::vector<std::string>& allowed) const {
  const std::string value = string(key);
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
    fail_at(key, "'" + value + "' is not one of: " + join(allowed));
  }
  return value;
}

std::string ConfigNode::choice_or(const std::string& key, const std::vector<std::string>& allowed,
                                  const std::string& fallback) const {
  return has(key) ? choice(key, allowed) : fallback;
}

std::vector<double> ConfigNode::numbers(const std::string& key, std::size_t expected_size) const {
  return child(key).as_numbers(expected_size);
}

std::vector<std::string> ConfigNode::strings(const std::string& key) const {
  std::vector<std::string> out;
  for (const auto& item : child(key).items()) out.push_back(item.as_string());
  return out;
}

void ConfigNode::reject_unknown_keys(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) fail("expected a map");
  for (const auto& kv : node_) {
    const auto key = kv.first.as<std::string>();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw ConfigError(location(kv.first) + ": " + child_path(key) +
                        ": unknown field (allowed: " + join(allowed) + ")");
    }
  }
}

}  // namespace fedsim::util
