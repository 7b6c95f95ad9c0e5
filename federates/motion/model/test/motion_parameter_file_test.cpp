// The motion parameter file: the shipped one is the built-in tuning, a key sets its field (in
// the edge's units where they differ), a typo, an out-of-range or non-finite value and a period
// the filters cannot run at are refused naming the file and field.
#include "motion/model/motion_parameter_file.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

namespace fedsim::motion {
namespace {

std::string error_of(const std::string& text, double dt_s = 0.02) {
  try {
    parse_motion_parameters(text, "motion.yaml", dt_s);
  } catch (const util::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(MotionParameterFile, TheShippedFileIsTheBuiltInTuning) {
  const MotionPlatformParameters file =
      load_motion_parameters(std::string(FEDSIM_DATA_DIR) + "/motion/washout.yaml", 0.02);
  const MotionPlatformParameters built_in;
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(file.washout.translational[i].gain, built_in.washout.translational[i].gain) << i;
    EXPECT_EQ(file.washout.translational[i].natural_frequency_radps,
              built_in.washout.translational[i].natural_frequency_radps) << i;
    EXPECT_EQ(file.washout.translational[i].break_frequency_radps,
              built_in.washout.translational[i].break_frequency_radps) << i;
    EXPECT_EQ(file.washout.rotational[i].natural_frequency_radps,
              built_in.washout.rotational[i].natural_frequency_radps) << i;
  }
  EXPECT_NEAR(file.washout.tilt.rate_limit_radps, built_in.washout.tilt.rate_limit_radps, 1e-12);
  EXPECT_NEAR(file.washout.tilt.angle_limit_rad, built_in.washout.tilt.angle_limit_rad, 1e-12);
  EXPECT_EQ(file.actuator_rate_hz, built_in.actuator_rate_hz);
}

TEST(MotionParameterFile, AKeySetsItsFieldInTheEdgesUnits) {
  const MotionPlatformParameters p = parse_motion_parameters(
      "washout:\n  translational:\n    heave: {gain: 0.3}\n  tilt: {rate_limit_deg_s: 2.0}\n"
      "platform: {actuator_rate_hz: 2000}\n",
      "motion.yaml", 0.02);
  EXPECT_EQ(p.washout.translational[2].gain, 0.3);
  EXPECT_EQ(p.washout.translational[2].natural_frequency_radps, 4.0);  // the rest stays
  EXPECT_NEAR(p.washout.tilt.rate_limit_radps, 2.0 * units::kDegToRad, 1e-12);
  EXPECT_EQ(p.actuator_rate_hz, 2000.0);
}

TEST(MotionParameterFile, BadValuesAreRefusedByFileAndField) {
  EXPECT_NE(error_of("washout:\n  tilt: {rate_limit_dps: 2}\n").find("rate_limit_dps"), std::string::npos);
  EXPECT_NE(error_of("washout:\n  translational:\n    surge: {gain: 1.5}\n").find("gain"), std::string::npos);
  EXPECT_NE(error_of("washout:\n  translational:\n    surge: {gain: .nan}\n").find("motion.yaml"), std::string::npos);
  EXPECT_NE(error_of("platform: {actuator_rate_hz: 100}\n").find("actuator_rate_hz"), std::string::npos);
  // 80 rad/s is within its range (100) but above Nyquist at 20 Hz (62.8 rad/s): the period check names it.
  const std::string nyquist =
      error_of("washout:\n  rotational:\n    roll: {natural_frequency_radps: 80}\n", 0.05);
  EXPECT_NE(nyquist.find("natural_frequency_radps"), std::string::npos) << nyquist;
  EXPECT_EQ(error_of("washout:\n  rotational:\n    roll: {natural_frequency_radps: 80}\n", 0.02), "");
}

}  // namespace
}  // namespace fedsim::motion
