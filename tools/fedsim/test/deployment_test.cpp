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
  EXPECT_EQ(d.after[0][0], "gnuplot");
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
