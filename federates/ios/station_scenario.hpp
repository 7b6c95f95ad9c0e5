// The instructor station's scenario runner (seed 9.8): a scenario file of the --scenarios
// folder, chosen on the page, run on the station's frame thread: timed events on the tick's sim
// time (an event already past fires at once), conditions on the station's field registry.
// It never makes a frame wait: if the page holds the runner, or the caller cannot take its
// registry at once, the frame is skipped and the scenario catches up in the next one.
#pragma once

#include "common/scenario/scenario.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::ios {

class StationScenario {
 public:
  explicit StationScenario(std::filesystem::path folder) : folder_(std::move(folder)) {}

  /// The scenario files the page may run (*.yaml in the folder), sorted.
  std::vector<std::string> files() const;
  /// Loads and starts a listed file; throws std::invalid_argument (a name not listed, or the
  /// file's own "file:line: field: problem").
  void start(const std::string& name);
  void stop();
  bool running() const { return running_.load(); }

  /// One frame (frame thread). `step` runs the scenario's step with the registry held, or returns
  /// false when the registry is busy (the frame is then skipped). Returns the actions due.
  using LockedStep = std::function<bool(const std::function<void(const scenario::FieldLookup&)>&)>;
  std::vector<scenario::Action> frame(double sim_time_s, double frame_period_s, const LockedStep& step);

  /// {"running", "name", "files", "fired" (the last 12, with their sim time), "waiting_for"}
  nlohmann::json state() const;

 private:
  std::filesystem::path folder_;
  mutable std::mutex mutex_;
  std::optional<scenario::Scenario> scenario_;
  std::atomic<bool> running_{false};
  std::string name_;
  std::vector<std::string> fired_;
};

}  // namespace fedsim::ios
