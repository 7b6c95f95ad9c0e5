#include "fedsim/deployment.hpp"

#include "common/util/config_node.hpp"

#include <gtest/gtest.h>

namespace fedsim::launcher {
namespace {

TEST(Deployment, ReadsFederatesTimingAndAfterCommands) {
  const auto d = parse_deployment(R"(
name: demo
mode: realtime
rate_hz: 100
domain: 7
timing: {args: [--frames, "500"]}
federates:
  - {name: io, binary: fedsim-io, args: [--profile, "${DATA_DIR}/p.csv"]}
  - {name: probe, binary: fedsim, args: [topic, list], lockstep: false, federate_options: false}
after:
  - [gnuplot, "${OUT_DIR}/plot.gp"]
)", "demo.yaml");
  EXPECT_EQ(d.name, "demo");
  EXPECT_EQ(d.mode, "realtime");
  EXPECT_DOUBLE_EQ(d.rate_hz, 100.0);
  EXPECT_EQ(d.domain, 7);
  ASSERT_EQ(d.federates.size(), 2u);
  EXPECT_TRUE(d.federates[0].lockstep);
  EXPECT_FALSE(d.federates[1].lockstep);
  EXPECT_EQ(d.timing_args, (std::vector<std::string>{"--frames", "500"}));
  ASSERT_EQ(d.after.size(), 1u);
  EXPECT_EQ(d.after[0].argv[0], "gnuplot");
  EXPECT_TRUE(d.after[0].needs.empty());
  EXPECT_FALSE(d.after[0].whole_run);
}

// An after-step as a map: its command, the files it reads that a good run may not make, and
// whether it judges the whole run (fedsim run skips it, by name, when those are not met).
TEST(Deployment, ReadsAfterStepsWithTheirNeeds) {
  const auto d = parse_deployment(R"(
name: demo
federates: [{name: a, binary: b}]
after:
  - run: [fedsim, image, montage, "${OUT_DIR}/m.png", "${OUT_DIR}/a.png", "${OUT_DIR}/b.png"]
    needs: ["${OUT_DIR}/a.png", "${OUT_DIR}/b.png"]
  - {run: [fedsim, qtg, --recording, "${OUT_DIR}"], whole_run: true}
)", "demo.yaml");
  ASSERT_EQ(d.after.size(), 2u);
  EXPECT_EQ(d.after[0].argv.size(), 6u);
  EXPECT_EQ(d.after[0].needs, (std::vector<std::string>{"${OUT_DIR}/a.png", "${OUT_DIR}/b.png"}));
  EXPECT_FALSE(d.after[0].whole_run);
  EXPECT_EQ(d.after[1].argv[1], "qtg");
  EXPECT_TRUE(d.after[1].needs.empty());
  EXPECT_TRUE(d.after[1].whole_run);
}

void expect_error(const std::string& text, const std::string& needle) {
  try {
    parse_deployment(text, "bad.yaml");
    FAIL() << "accepted: " << text;
  } catch (const util::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(Deployment, RejectsBadFilesWithFileLineAndField) {
  expect_error("name: x\nfederates: []\n", "bad.yaml:2: federates: lists no federate");
  expect_error("name: x\nmode: fast\nfederates: [{name: a, binary: b}]\n",
               "bad.yaml:2: mode: 'fast' is not one of");
  expect_error("name: x\nfederates:\n  - {name: a, binary: b}\n  - {name: a, binary: c}\n",
               "bad.yaml:4: federates[1].name: 'a' is used twice");
  expect_error("name: x\nfederates:\n  - {name: timing, binary: b}\n", "clashes with the timing");
  expect_error("name: x\nfederates:\n  - {name: a, binray: b}\n", "bad.yaml:3: federates[0].binray: unknown field");
  expect_error("name: x\ndomain: 300\nfederates: [{name: a, binary: b}]\n", "bad.yaml:2: domain: value 300");
  expect_error("name: x\nfederates: [{name: a, binary: b}\n", "bad.yaml:");
  expect_error("name: x\nfederates: [{name: a, binary: b}]\nafter:\n  - []\n",
               "bad.yaml:4: after[0]: an 'after' command is empty");
  expect_error("name: x\nfederates: [{name: a, binary: b}]\nafter:\n  - {needs: [f]}\n",
               "after[0].run: an 'after' command is empty");
  expect_error("name: x\nfederates: [{name: a, binary: b}]\nafter:\n  - {run: [c], nedds: [f]}\n",
               "bad.yaml:4: after[0].nedds: unknown field");
  expect_error("name: x\nfederates: [{name: a, binary: b}]\nafter:\n  - {run: [c], whole_run: maybe}\n",
               "after[0].whole_run");
  // A needed file the step does not name is a typo that would skip the step in every run.
  expect_error("name: x\nfederates: [{name: a, binary: b}]\nafter:\n"
               "  - {run: [c, \"${OUT_DIR}/a.png\"], needs: [\"${OUT_DIR}/aa.png\"]}\n",
               "bad.yaml:4: after[0].needs: '${OUT_DIR}/aa.png' is not named in the step's arguments");
}

// Names become paths (out/<deployment>/, logs/<federate>.log) and the timing federate's
// comma-separated --expect list: "a,b" was two expected federates, "../x" left the folder.
TEST(Deployment, RefusesNamesThatAreNotPlainWords) {
  const std::string rule = "must be 1-32 characters of A-Z a-z 0-9 _ -";
  expect_error("name: x\nfederates:\n  - {name: \"a,b\", binary: b}\n",
               "bad.yaml:3: federates[0].name: 'a,b' " + rule);
  expect_error("name: x\nfederates:\n  - {name: ../x, binary: b}\n",
               "bad.yaml:3: federates[0].name: '../x' " + rule);
  expect_error("name: x\nfederates:\n  - {name: a b, binary: b}\n", "federates[0].name: 'a b'");
  expect_error("name: x\nfederates:\n  - {name: \"\", binary: b}\n", "federates[0].name: ''");
  expect_error("name: x\nfederates:\n  - {name: " + std::string(33, 'a') + ", binary: b}\n",
               "federates[0].name: '" + std::string(33, 'a') + "' " + rule);
  expect_error("name: ../../etc\nfederates: [{name: a, binary: b}]\n",
               "bad.yaml:1: name: '../../etc' " + rule);
  // The negative control: every allowed character, 32 of them.
  const std::string longest = "Ab-_09" + std::string(26, 'z');
  const auto d = parse_deployment("name: Run-1_x\nfederates: [{name: " + longest + ", binary: b}]\n",
                                  "ok.yaml");
  EXPECT_EQ(d.name, "Run-1_x");
  EXPECT_EQ(d.federates.at(0).name, longest);
}

// yaml-cpp takes a list or a map as a key (reading it as text threw its own conversion error,
// without file or field) and keeps duplicate keys (a lookup found the first: the later value was
// silently ignored). Both are refused by util::ConfigNode for every config file.
TEST(Deployment, RefusesNonScalarAndDuplicateKeysWithFileLineAndField) {
  expect_error("name: x\n[a, b]: 1\nfederates: [{name: a, binary: b}]\n",
               "bad.yaml:2: (top level): a key must be plain text, not a list");
  expect_error("name: x\nfederates:\n  - name: a\n    binary: b\n    {k: v}: 1\n",
               "bad.yaml:5: federates[0]: a key must be plain text, not a map");
  expect_error("name: x\nmode: realtime\nfederates: [{name: a, binary: b}]\nmode: lockstep\n",
               "bad.yaml:4: mode: given twice (first on line 2)");
  expect_error("name: x\nfederates:\n  - name: a\n    binary: b\n    binary: c\n",
               "bad.yaml:5: federates[0].binary: given twice (first on line 4)");
  expect_error("name: x\ntiming: {args: [--frames, \"5\"], args: []}\nfederates: [{name: a, binary: b}]\n",
               "bad.yaml:2: timing.args: given twice (first on line 2)");
}

TEST(Deployment, SubstitutesKnownVariablesAndRejectsUnknownOnes) {
  const std::map<std::string, std::string> vars{{"OUT_DIR", "/tmp/o"}, {"DATA_DIR", "/d"}};
  EXPECT_EQ(substitute("${OUT_DIR}/x.csv", vars), "/tmp/o/x.csv");
  EXPECT_EQ(substitute("a${DATA_DIR}b${OUT_DIR}", vars), "a/db/tmp/o");
  EXPECT_EQ(substitute("plain", vars), "plain");
  EXPECT_THROW(substitute("${NOPE}", vars), util::ConfigError);
  EXPECT_THROW(substitute("${OUT_DIR", vars), util::ConfigError);
}

}  // namespace
}  // namespace fedsim::launcher

namespace fedsim::launcher {
namespace {

// restart: no is the default; on-failure takes an optional bound; anything else names the
// file, line and field as the other fields do.
TEST(Deployment, ReadsAndChecksTheRestartPolicy) {
  const auto d = parse_deployment(R"(
name: demo
federates:
  - {name: io, binary: fedsim-io}
  - {name: flight, binary: fedsim-flight, restart: on-failure}
  - {name: nav, binary: fedsim-nav, restart: on-failure, max_restarts: 7}
  - {name: motion, binary: fedsim-motion, restart: no}
)", "demo.yaml");
  ASSERT_EQ(d.federates.size(), 4u);
  EXPECT_FALSE(d.federates[0].restart_on_failure);
  EXPECT_TRUE(d.federates[1].restart_on_failure);
  EXPECT_EQ(d.federates[1].max_restarts, 3);
  EXPECT_EQ(d.federates[2].max_restarts, 7);
  EXPECT_FALSE(d.federates[3].restart_on_failure);
  expect_error("name: x\nfederates:\n  - {name: a, binary: b, restart: always}\n",
               "bad.yaml:3: federates[0].restart: 'always' is not one of");
  expect_error("name: x\nfederates:\n  - {name: a, binary: b, max_restarts: 2}\n",
               "bad.yaml:3: federates[0].max_restarts: needs restart: on-failure");
  expect_error("name: x\nfederates:\n  - {name: a, binary: b, restart: on-failure, max_restarts: 0}\n",
               "bad.yaml:3: federates[0].max_restarts: value 0");
  expect_error("name: x\nfederates:\n  - {name: a, binary: b, restart: on-failure, max_restarts: nan}\n",
               "bad.yaml:3: federates[0].max_restarts");
}

}  // namespace
}  // namespace fedsim::launcher
