// The one registry of deployment members (fedsim/members.hpp): the timing member `fedsim run`
// adds, every member as its host sees it, a recorder's topics, and a member's component built
// from its arguments by its own program (a bad argument named with file and member).
#include "fedsim/members.hpp"

#include "common/util/build_paths.hpp"
#include "common/util/config_node.hpp"
#include "timing/timing_component.hpp"

#include <gtest/gtest.h>

namespace fedsim::launcher {
namespace {

const char* kDemo = R"(
name: demo
mode: lockstep
rate_hz: 100
timing: {args: [--frames, "500", --scale, "1"]}
federates:
  - {name: io, binary: fedsim-io, args: [--profile, "${DATA_DIR}/profiles/elevator_doublets.csv"]}
  - {name: probe, binary: fedsim, args: [topic, list], lockstep: false, federate_options: false}
  - {name: recorder, binary: fedsim, args: [record, --topics, "fedsim/a,fedsim/b", --out, "${OUT_DIR}"]}
)";

std::map<std::string, std::string> vars() { return {{"DATA_DIR", util::data_dir()}, {"OUT_DIR", "/tmp/out"}}; }

TEST(Members, TheTimingMemberTakesModeRateTheLockstepMembersAndTheDeploymentsArgs) {
  const Deployment d = parse_deployment(kDemo, "demo.yaml");
  const FederateSpec timing = timing_spec(d);
  EXPECT_EQ(timing.name, "timing");
  EXPECT_EQ(timing.binary, "fedsim-timing");
  EXPECT_EQ(timing.args, (std::vector<std::string>{"--mode", "lockstep", "--rate", "100.000000", "--shutdown-on-exit",
                                                   "--expect", "io,recorder", "--frames", "500", "--scale", "1"}));
}

TEST(Members, EveryMemberWithItsArgumentsSubstitutedTheTimingMemberLast) {
  const Deployment d = parse_deployment(kDemo, "demo.yaml");
  const Members members(d, vars());
  ASSERT_EQ(members.all().size(), 4u);
  EXPECT_EQ(members.all()[0].args[1], util::data_dir() + "/profiles/elevator_doublets.csv");
  EXPECT_TRUE(members.all()[3].is_timing);
  EXPECT_EQ(members.all()[3].spec->name, "timing");
  Deployment without = d;
  without.has_timing = false;
  EXPECT_EQ(Members(without, vars()).all().size(), 3u);
}

TEST(Members, ARecordersTopicsAndFolder) {
  const Deployment d = parse_deployment(kDemo, "demo.yaml");
  const Members members(d, vars());
  EXPECT_FALSE(recorder_of(members.all()[0])) << "not fedsim";
  EXPECT_FALSE(recorder_of(members.all()[1])) << "fedsim topic, not fedsim record";
  const auto recorder = recorder_of(members.all()[2]);
  ASSERT_TRUE(recorder);
  EXPECT_EQ(recorder->topics, (std::vector<std::string>{"fedsim/a", "fedsim/b"}));
  EXPECT_EQ(recorder->out_dir, "/tmp/out");
}

TEST(Members, AComponentIsBuiltByItsProgramFromTheMembersArguments) {
  const Deployment d = parse_deployment(kDemo, "demo.yaml");
  const Members members(d, vars());
  EXPECT_EQ(build_component(d, members.all()[1]), nullptr) << "fedsim is not a component program";
  const auto timing = build_component(d, members.all()[3]);
  ASSERT_NE(timing, nullptr);
  const auto& options = dynamic_cast<const timing::TimingComponent&>(*timing).options();
  EXPECT_EQ(options.common.max_frames, 500u);
  EXPECT_DOUBLE_EQ(options.scale, 1.0);
  EXPECT_EQ(options.expect, (std::vector<std::string>{"io", "recorder"}));
  EXPECT_EQ(timing->name(), "timing");
}

TEST(Members, ABadArgumentIsNamedWithFileAndMember) {
  const Deployment d = parse_deployment(R"(
name: bad
timing: {args: [--frames, "ten"]}
federates:
  - {name: io, binary: fedsim-io, args: [--profile, "${DATA_DIR}/profiles/elevator_doublets.csv"]}
)", "bad.yaml");
  const Members members(d, vars());
  try {
    build_component(d, members.all()[1]);
    FAIL() << "accepted --frames ten";
  } catch (const util::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml: federate 'timing': "), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fedsim::launcher
