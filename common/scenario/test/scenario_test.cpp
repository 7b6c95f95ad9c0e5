// Scenario files: parsed with file:line errors, run frame by frame against a fake field lookup.
#include "common/scenario/scenario.hpp"
#include "common/util/build_paths.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>

namespace fedsim::scenario {
namespace {

constexpr double kFrame = 1.0 / 50.0;
const std::string kState = "fedsim/aircraft_state";

/// Field values a test sets; fields never set have no value.
struct FakeFields {
  std::map<std::string, double> values;  // "topic.field" -> value
  FieldLookup lookup() const {
    return [this](const std::string& topic, const std::string& field) -> std::optional<double> {
      const auto it = values.find(topic + "." + field);
      if (it == values.end()) return std::nullopt;
      return it->second;
    };
  }
};

FieldLookup no_fields() {
  return [](const std::string&, const std::string&) { return std::optional<double>(); };
}

/// The frame index's sim time as a 50 Hz loop accumulates it (rounding included on purpose).
std::vector<double> accumulated_times(int frames) {
  std::vector<double> out;
  double t = 0.0;
  for (int i = 0; i < frames; ++i, t += kFrame) out.push_back(t);
  return out;
}

/// The error of parsing `text` ("(accepted)" if it parses).
std::string error_of(const std::string& text) {
  try {
    Scenario::parse(text, "s.yaml");
  } catch (const util::ConfigError& e) {
    return e.what();
  }
  return "(accepted)";
}

/// The line number of a "s.yaml:<line>: ..." error (-1 if it does not start that way).
int line_of(const std::string& error) {
  const std::string prefix = "s.yaml:";
  if (error.rfind(prefix, 0) != 0) return -1;
  return std::stoi(error.substr(prefix.size()));
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Scenario, TimedEventsFireInTheirFrameOnce) {
  auto s = Scenario::parse(R"(name: timed
events:
  - at_s: 5
    do: {command: freeze}
  - at_s: 8
    do: {command: run}
)", "s.yaml");
  std::map<int, std::vector<std::string>> by_frame;
  const auto times = accumulated_times(600);
  for (std::size_t i = 0; i < times.size(); ++i) {
    for (const auto& a : s.step(times[i], no_fields())) by_frame[static_cast<int>(i)].push_back(a.text);
  }
  ASSERT_EQ(by_frame.size(), 2u);  // each once
  EXPECT_EQ(by_frame.at(250), std::vector<std::string>{"freeze"});  // 250 * 20 ms = 5 s
  EXPECT_EQ(by_frame.at(400), std::vector<std::string>{"run"});
  // Control: frame 249 (4.98 s) is before the event.
  EXPECT_FALSE(by_frame.count(249));
}

TEST(Scenario, TimedEventToleratesRoundingBelowItsTime) {
  auto s = Scenario::parse("name: t\nevents:\n  - at_s: 5\n    do: stop\n", "s.yaml");
  EXPECT_TRUE(s.step(4.98, no_fields()).empty());
  EXPECT_EQ(s.step(5.0 - 1e-9, no_fields()).size(), 1u);
  EXPECT_TRUE(s.finished());
}

TEST(Scenario, CommandActionsCarryTheValidatedRequest) {
  auto s = Scenario::parse(R"(name: c
events:
  - at_s: 0
    do:
      command: reposition
      airport: KSFO
      runway: 28R
      gate_nm: 10
)", "s.yaml");
  const auto fired = s.step(0.0, no_fields());
  ASSERT_EQ(fired.size(), 1u);
  EXPECT_EQ(fired[0].kind, Action::Kind::kCommand);
  EXPECT_EQ(fired[0].line, 3);
  const auto& r = std::get<instructor::RepositionRequest>(fired[0].command);
  EXPECT_EQ(r.kind, instructor::RepositionRequest::Kind::kApproachGate);
  EXPECT_DOUBLE_EQ(r.gate_distance_m, 10 * units::kNmToM);
}

TEST(Scenario, ConditionWithUnitFiresWhenTheValueCrosses) {
  auto s = Scenario::parse(R"(name: c
events:
  - when: "fedsim/aircraft_state.height_agl_m < 500 ft"
    do: {command: fail, system: engine1}
)", "s.yaml");
  FakeFields f;
  const double threshold_m = 500 * units::kFtToM;  // 152.4 m
  f.values[kState + ".height_agl_m"] = 160.0;      // above 500 ft, below 500 m
  EXPECT_TRUE(s.step(0.0, f.lookup()).empty());   // read as feet, not metres
  f.values[kState + ".height_agl_m"] = threshold_m + 0.01;
  EXPECT_TRUE(s.step(kFrame, f.lookup()).empty());
  f.values[kState + ".height_agl_m"] = threshold_m - 0.01;
  const auto fired = s.step(2 * kFrame, f.lookup());
  ASSERT_EQ(fired.size(), 1u);
  EXPECT_EQ(std::get<instructor::FailureRequest>(fired[0].command).system, "engine1");
  EXPECT_TRUE(s.step(3 * kFrame, f.lookup()).empty());  // once
}

TEST(Scenario, ConditionThatNeverCrossesNeverFires) {
  auto s = Scenario::parse(R"(name: c
events:
  - when: "fedsim/aircraft_state.height_agl_m < 500 ft"
    do: stop
)", "s.yaml");
  FakeFields f;
  for (int i = 0; i < 500; ++i) {
    f.values[kState + ".height_agl_m"] = 1000.0 - i;  // descends to 501 m, never below 152.4 m
    EXPECT_TRUE(s.step(i * kFrame, f.lookup()).empty());
  }
  EXPECT_FALSE(s.finished());
}

TEST(Scenario, MissingFieldIsFalseAndListed) {
  auto s = Scenario::parse(R"(name: m
events:
  - when: {any: ["fedsim/aircraft_state.on_ground == 1", "fedsim/navigation_state.nav[0].course_deviation > 0.5"]}
    do: stop
)", "s.yaml");
  EXPECT_EQ(s.fields(), (std::vector<std::string>{"fedsim/aircraft_state.on_ground",
                                                  "fedsim/navigation_state.nav[0].course_deviation"}));
  FakeFields f;
  f.values[kState + ".on_ground"] = 0.0;
  EXPECT_TRUE(s.step(0.0, f.lookup()).empty());
  EXPECT_EQ(s.missing_fields(), std::vector<std::string>{"fedsim/navigation_state.nav[0].course_deviation"});
  f.values["fedsim/navigation_state.nav[0].course_deviation"] = 0.6;
  EXPECT_EQ(s.step(kFrame, f.lookup()).size(), 1u);  // control: with the value it fires
  EXPECT_TRUE(s.missing_fields().empty());
}

TEST(Scenario, AllNeedsEveryPart) {
  auto s = Scenario::parse(R"(name: a
events:
  - when: {all: ["fedsim/aircraft_state.on_ground == 1", "fedsim/aircraft_state.ground_speed_mps < 5 kt"]}
    do: stop
)", "s.yaml");
  FakeFields f;
  f.values[kState + ".on_ground"] = 1.0;
  f.values[kState + ".ground_speed_mps"] = 3.0;  // > 5 kt (2.57 m/s)
  EXPECT_TRUE(s.step(0.0, f.lookup()).empty());
  f.values[kState + ".ground_speed_mps"] = 2.0;
  EXPECT_EQ(s.step(kFrame, f.lookup()).size(), 1u);
}

TEST(Scenario, ForSecondsNeedsTheConditionHeldWithoutBreak) {
  auto s = Scenario::parse(R"(name: hold
events:
  - when: "fedsim/aircraft_state.on_ground == 1"
    for_s: 10
    do: stop
)", "s.yaml");
  FakeFields f;
  f.values[kState + ".on_ground"] = 1.0;
  const auto times = accumulated_times(2000);
  int fired_at = -1;
  for (int i = 0; i < 2000 && fired_at < 0; ++i) {
    // Broken at frame 300 (6 s): the count restarts at frame 301 (6.02 s).
    f.values[kState + ".on_ground"] = i == 300 ? 0.0 : 1.0;
    if (!s.step(times[i], f.lookup()).empty()) fired_at = i;
  }
  EXPECT_EQ(fired_at, 301 + 500);  // 10 s after the hold restarted, not 10 s after the start
  EXPECT_TRUE(s.finished());
}

TEST(Scenario, StopEndsTheScenarioAndLaterActionsDoNotFire) {
  auto s = Scenario::parse(R"(name: s
events:
  - at_s: 1
    do: {log: "first"}
  - at_s: 1
    do: stop
  - at_s: 1
    do: {log: "after the stop"}
  - at_s: 2
    do: {log: "later"}
)", "s.yaml");
  const auto fired = s.step(1.0, no_fields());
  ASSERT_EQ(fired.size(), 2u);
  EXPECT_EQ(fired[0].kind, Action::Kind::kLog);
  EXPECT_EQ(fired[0].text, "first");
  EXPECT_EQ(fired[1].kind, Action::Kind::kStop);
  EXPECT_TRUE(s.finished());
  EXPECT_TRUE(s.step(2.0, no_fields()).empty());
}

TEST(Scenario, SimTimeGoingBackReArms) {
  auto s = Scenario::parse(R"(name: r
events:
  - at_s: 1
    do: {command: freeze}
  - when: "fedsim/aircraft_state.on_ground == 0"
    do: {log: "airborne"}
)", "s.yaml");
  FakeFields f;
  f.values[kState + ".on_ground"] = 0.0;
  int freezes = 0, logs = 0;
  auto run = [&](double from, double to) {
    for (double t = from; t < to; t += kFrame) {
      for (const auto& a : s.step(t, f.lookup())) (a.kind == Action::Kind::kLog ? logs : freezes)++;
    }
  };
  run(0.0, 3.0);
  EXPECT_EQ(freezes, 1);
  EXPECT_EQ(logs, 1);
  run(3.0, 6.0);  // control: time going on does not re-arm
  EXPECT_EQ(freezes, 1);
  run(0.0, 3.0);  // RESET: sim time back to 0
  EXPECT_EQ(freezes, 2);
  EXPECT_EQ(logs, 2);
}

TEST(Scenario, ResetAfterStopRunsAgain) {
  auto s = Scenario::parse("name: r\nevents:\n  - at_s: 1\n    do: stop\n", "s.yaml");
  s.step(1.0, no_fields());
  ASSERT_TRUE(s.finished());
  s.step(1.0, no_fields());  // a frozen frame (same time) is not a reset
  EXPECT_TRUE(s.finished());
  s.step(0.0, no_fields());
  EXPECT_FALSE(s.finished());
}

TEST(Scenario, EverySecondsRepeats) {
  auto s = Scenario::parse(R"(name: e
events:
  - every_s: 30
    do: {command: snapshot, tag: periodic}
)", "s.yaml");
  std::vector<int> frames;
  const auto times = accumulated_times(50 * 100 + 1);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!s.step(times[i], no_fields()).empty()) frames.push_back(static_cast<int>(i));
  }
  EXPECT_EQ(frames, (std::vector<int>{1500, 3000, 4500}));
}

TEST(Scenario, EveryWithAtStartsThere) {
  auto s = Scenario::parse("name: e\nevents:\n  - at_s: 0\n    every_s: 2\n    do: {log: tick}\n", "s.yaml");
  int count = 0;
  for (double t = 0.0; t < 5.0; t += 0.5) count += static_cast<int>(s.step(t, no_fields()).size());
  EXPECT_EQ(count, 3);  // 0, 2, 4
}

// ---- Validation: each error names the file and the line ----

TEST(ScenarioErrors, UnknownKeyNamesItsLine) {
  const auto e = error_of("name: x\nevents:\n  - at_s: 1\n    do: stop\n    whn: x\n");
  EXPECT_EQ(line_of(e), 5) << e;
  EXPECT_TRUE(contains(e, "events[0].whn: unknown field")) << e;
  EXPECT_EQ(error_of("name: x\nevents:\n  - at_s: 1\n    do: stop\n"), "(accepted)");  // control
}

TEST(ScenarioErrors, UnknownTopLevelKeyAndDuplicateKey) {
  EXPECT_EQ(line_of(error_of("name: x\nevent:\n  - at_s: 1\n    do: stop\n")), 2);
  const auto e = error_of("name: x\nevents:\n  - at_s: 1\n    do: stop\n    do: {log: y}\n");
  EXPECT_EQ(line_of(e), 5) << e;
  EXPECT_TRUE(contains(e, "given twice")) << e;
}

TEST(ScenarioErrors, EventNeedsExactlyOneTrigger) {
  const auto neither = error_of("name: x\nevents:\n  - at_s: 1\n    do: stop\n  - do: stop\n");
  EXPECT_EQ(line_of(neither), 5) << neither;
  EXPECT_TRUE(contains(neither, "needs at_s, every_s or when")) << neither;
  const auto both = error_of(
      "name: x\nevents:\n  - at_s: 1\n    when: \"fedsim/aircraft_state.on_ground == 1\"\n    do: stop\n");
  EXPECT_EQ(line_of(both), 4) << both;
  EXPECT_TRUE(contains(both, "not both")) << both;
  const auto for_without_when = error_of("name: x\nevents:\n  - at_s: 1\n    for_s: 2\n    do: stop\n");
  EXPECT_EQ(line_of(for_without_when), 4) << for_without_when;
}

TEST(ScenarioErrors, BadTimesRefused) {
  for (const std::string bad : {"-1", ".nan", ".inf", "-.inf", "1e999", "soon"}) {
    const auto e = error_of("name: x\nevents:\n  - do: stop\n    at_s: " + bad + "\n");
    EXPECT_EQ(line_of(e), 4) << bad << ": " << e;
    EXPECT_TRUE(contains(e, "events[0].at_s")) << e;
  }
  EXPECT_EQ(line_of(error_of("name: x\nevents:\n  - every_s: 0\n    do: stop\n")), 3);
  const auto for_nan = error_of(
      "name: x\nevents:\n  - when: \"fedsim/aircraft_state.on_ground == 1\"\n    for_s: .nan\n    do: stop\n");
  EXPECT_EQ(line_of(for_nan), 4) << for_nan;
  EXPECT_EQ(error_of("name: x\nevents:\n  - do: stop\n    at_s: 0\n"), "(accepted)");  // control
}

TEST(ScenarioErrors, BadConditionsRefusedWithTheirLine) {
  const std::string head = "name: x\nevents:\n  - do: stop\n    when: ";
  const std::pair<std::string, std::string> cases[] = {
      {"\"fedsim/aircraft_state.height_agl_m =< 5\"", "expected an operator"},
      {"\"fedsim/aircraft_state.height_agl_m < 5 furlongs\"", "unknown unit 'furlongs'"},
      {"\"height_agl_m < 5 ft\"", "has no topic"},
      {"\"fedsim/aircraft_state. < 5\"", "field ''"},
      {"\"fedsim/aircraft_state.height_agl_m < nan\"", "not a finite number"},
      {"\"fedsim/aircraft_state.height_agl_m < inf ft\"", "not a finite number"},
      {"\"fedsim/aircraft_state.height_agl_m < 5 ft extra\"", "unexpected 'extra'"},
      {"{all: []}", "non-empty list"},
      {"{some: [\"fedsim/aircraft_state.on_ground == 1\"]}", "unknown field"},
  };
  for (const auto& [when, problem] : cases) {
    const auto e = error_of(head + when + "\n");
    EXPECT_EQ(line_of(e), 4) << when << ": " << e;
    EXPECT_TRUE(contains(e, problem)) << when << ": " << e;
  }
  // A bad part of a list points at the part's own line.
  const auto nested = error_of(head + "\n      any:\n        - \"fedsim/aircraft_state.on_ground == 1\"\n"
                                      "        - \"fedsim/aircraft_state.on_ground ~ 1\"\n");
  EXPECT_EQ(line_of(nested), 7) << nested;
  // Controls: every unit and operator is accepted.
  for (const std::string unit : {"ft", "kt", "deg", "nm", "fpm", "m", "mps", "s", ""}) {
    for (const std::string op : {"<", "<=", ">", ">=", "==", "!="}) {
      EXPECT_EQ(error_of(head + "\"fedsim/aircraft_state.velocity_ned_mps[2] " + op + " -5.5 " + unit + "\"\n"),
                "(accepted)") << op << unit;
    }
  }
}

TEST(ScenarioErrors, UnknownCommandAndBadActionRefused) {
  const auto unknown = error_of("name: x\nevents:\n  - at_s: 1\n    do: {command: explode}\n");
  EXPECT_EQ(line_of(unknown), 4) << unknown;
  EXPECT_TRUE(contains(unknown, "unknown command 'explode'")) << unknown;
  EXPECT_EQ(line_of(error_of("name: x\nevents:\n  - at_s: 1\n    do: halt\n")), 4);
  EXPECT_EQ(line_of(error_of("name: x\nevents:\n  - at_s: 1\n    do: {log: \"\"}\n")), 4);
  EXPECT_EQ(line_of(error_of("name: x\nevents:\n  - at_s: 1\n    do: {log: a, command: run}\n")), 4);
}

TEST(ScenarioErrors, CommandRefusedByTheInstructorLibraryKeepsTheScenarioLine) {
  const auto typo = error_of("name: x\nevents:\n  - at_s: 1\n    do: {command: fail, system: enigne1}\n");
  EXPECT_EQ(line_of(typo), 4) << typo;
  EXPECT_TRUE(contains(typo, "events[0].do: failure: unknown system 'enigne1'")) << typo;
  // Block style: the line of the field the instructor library names.
  const auto lat = error_of(R"(name: x
events:
  - at_s: 1
    do:
      command: reposition
      lat_deg: 95
      lon_deg: 0
      alt_ft: 3000
      heading_deg: 90
)");
  EXPECT_EQ(line_of(lat), 6) << lat;
  EXPECT_TRUE(contains(lat, "lat_deg: 95")) << lat;
  const auto nan = error_of("name: x\nevents:\n  - at_s: 1\n    do: {command: weather, wind_kt: .nan}\n");
  EXPECT_EQ(line_of(nan), 4) << nan;
  EXPECT_TRUE(contains(nan, "not a finite number")) << nan;
  // Typed as YAML reads it: a quoted number is text, which the instructor library refuses.
  EXPECT_TRUE(contains(error_of("name: x\nevents:\n  - at_s: 1\n    do: {command: weather, wind_kt: \"10\"}\n"),
                       "is not a number"));
  // Controls: the same commands, correct, are accepted.
  EXPECT_EQ(error_of("name: x\nevents:\n  - at_s: 1\n    do: {command: fail, system: engine1}\n"), "(accepted)");
  EXPECT_EQ(error_of("name: x\nevents:\n  - at_s: 1\n    do: {command: weather, wind_kt: 10, turbulence: light}\n"),
            "(accepted)");
  EXPECT_EQ(error_of("name: x\nevents:\n  - at_s: 1\n    do: {command: time_of_day, utc: \"2026-12-22T01:30:00\", "
                     "lights: false}\n"),
            "(accepted)");
}

TEST(ScenarioErrors, FileAndStructureErrors) {
  EXPECT_TRUE(contains(error_of(""), "s.yaml:1:"));
  EXPECT_EQ(line_of(error_of("name: x\nevents: []\n")), 2);
  EXPECT_EQ(line_of(error_of("events:\n  - at_s: 1\n    do: stop\n")), 1);  // no name
  EXPECT_EQ(line_of(error_of("name: x\nevents:\n  - at_s:\n    do: stop\n")), 3);  // no value
  EXPECT_EQ(line_of(error_of("name: x\nevents:\n  - at_s: [1\n")), 4);  // YAML syntax
  try {
    Scenario::load_file("/nonexistent/scenario.yaml");
    FAIL() << "a missing file was accepted";
  } catch (const util::ConfigError& e) {
    EXPECT_TRUE(contains(e.what(), "/nonexistent/scenario.yaml: cannot open file"));
  }
}

// ---- The example scenarios in data/scenarios ----

TEST(ScenarioFiles, EveryExampleLoads) {
  const std::filesystem::path dir = fedsim::util::source_dir() + "/data/scenarios";
  int loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const auto s = Scenario::load_file(entry.path().string());
    EXPECT_FALSE(s.name().empty());
    EXPECT_GT(s.event_count(), 0u);
    ++loaded;
  }
  EXPECT_GE(loaded, 2);  // the directory was found and holds the examples
}

TEST(ScenarioFiles, EngineFailureApproachRunsAsDescribed) {
  auto s = Scenario::load_file(fedsim::util::source_dir() + "/data/scenarios/engine_failure_approach.yaml");
  for (const auto& field : s.fields()) EXPECT_EQ(field.rfind(kState + ".", 0), 0u) << field;
  FakeFields f;
  f.values[kState + ".height_agl_m"] = 900.0;
  f.values[kState + ".climb_rate_mps"] = -3.5;
  f.values[kState + ".on_ground"] = 0.0;
  std::vector<std::string> log;
  double t = 0.0;
  auto frame = [&] {
    for (const auto& a : s.step(t, f.lookup())) log.push_back(a.text);
    t += kFrame;
  };
  while (t < 30.0) frame();  // the approach above 1000 ft: no failure
  EXPECT_EQ(std::count(log.begin(), log.end(), "fail engine1"), 0);
  f.values[kState + ".height_agl_m"] = 1000 * units::kFtToM - 1.0;
  frame();
  EXPECT_EQ(std::count(log.begin(), log.end(), "fail engine1"), 1);
  f.values[kState + ".height_agl_m"] = 0.0;
  f.values[kState + ".on_ground"] = 1.0;
  const double touchdown = t;
  while (!s.finished() && t < touchdown + 60.0) frame();
  EXPECT_TRUE(s.finished());
  EXPECT_NEAR(t - kFrame - touchdown, 10.0, kFrame);
}

}  // namespace
}  // namespace fedsim::scenario
