#include "scenario/scenario_component.hpp"

#include "common/runtime/sim_command_codec.hpp"
#include "common/util/config_node.hpp"
#include "tools/topic/typed_flattener.hpp"

#include <charconv>
#include <set>

namespace fedsim::scenario {

namespace {

/// "fedsim/engine_state[1]" -> "fedsim/engine_state"; a topic without an instance stays.
std::string base_topic(const std::string& topic) {
  const auto bracket = topic.find('[');
  return bracket == std::string::npos ? topic : topic.substr(0, bracket);
}

/// The topic part of "topic.field" (the field starts at the first '.' after the last '/').
std::string topic_of(const std::string& topic_field) {
  const auto slash = topic_field.rfind('/');
  const auto dot = topic_field.find('.', slash == std::string::npos ? 0 : slash);
  return topic_field.substr(0, dot);
}

std::optional<double> as_number(const std::string& cell) {
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (ec != std::errc() || ptr != cell.data() + cell.size() || cell.empty()) return std::nullopt;
  return v;
}

/// The instance a keyed sample is: "[<engine_index>]" / "[<channel_id>]" (as the instructor
/// station names them), "" for a topic with one instance.
std::string instance_suffix(const std::vector<std::string>& names, const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i) {
    if (names[i] == "engine_index" || names[i] == "channel_id") return "[" + cells[i] + "]";
  }
  return {};
}

}  // namespace

ScenarioComponent::ScenarioComponent(std::string name, Scenario scenario)
    : Component(std::move(name)),
      scenario_(std::move(scenario)),
      commands_(writes(runtime::topics::sim_command)) {
  std::set<std::string> topics;
  for (const std::string& f : scenario_.fields()) topics.insert(base_topic(topic_of(f)));
  for (const std::string& topic : topics) {
    const bool known = runtime::topics::visit(topic, [&](const auto& catalogue_topic) {
      using T = typename std::decay_t<decltype(catalogue_topic)>::Message;
      if (runtime::topics::is_backbone(topic)) {
        throw std::invalid_argument("scenario: a condition reads " + topic +
                                    ", a backbone topic; conditions read state topics");
      }
      auto& port = reads(catalogue_topic);
      auto flattener = std::make_shared<tools::TypedFlattener<T>>(catalogue_topic);
      auto seen = std::make_shared<std::uint64_t>(0);
      refreshers_.push_back([this, &port, flattener, seen, topic] {
        if (port.updates() == *seen || !port.latest()) return;
        *seen = port.updates();
        const std::vector<std::string> cells = flattener->cells(*port.latest());
        auto& values = fields_[topic + instance_suffix(flattener->names(), cells)];
        for (std::size_t i = 0; i < cells.size(); ++i) {
          if (const auto v = as_number(cells[i])) values[flattener->names()[i]] = *v;
        }
      });
    });
    if (!known) {
      throw std::invalid_argument("scenario: a condition reads '" + topic + "', which is not a fedsim topic (" +
                                  "fedsim/aircraft_state, fedsim/navigation_state, fedsim/engine_state ...)");
    }
  }
}

std::optional<double> ScenarioComponent::lookup(const std::string& topic, const std::string& field) const {
  const auto t = fields_.find(topic);
  if (t == fields_.end()) return std::nullopt;
  const auto f = t->second.find(field);
  if (f == t->second.end()) return std::nullopt;
  return f->second;
}

void ScenarioComponent::step(const runtime::FrameContext& frame) {
  for (auto& refresh : refreshers_) refresh();
  scenario_.set_frame_period(frame.frame_period_s);
  const auto actions = scenario_.step(frame.sim_time_s, [this](const std::string& t, const std::string& f) {
    return lookup(t, f);
  });
  for (const Action& a : actions) act(a, frame);
  // A field a condition waits for that never came is worth one line (a typo shows here).
  const auto missing = scenario_.missing_fields();
  if (frame.sim_time_s > 2.0 && missing != reported_missing_) {
    reported_missing_ = missing;
    for (const auto& m : missing) log().warn("scenario: no value of {} yet (is its writer running? is the name right?)", m);
  }
}

void ScenarioComponent::act(const Action& a, const runtime::FrameContext& frame) {
  fired_.push_back({frame.sim_time_s, a.text});
  switch (a.kind) {
    case Action::Kind::kLog:
      log().info("scenario t={:.2f}s (line {}): {}", frame.sim_time_s, a.line, a.text);
      return;
    case Action::Kind::kStop: {
      log().info("scenario t={:.2f}s (line {}): stop: the scenario ends the run", frame.sim_time_s, a.line);
      msg::SimCommand c = runtime::to_sim_command(instructor::ShutdownRequest{});
      c.issuer(name());
      c.sequence_number(++sequence_);
      commands_.write(c);
      return;
    }
    case Action::Kind::kCommand: {
      msg::SimCommand c = runtime::to_sim_command(a.command);
      c.issuer(name());
      c.sequence_number(++sequence_);
      log().info("scenario t={:.2f}s (line {}): {}", frame.sim_time_s, a.line, a.text);
      if (!commands_.write(c)) report_fault("command_rejected", "scenario: the command writer refused " + a.text);
      return;
    }
  }
}

runtime::FederateProgram program() {
  auto file = std::make_shared<std::string>();
  runtime::FederateProgram p;
  p.program = "fedsim-scenario";
  p.default_name = "scenario";
  p.description = "runs an instructor scenario file: timed and conditional events sent as instructor commands";
  p.add_options = [file](CLI::App& app) {
    app.add_option("--file", *file, "the scenario (YAML; data/scenarios has examples)")->required();
  };
  p.make_component = [file](const runtime::FederateOptions& common) {
    return std::unique_ptr<runtime::Component>(
        std::make_unique<ScenarioComponent>(common.name, Scenario::load_file(*file)));
  };
  return p;
}

}  // namespace fedsim::scenario
