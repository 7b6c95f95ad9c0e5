#include "io/model/input_profile.hpp"

#include <gtest/gtest.h>

namespace fedsim::io {
namespace {

const char* kDoublet =
    "# an elevator doublet with a throttle ramp\n"
    "time_s, elevator, throttle\n"
    "0.0, 0.0, 0.5\n"
    "2.0, 0.0, 0.5\n"
    "2.0, 0.1, 0.5\n"
    "3.0, 0.1, 0.7\n"
    "3.0, -0.1, 0.7\n"
    "4.0, -0.1, 0.7\n"
    "4.0, 0.0, 0.7\n";

TEST(InputProfile, ProducesStepsRampsAndDoublets) {
  auto p = InputProfile::parse(kDoublet, "doublet.csv");
  EXPECT_DOUBLE_EQ(p.value(0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(p.value(0, 1.999), 0.0);
  EXPECT_DOUBLE_EQ(p.value(0, 2.0), 0.1);    // step at t = 2
  EXPECT_DOUBLE_EQ(p.value(0, 2.5), 0.1);
  EXPECT_DOUBLE_EQ(p.value(0, 3.5), -0.1);   // second half of the doublet
  EXPECT_DOUBLE_EQ(p.value(0, 10.0), 0.0);   // holds the last value
  EXPECT_NEAR(p.value(1, 2.5), 0.6, 1e-12);  // ramp 0.5 -> 0.7 between 2 and 3 s
}

TEST(InputProfile, GroupNamesDriveEveryEngine) {
  auto p = InputProfile::parse(kDoublet, "doublet.csv");
  ControlInputs c = default_controls();
  p.sample(2.5, c);
  for (int e = 0; e < kMaxEngines; ++e) EXPECT_NEAR(c.throttle(e), 0.6, 1e-12);
  EXPECT_DOUBLE_EQ(c[Channel::kElevator], 0.1);
  EXPECT_DOUBLE_EQ(c[Channel::kMixture1], 1.0);  // not driven: untouched
  EXPECT_TRUE(p.drives(Channel::kThrottle3));
  EXPECT_FALSE(p.drives(Channel::kRudder));
}

TEST(InputProfile, SamplingBackwardsInTimeStillWorks) {
  auto p = InputProfile::parse(kDoublet, "doublet.csv");
  EXPECT_DOUBLE_EQ(p.value(0, 3.5), -0.1);
  EXPECT_DOUBLE_EQ(p.value(0, 0.5), 0.0);  // after a reset sim time starts again
  EXPECT_DOUBLE_EQ(p.value(0, 2.2), 0.1);
}

TEST(InputProfile, RelativeModeAddsToTheBaseAndClamps) {
  auto p = InputProfile::parse("time_s,elevator\n0,0.1\n", "rel.csv");
  ControlInputs base = default_controls();
  base[Channel::kElevator] = -0.05;
  base[Channel::kThrottle1] = 0.6;
  ControlInputs out;
  p.sample_relative(1.0, base, out);
  EXPECT_NEAR(out[Channel::kElevator], 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(out[Channel::kThrottle1], 0.6);
  base[Channel::kElevator] = 0.95;
  p.sample_relative(1.0, base, out);
  EXPECT_DOUBLE_EQ(out[Channel::kElevator], 1.0);
}

void expect_error(const std::string& text, const std::string& needle) {
  try {
    InputProfile::parse(text, "bad.csv");
    FAIL() << "no error for: " << text;
  } catch (const ProfileError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos)
        << "message was: " << e.what();
  }
}

TEST(InputProfile, MalformedProfilesNameFileAndLine) {
  expect_error("time_s,elevatr\n0,0\n", "bad.csv:1: unknown channel 'elevatr'");
  expect_error("elevator,time_s\n0,0\n", "bad.csv:1: the header must start with 'time_s'");
  expect_error("time_s,elevator\n0,0\n1,abc\n", "bad.csv:3: column 'elevator': not a number: 'abc'");
  expect_error("time_s,elevator\n# c\n\n0,0\n2,0.1\n1,0\n", "bad.csv:6: time_s goes backwards");
  expect_error("time_s,elevator\n0,0,1\n", "bad.csv:2: 3 fields, the header has 2");
  expect_error("time_s,throttle\n0,1.5\n", "bad.csv:2: column 'throttle': 1.5 is outside");
  expect_error("time_s,elevator\n1,0\n1,0.1\n1,0.2\n", "bad.csv:4: more than two rows");
  expect_error("time_s,throttle,throttle2\n0,0,0\n", "bad.csv:1: channel 'throttle2' is given twice");
  expect_error("time_s,elevator\n", "bad.csv: the profile has a header but no rows");
  expect_error("time_s,elevator\n-1,0\n", "bad.csv:2: time_s must not be negative");
  expect_error("time_s,elevator\nnan,0\n", "bad.csv:2: column 'time_s': not a number: 'nan'");
}

TEST(InputProfile, MissingFileIsAClearError) {
  EXPECT_THROW(InputProfile::load_file("/nonexistent/profile.csv"), ProfileError);
}

}  // namespace
}  // namespace fedsim::io
