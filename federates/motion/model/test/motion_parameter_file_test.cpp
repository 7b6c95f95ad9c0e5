// The motion parameter file: the shipped one is the built-in tuning and platform design, a key
// sets its field (in the edge's units where they differ), a changed geometry changes the jack
// lengths, a typo, an out-of-range or non-finite value, a neutral pose out of the jacks' reach
// and a period the filters cannot run at are refused naming the file, line and field.
#include "motion/model/motion_parameter_file.hpp"
#include "common/util/build_paths.hpp"

#include "common/units/units.hpp"
#include "motion/model/stewart_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

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
      load_motion_parameters(fedsim::util::data_dir() + "/motion/washout.yaml", 0.02);
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

// A pose off neutral. With the neutral at mid-stroke every design has the same jack lengths
// there (the neutral height adapts to the radii), so only an excursion tells radii apart.
PlatformPose excursion() {
  PlatformPose pose;
  pose.position_i_m = {0.3, -0.2, 0.1};
  pose.attitude =
      EulerAngles{5.0 * units::kDegToRad, -4.0 * units::kDegToRad, 8.0 * units::kDegToRad};
  return pose;
}

void expect_same_geometry(const StewartGeometry& a, const StewartGeometry& b) {
  for (int k = 0; k < kJackCount; ++k) {
    EXPECT_TRUE(a.base_joints_i_m[k] == b.base_joints_i_m[k]) << "base joint " << k;
    EXPECT_TRUE(a.top_joints_p_m[k] == b.top_joints_p_m[k]) << "upper joint " << k;
  }
  EXPECT_EQ(a.min_length_m, b.min_length_m);
  EXPECT_EQ(a.max_length_m, b.max_length_m);
  // Bit for bit: the file's figures are the built-in ones, not merely close.
  EXPECT_EQ(StewartKinematics(a).neutral_lengths_m(), StewartKinematics(b).neutral_lengths_m());
  EXPECT_EQ(StewartKinematics(a).inverse(excursion()), StewartKinematics(b).inverse(excursion()));
}

TEST(MotionParameterFile, TheShippedGeometryAndJacksAreTheBuiltInDesign) {
  const MotionPlatformParameters file =
      load_motion_parameters(fedsim::util::data_dir() + "/motion/washout.yaml", 0.02);
  const MotionPlatformParameters built_in;
  expect_same_geometry(file.geometry, built_in.geometry);
  EXPECT_EQ(file.actuator.natural_frequency_radps, built_in.actuator.natural_frequency_radps);
  EXPECT_EQ(file.actuator.damping_ratio, built_in.actuator.damping_ratio);
  EXPECT_EQ(file.actuator.velocity_limit_mps, built_in.actuator.velocity_limit_mps);
  EXPECT_EQ(file.actuator.acceleration_limit_mps2, built_in.actuator.acceleration_limit_mps2);
  EXPECT_EQ(file.actuator.cushion_deceleration_mps2, built_in.actuator.cushion_deceleration_mps2);
  std::printf("[figure] shipped geometry: jacks %.4f m at neutral (stroke %.3f..%.3f m)\n",
              StewartKinematics(file.geometry).neutral_lengths_m()[0], file.geometry.min_length_m,
              file.geometry.max_length_m);
}

TEST(MotionParameterFile, WithoutAGeometrySectionTheBuiltInDesignStays) {
  const MotionPlatformParameters p =
      parse_motion_parameters("platform: {actuator_rate_hz: 1000}\n", "motion.yaml", 0.02);
  expect_same_geometry(p.geometry, MotionPlatformParameters{}.geometry);
}

TEST(MotionParameterFile, AChangedGeometryChangesTheJackLengths) {
  const StewartKinematics built_in(MotionPlatformParameters{}.geometry);
  // Wider base: neutral stays at mid-stroke (lower), the lengths off neutral change.
  const MotionPlatformParameters wider =
      parse_motion_parameters("geometry: {base_radius_m: 2.2}\n", "motion.yaml", 0.02);
  const StewartKinematics k(wider.geometry);
  for (int j = 0; j < kJackCount; ++j) {
    EXPECT_NEAR(k.neutral_lengths_m()[j], built_in.neutral_lengths_m()[j], 1e-12) << j;
    // Far above rounding (1e-12 m): each jack's length off neutral moved with the base.
    EXPECT_GT(std::abs(k.inverse(excursion())[j] - built_in.inverse(excursion())[j]), 1e-4) << j;
  }
  EXPECT_LT(wider.geometry.base_joints_i_m[0].z(), built_in.geometry().base_joints_i_m[0].z());
  // Shorter jacks: mid-stroke, hence every neutral length, moves with them.
  const MotionPlatformParameters shorter = parse_motion_parameters(
      "geometry: {min_length_m: 2.0, max_length_m: 3.5}\n", "motion.yaml", 0.02);
  const JackArray shorter_m = StewartKinematics(shorter.geometry).neutral_lengths_m();
  for (double length_m : shorter_m) {
    EXPECT_NEAR(length_m, 2.75, 1e-12);
  }
  // A named neutral height places the neutral off mid-stroke.
  const MotionPlatformParameters lower =
      parse_motion_parameters("geometry: {neutral_height_m: 2.5}\n", "motion.yaml", 0.02);
  const double mid_stroke_m = built_in.neutral_lengths_m()[0];
  const double mid_height_m = built_in.geometry().base_joints_i_m[0].z();
  const double span_sq = mid_stroke_m * mid_stroke_m - mid_height_m * mid_height_m;  // unchanged
  const JackArray lower_m = StewartKinematics(lower.geometry).neutral_lengths_m();
  for (double length_m : lower_m) {
    EXPECT_NEAR(length_m, std::sqrt(span_sq + 2.5 * 2.5), 1e-12);
  }
  // Each one flies.
  for (const MotionPlatformParameters* p : {&wider, &shorter, &lower}) {
    EXPECT_NO_THROW(MotionPlatform(*p, 0.02));
  }
}

TEST(MotionParameterFile, JackLimitsAreRead) {
  const MotionPlatformParameters p = parse_motion_parameters(
      "actuator: {velocity_limit_mps: 0.6, acceleration_limit_mps2: 8.0, natural_frequency_radps: 40}\n",
      "motion.yaml", 0.02);
  EXPECT_EQ(p.actuator.velocity_limit_mps, 0.6);
  EXPECT_EQ(p.actuator.acceleration_limit_mps2, 8.0);
  EXPECT_EQ(p.actuator.natural_frequency_radps, 40.0);
  EXPECT_EQ(p.actuator.damping_ratio, JackActuatorParameters{}.damping_ratio);  // the rest stays
}

// Every geometry, jack and related platform key on its own line (the built-in values), so that a
// case can replace one line and expect that line named.
const std::vector<std::string> kValidLines = {
    "geometry:",                        // 1
    "  base_radius_m: 2.0",             // 2
    "  top_radius_m: 1.5",              // 3
    "  base_half_separation_deg: 10",   // 4
    "  top_half_separation_deg: 10",    // 5
    "  min_length_m: 2.21",             // 6
    "  max_length_m: 3.734",            // 7
    "actuator:",                        // 8
    "  natural_frequency_radps: 50",    // 9
    "  damping_ratio: 0.8",             // 10
    "  velocity_limit_mps: 0.8",        // 11
    "  acceleration_limit_mps2: 10",    // 12
    "  cushion_deceleration_mps2: 10",  // 13
    "platform:",                        // 14
    "  soft_limit_margin_m: 0.05",      // 15
    "  engage_speed_mps: 0.15",         // 16
};

// The valid lines with line `line` (1-based) replaced.
std::string with_line(int line, const std::string& replacement) {
  std::ostringstream text;
  for (int n = 1; n <= static_cast<int>(kValidLines.size()); ++n) {
    text << (n == line ? replacement : kValidLines[n - 1]) << "\n";
  }
  return text.str();
}

TEST(MotionParameterFile, EachBadGeometryOrJackValueIsRefusedByNameAndLine) {
  ASSERT_EQ(error_of(with_line(6, kValidLines[5])), "");  // the control: the valid lines load
  struct Case {
    int line;
    std::string replacement;
    std::string where;    // "file:line: field:"
    std::string problem;  // a word of the reason
  };
  const std::vector<Case> cases = {
      {2, "  base_radius_m: 0", "motion.yaml:2: geometry.base_radius_m:", "> 0"},
      {2, "  base_radius: 2.0", "motion.yaml:2: geometry.base_radius:", "unknown field"},
      {3, "  top_radius_m: -1.5", "motion.yaml:3: geometry.top_radius_m:", "outside the allowed range"},
      {4, "  base_half_separation_deg: 30", "motion.yaml:4: geometry.base_half_separation_deg:", "(0, 30)"},
      {5, "  top_half_separation_deg: .nan", "motion.yaml:5: geometry.top_half_separation_deg:", "finite"},
      {6, "  min_length_m: 0", "motion.yaml:6: geometry.min_length_m:", "> 0"},
      {7, "  max_length_m: 2.0", "motion.yaml:7: geometry.max_length_m:", "above min_length_m"},
      {7, "  max_length_m: .inf", "motion.yaml:7: geometry.max_length_m:", "finite"},
      {9, "  natural_frequency_radps: 300", "motion.yaml:9: actuator.natural_frequency_radps:",
       "0.2 x platform.actuator_rate_hz"},
      {10, "  damping_ratio: 0", "motion.yaml:10: actuator.damping_ratio:", "> 0"},
      {11, "  velocity_limit_mps: .inf", "motion.yaml:11: actuator.velocity_limit_mps:", "finite"},
      // A velocity limit below the engage speed: the speed that no longer fits is named.
      {11, "  velocity_limit_mps: 0.1", "motion.yaml:16: platform.engage_speed_mps:",
       "actuator.velocity_limit_mps"},
      {12, "  acceleration_limit_mps2: 0", "motion.yaml:12: actuator.acceleration_limit_mps2:", "> 0"},
      {13, "  cushion_deceleration_mps2: -1", "motion.yaml:13: actuator.cushion_deceleration_mps2:",
       "outside the allowed range"},
      {15, "  soft_limit_margin_m: 0.8", "motion.yaml:15: platform.soft_limit_margin_m:",
       "half the jack stroke"},
  };
  for (const Case& c : cases) {
    const std::string error = error_of(with_line(c.line, c.replacement));
    EXPECT_EQ(error.rfind(c.where, 0), 0u) << c.replacement << " -> " << error;
    EXPECT_NE(error.find(c.problem), std::string::npos) << c.replacement << " -> " << error;
  }
}

TEST(MotionParameterFile, AnUnreachableNeutralIsRefused) {
  // Too low: sqrt(span^2 + 1.5^2) = 1.98 m, shorter than the retracted jack (2.21 m).
  const std::string where = "motion.yaml:8: geometry.neutral_height_m: the neutral pose is unreachable";
  const std::string low = error_of(with_line(8, "  neutral_height_m: 1.5\nactuator:"));
  EXPECT_EQ(low.rfind(where, 0), 0u) << low;
  // Inside the stroke (3.73 m < 3.734 m) but not inside the soft limit 0.05 m from its end.
  const std::string high = error_of(with_line(8, "  neutral_height_m: 3.5\nactuator:"));
  EXPECT_EQ(high.rfind(where, 0), 0u) << high;
  EXPECT_NE(high.find("soft_limit_margin_m"), std::string::npos) << high;
  EXPECT_EQ(error_of(with_line(8, "  neutral_height_m: 3.0\nactuator:")), "");  // the control
  // At mid-stroke: a base so wide that the jacks cannot span the gap at any height.
  const std::string wide = error_of(with_line(2, "  base_radius_m: 6.0"));
  EXPECT_NE(wide.find("motion.yaml:"), std::string::npos) << wide;
  EXPECT_NE(wide.find("geometry: the neutral pose is unreachable"), std::string::npos) << wide;
  EXPECT_NE(wide.find("base_radius_m"), std::string::npos) << wide;
}

}  // namespace
}  // namespace fedsim::motion
