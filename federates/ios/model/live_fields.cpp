#include "ios/model/live_fields.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>

namespace fedsim::ios {

namespace {

std::optional<double> as_number(const std::string& cell) {
  if (cell == "nan") return std::nan("");
  if (cell == "inf") return HUGE_VAL;
  if (cell == "-inf") return -HUGE_VAL;
  double v = 0.0;
  const char* end = cell.data() + cell.size();
  const auto [ptr, ec] = std::from_chars(cell.data(), end, v);
  if (ec != std::errc() || ptr != end || cell.empty()) return std::nullopt;
  return v;
}

std::string unquoted(const std::string& cell) {
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') {
    std::string out;
    for (std::size_t i = 1; i + 1 < cell.size(); ++i) {
      out += cell[i];
      if (cell[i] == '"' && cell[i + 1] == '"') ++i;  // CSV's doubled quote
    }
    return out;
  }
  return cell;
}

}  // namespace

void LiveFields::update(const std::string& topic, const std::vector<std::string>& names,
                        const std::vector<std::string>& cells, double now_s) {
  TopicFields& t = topics_[topic];
  t.names.clear();
  t.values.clear();
  t.text.clear();
  for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i) {
    if (const auto v = as_number(cells[i])) {
      t.names.push_back(names[i]);
      t.values.push_back(*v);
    } else if (!cells[i].empty() && cells[i].front() != '[') {
      t.text[names[i]] = unquoted(cells[i]);
    }
  }
  ++t.samples;
  t.updated_s = now_s;
}

void LiveFields::set(const std::string& topic, const std::string& field, double value, double now_s) {
  TopicFields& t = topics_[topic];
  for (std::size_t i = 0; i < t.names.size(); ++i) {
    if (t.names[i] == field) {
      t.values[i] = value;
      t.updated_s = now_s;
      return;
    }
  }
  t.names.push_back(field);
  t.values.push_back(value);
  t.updated_s = now_s;
}

std::optional<double> LiveFields::value(const std::string& topic, const std::string& field) const {
  const auto it = topics_.find(topic);
  if (it == topics_.end()) return std::nullopt;
  for (std::size_t i = 0; i < it->second.names.size(); ++i) {
    if (it->second.names[i] == field) return it->second.values[i];
  }
  return std::nullopt;
}

std::string LiveFields::to_json() const {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [topic, t] : topics_) {
    nlohmann::json fields = nlohmann::json::object();
    for (std::size_t i = 0; i < t.names.size(); ++i) {
      fields[t.names[i]] = std::isfinite(t.values[i]) ? nlohmann::json(t.values[i]) : nlohmann::json(nullptr);
    }
    out[topic] = {{"n", t.samples}, {"f", std::move(fields)}, {"t", t.text}};
  }
  return out.dump();
}

std::string instance_name(const std::string& topic, const std::vector<std::string>& names,
                          const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i) {
    if (names[i] == "engine_index" || names[i] == "channel_id") return topic + "[" + unquoted(cells[i]) + "]";
  }
  return topic;
}

}  // namespace fedsim::ios
