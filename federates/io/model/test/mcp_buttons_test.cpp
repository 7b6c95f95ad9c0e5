// The MCP's buttons as a profile drives them: a rise to >= 0.5 is one press, holding is not
// another, each button counts on its own; the panel's selections keep their ranges.
#include "io/model/control_inputs.hpp"
#include "io/model/input_profile.hpp"

#include <gtest/gtest.h>

namespace fedsim::io {
namespace {

int index_of(Channel button) { return static_cast<int>(button) - static_cast<int>(Channel::kMcpCmd); }

TEST(McpButtonCounter, ARiseIsOnePressAndHoldingIsNotAnother) {
  McpButtonCounter counter;
  ControlInputs c = default_controls();
  counter.update(c);
  EXPECT_EQ(counter.presses()[index_of(Channel::kMcpApp)], 0u);
  c[Channel::kMcpApp] = 1.0;
  for (int i = 0; i < 5; ++i) counter.update(c);  // held for five frames
  EXPECT_EQ(counter.presses()[index_of(Channel::kMcpApp)], 1u);
  EXPECT_TRUE(counter.held(Channel::kMcpApp));
  c[Channel::kMcpApp] = 0.4;  // below the threshold: released
  counter.update(c);
  EXPECT_FALSE(counter.held(Channel::kMcpApp));
  c[Channel::kMcpApp] = 0.5;
  counter.update(c);
  EXPECT_EQ(counter.presses()[index_of(Channel::kMcpApp)], 2u);
  // The others never moved.
  for (int i = 0; i < kMcpButtonCount; ++i) {
    if (i != index_of(Channel::kMcpApp)) {
      EXPECT_EQ(counter.presses()[i], 0u) << i;
    }
  }
  // A not-a-button channel does not count.
  EXPECT_FALSE(counter.held(Channel::kElevator));
}

TEST(McpButtonCounter, AProfilesStepsPressTheButtonsInTheirOrder) {
  InputProfile p = InputProfile::parse(
      "time_s,mcp_cmd,toga\n0,0,0\n1,0,0\n1,1,0\n2,1,0\n2,0,1\n3,0,1\n3,0,0\n4,1,0\n", "steps.csv");
  McpButtonCounter counter;
  ControlInputs c = default_controls();
  for (double t = 0.0; t <= 4.0 + 1e-9; t += 0.02) {
    p.sample(t, c);
    counter.update(c);
  }
  EXPECT_EQ(counter.presses()[index_of(Channel::kMcpCmd)], 2u);  // the step at 1 s, the ramp 3 -> 4 s
  EXPECT_EQ(counter.presses()[index_of(Channel::kToga)], 1u);
  EXPECT_EQ(index_of(Channel::kToga), kMcpButtonCount - 1);  // the last of controls.idl's MCP_*
}

TEST(McpSelections, TheProfileColumnsKeepTheirRanges) {
  EXPECT_THROW(InputProfile::parse("time_s,mcp_speed_kt\n0,500\n", "fast.csv"), ProfileError);
  EXPECT_THROW(InputProfile::parse("time_s,mcp_bank_limit_deg\n0,45\n", "steep.csv"), ProfileError);
  EXPECT_NO_THROW(InputProfile::parse("time_s,mcp_speed_kt,mcp_bank_limit_deg\n0,145,15\n", "ok.csv"));
  const ControlInputs c = default_controls();
  EXPECT_EQ(c[Channel::kMcpSpeedKt], 150.0);
  EXPECT_EQ(c[Channel::kMcpBankLimitDeg], 25.0);
  EXPECT_EQ(c[Channel::kFlightDirector], 1.0);
}

}  // namespace
}  // namespace fedsim::io
