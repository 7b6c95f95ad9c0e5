// The scenario federate in-process: its timed events fire on the frame's sim time, its conditions
// read the fields of the state it names, its commands reach the other federates, and `stop` ends
// the run. Every check has a control that would show a false pass.
#include "scenario/scenario_component.hpp"
#include "common/util/build_paths.hpp"

#include "common/runtime/composition.hpp"

#include <gtest/gtest.h>

namespace fedsim::scenario {
namespace {

/// An aircraft descending at 10 m/s from 500 m; notes the failure commands it receives.
class Descending final : public runtime::Component {
 public:
  Descending() : Component("flight"), out_(writes(runtime::topics::aircraft_state)) {}
  void on_command(const msg::SimCommand& c) override {
    failure_pending_ |= c.kind() == msg::COMMAND_FAILURE;
  }
  void step(const runtime::FrameContext& frame) override {
    if (failure_pending_) failed_at_s.push_back(frame.sim_time_s);  // the frame it acts in
    failure_pending_ = false;
    msg::AircraftState s;
    s.altitude_msl_m(500.0 - 10.0 * frame.end_time_s());
    s.stamp(frame.end_stamp());
    out_.write(s);
  }
  std::vector<double> failed_at_s;

 private:
  bool failure_pending_ = false;
  runtime::Output<msg::AircraftState>& out_;
};

struct ScenarioRun {
  explicit ScenarioRun(const std::string& stop_below)
      : scenario("scenario", Scenario::parse(R"(name: test
events:
  - at_s: 1
    do: {command: fail, system: engine1}
  - when: "fedsim/aircraft_state.altitude_msl_m < 300 m"
    do: {log: "below 300 m"}
  - when: "fedsim/aircraft_state.altitude_msl_m < )" + stop_below + R"("
    for_s: 0.5
    do: stop
)", "test.yaml")),
        composition({}) {
    composition.add(aircraft);
    composition.add(scenario);
    // What a component writes on fedsim/sim_command goes to everyone, as over DDS.
    composition.on_written(runtime::topics::sim_command,
                           std::function<void(const msg::SimCommand&)>(
                               [this](const msg::SimCommand& c) { composition.command(c); }));
    frames = composition.run(1500);
  }
  Descending aircraft;
  ScenarioComponent scenario;
  runtime::Composition composition;
  std::uint64_t frames = 0;
};

TEST(ScenarioComponent, TimedAndConditionalEventsThenStop) {
  ScenarioRun run("1000 ft");
  const auto& fired = run.scenario.fired();
  ASSERT_EQ(fired.size(), 3u);
  EXPECT_EQ(fired[0].text, "fail engine1");
  EXPECT_NEAR(fired[0].sim_time_s, 1.0, 1e-9);                    // in the frame that starts at 1 s
  ASSERT_EQ(run.aircraft.failed_at_s.size(), 1u);                 // the command reached the aircraft
  EXPECT_NEAR(run.aircraft.failed_at_s[0], 1.02, 1e-9);           // the next frame
  // 1000 ft = 304.8 m: the state says so at 19.52 s, read one frame later, held 0.5 s.
  EXPECT_EQ(fired[1].text, "below 300 m");
  EXPECT_NEAR(fired[1].sim_time_s, 20.02, 1e-9);
  EXPECT_EQ(fired[2].text, "stop");
  EXPECT_NEAR(fired[2].sim_time_s, 20.04, 1e-9);
  EXPECT_LT(run.frames, 1010u);  // the SHUTDOWN ended the run
  EXPECT_TRUE(run.composition.shutdown_requested());
}

TEST(ScenarioComponent, AConditionThatNeverHoldsNeverStops) {
  ScenarioRun run("100 m");  // the aircraft is still at 200 m at 30 s
  EXPECT_EQ(run.frames, 1500u);
  EXPECT_FALSE(run.composition.shutdown_requested());
  EXPECT_EQ(run.scenario.fired().size(), 2u);  // the failure and the log, no stop
}

TEST(ScenarioComponent, RefusesATopicThatIsNotFedsims) {
  EXPECT_THROW(ScenarioComponent("s", Scenario::parse(R"(name: t
events:
  - when: "fedsim/no_such_topic.x > 1"
    do: stop
)", "t.yaml")),
               std::invalid_argument);
}

TEST(ScenarioComponent, EveryShippedScenarioBuildsItsPorts) {
  for (const char* file : {"engine_failure_approach.yaml", "freeze_and_reposition.yaml"}) {
    ScenarioComponent component("scenario", Scenario::load_file(fedsim::util::data_dir() + "/scenarios/" + file));
    EXPECT_FALSE(component.ports().empty()) << file;
  }
}

}  // namespace
}  // namespace fedsim::scenario
