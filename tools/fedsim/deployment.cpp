#include "fedsim/deployment.hpp"

#include "common/util/config_node.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

namespace fedsim::launcher {

namespace {

using util::ConfigNode;

std::vector<std::string> string_list(const ConfigNode& node, const std::string& key) {
  if (!node.has(key)) return {};
  std::vector<std::string> out;
  for (const auto& item : node.child(key).items()) out.push_back(item.as_string());
  return out;
}

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}

/// A name of the deployment or a federate. Names become file names (out/<deployment>/,
/// logs/<federate>.log: no '/' or '..'), a comma-separated list (the timing federate's --expect)
/// and FederateStatus.federate (string<32>), so: 1-32 of [A-Za-z0-9_-].
std::string read_name(const ConfigNode& node) {
  const std::string name = node.string("name");
  const bool ok = !name.empty() && name.size() <= 32 &&
                  std::all_of(name.begin(), name.end(), is_name_char);
  if (!ok) node.fail_at("name", "'" + name + "' must be 1-32 characters of A-Z a-z 0-9 _ -");
  return name;
}

FederateSpec read_federate(const ConfigNode& node) {
  node.reject_unknown_keys({"name", "binary", "args", "lockstep", "federate_options", "required",
                            "restart", "max_restarts"});
  FederateSpec spec;
  spec.name = read_name(node);
  spec.binary = node.string("binary");
  spec.args = string_list(node, "args");
  spec.lockstep = node.boolean_or("lockstep", true);
  spec.federate_options = node.boolean_or("federate_options", true);
  spec.required = node.boolean_or("required", true);
  spec.restart_on_failure = node.choice_or("restart", {"no", "on-failure"}, "no") == "on-failure";
  if (node.has("max_restarts")) {
    if (!spec.restart_on_failure) node.fail_at("max_restarts", "needs restart: on-failure");
    spec.max_restarts = node.integer("max_restarts", 1, 100);
  }
  if (spec.lockstep && !spec.federate_options) {
    node.fail_at("lockstep", "a lockstep federate needs the federate options (--name...)");
  }
  return spec;
}

/// An after-step: a command (a list), or {run: command, needs: [files], whole_run: bool}.
/// A needed file must be named in the step's arguments: `needs` says which of what the step
/// reads may be missing, so a name that is not among them is a typo that would skip it forever.
AfterStep read_after_step(const ConfigNode& node) {
  AfterStep step;
  if (!node.yaml().IsMap()) {
    for (const auto& word : node.items()) step.argv.push_back(word.as_string());
    if (step.argv.empty()) node.fail("an 'after' command is empty");
    return step;
  }
  node.reject_unknown_keys({"run", "needs", "whole_run"});
  step.argv = string_list(node, "run");
  if (step.argv.empty()) node.fail_at("run", "an 'after' command is empty (or missing)");
  step.needs = string_list(node, "needs");
  for (const auto& file : step.needs) {
    const bool named = std::any_of(step.argv.begin(), step.argv.end(), [&file](const std::string& word) {
      return !file.empty() && word.find(file) != std::string::npos;
    });
    if (!named) node.fail_at("needs", "'" + file + "' is not named in the step's arguments");
  }
  step.whole_run = node.boolean_or("whole_run", false);
  return step;
}

Deployment read(const ConfigNode& root) {
  root.reject_unknown_keys({"name", "mode", "rate_hz", "domain", "qos_file", "participant_profile",
                            "sync_qos", "timing", "federates", "after"});
  Deployment d;
  d.file = root.file();
  d.name = read_name(root);
  d.mode = root.choice_or("mode", {"realtime", "lockstep"}, "lockstep");
  d.rate_hz = root.number_or("rate_hz", 50.0, 1.0, 10000.0);
  if (root.has("domain")) {
    d.domain = root.integer("domain", 0, 232);
    d.domain_given = true;
  }
  d.qos_file = root.string_or("qos_file", "${SOURCE_DIR}/qos/fedsim_qos.xml");
  d.participant_profile = root.string_or("participant_profile", "fedsim_loopback");
  d.sync_qos = root.choice_or("sync_qos", {"best_effort", "reliable"}, "best_effort");
  if (root.has("timing")) {
    const auto timing = root.child("timing");
    timing.reject_unknown_keys({"args", "enabled"});
    d.timing_args = string_list(timing, "args");
    d.has_timing = timing.boolean_or("enabled", true);
  }
  std::set<std::string> names{"timing"};
  for (const auto& item : root.child("federates").items()) {
    auto spec = read_federate(item);
    if (!names.insert(spec.name).second) {
      item.fail_at("name", "'" + spec.name + "' is used twice (or clashes with the timing federate)");
    }
    d.federates.push_back(std::move(spec));
  }
  if (d.federates.empty()) root.fail_at("federates", "lists no federate");
  if (root.has("after")) {
    for (const auto& item : root.child("after").items()) d.after.push_back(read_after_step(item));
  }
  return d;
}

}  // namespace

Deployment load_deployment(const std::string& path) { return read(ConfigNode::load_file(path)); }

Deployment parse_deployment(const std::string& text, const std::string& origin) {
  return read(ConfigNode::parse(text, origin));
}

std::string substitute(const std::string& text, const std::map<std::string, std::string>& vars) {
  std::string out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto start = text.find("${", pos);
    if (start == std::string::npos) {
      out += text.substr(pos);
      break;
    }
    const auto end = text.find('}', start);
    if (end == std::string::npos) throw util::ConfigError("unterminated ${ in '" + text + "'");
    out += text.substr(pos, start - pos);
    const std::string name = text.substr(start + 2, end - start - 2);
    const auto it = vars.find(name);
    if (it == vars.end()) throw util::ConfigError("unknown variable ${" + name + "} in '" + text + "'");
    out += it->second;
    pos = end + 1;
  }
  return out;
}

}  // namespace fedsim::launcher
