// fedsim-scenario: runs an instructor scenario file (common/scenario, seed 9.8) in the federation,
// frame by frame: timed events on the frame's sim time, conditions on the fields of the topics
// the file names (flattened as the recorder names CSV columns), actions sent as instructor
// commands; `stop` sends SHUTDOWN, which ends the run. `fedsim run --scenario FILE` adds it to
// any deployment.
//
// Ports (declared from the file):
//   reads   each catalogue topic a condition names (a lockstep input where the catalogue says
//           so: in lockstep, frame N's conditions see frame N-1's state, every run alike)
//   writes  fedsim/sim_command (reliable, transient local)
#pragma once

#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "common/scenario/scenario.hpp"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::scenario {

class ScenarioComponent final : public runtime::Component {
 public:
  ScenarioComponent(std::string name, Scenario scenario);
  void step(const runtime::FrameContext& frame) override;

  /// Actions sent so far (commands, logs and stops), in order, with their frame's sim time.
  struct Fired {
    double sim_time_s = 0.0;
    std::string text;
  };
  const std::vector<Fired>& fired() const { return fired_; }

 private:
  void refresh_fields();
  std::optional<double> lookup(const std::string& topic, const std::string& field) const;
  void act(const Action& action, const runtime::FrameContext& frame);

  Scenario scenario_;
  // One per topic a condition reads: refreshes that topic's (instances') fields when it updated.
  std::vector<std::function<void()>> refreshers_;
  std::map<std::string, std::map<std::string, double>> fields_;  // instance -> field -> value
  std::uint32_t sequence_ = 0;
  std::vector<Fired> fired_;
  std::vector<std::string> reported_missing_;

  // ---- Ports ----
  runtime::Output<msg::SimCommand>& commands_;
};

/// The program: --file FILE (checked before anything is sent: file:line errors, exit 2).
runtime::FederateProgram program();

}  // namespace fedsim::scenario
