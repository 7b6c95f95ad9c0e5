#include "ios/station_scenario.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace fedsim::ios {

std::vector<std::string> StationScenario::files() const {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder_, ec)) {
    if (e.path().extension() == ".yaml") names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

void StationScenario::start(const std::string& name) {
  // Only a file the station listed: never a path the page makes up.
  const auto listed = files();
  if (std::find(listed.begin(), listed.end(), name) == listed.end()) {
    throw std::invalid_argument("scenario: no file '" + name + "' in " + folder_.string());
  }
  scenario::Scenario loaded = [&] {
    try {
      return scenario::Scenario::load_file((folder_ / name).string());
    } catch (const std::exception& e) {
      throw std::invalid_argument(e.what());  // file:line: field: problem
    }
  }();
  std::lock_guard lock(mutex_);
  scenario_ = std::move(loaded);
  name_ = name;
  fired_.clear();
  running_.store(true);
}

void StationScenario::stop() {
  std::lock_guard lock(mutex_);
  running_.store(false);
  scenario_.reset();
}

std::vector<scenario::Action> StationScenario::frame(double sim_time_s, double frame_period_s, const LockedStep& step) {
  std::vector<scenario::Action> actions;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock || !scenario_) return actions;
  scenario_->set_frame_period(frame_period_s);
  const bool stepped = step([&](const scenario::FieldLookup& lookup) { actions = scenario_->step(sim_time_s, lookup); });
  if (!stepped) return actions;
  char at[32];
  std::snprintf(at, sizeof at, "t=%.2f s: ", sim_time_s);
  for (const auto& a : actions) fired_.push_back(at + a.text);
  if (scenario_->finished()) running_.store(false);
  return actions;
}

nlohmann::json StationScenario::state() const {
  std::lock_guard lock(mutex_);
  nlohmann::json out{{"running", running_.load()}, {"name", name_}, {"files", files()}};
  const std::size_t first = fired_.size() > 12 ? fired_.size() - 12 : 0;
  out["fired"] = std::vector<std::string>(fired_.begin() + static_cast<long>(first), fired_.end());
  if (scenario_) out["waiting_for"] = scenario_->missing_fields();
  return out;
}

}  // namespace fedsim::ios
