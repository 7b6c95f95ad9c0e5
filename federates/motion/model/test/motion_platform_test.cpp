// Motion platform: engaging, the stated manoeuvres inside the stroke without limiting, the
// limiter on a larger manoeuvre, the delivered cue, parking and every fault path.
#include "motion/model/motion_platform.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "motion/model/test/manoeuvres.hpp"

namespace fedsim::motion {
namespace {

using test::kG;
constexpr double kDt = 1.0 / 60.0;

MotionInputs level() { return MotionInputs{}; }

double max_speed(const MotionPlatformOutputs& out) {
  double v = 0.0;
  for (double s : out.jack_velocity_mps) v = std::max(v, std::abs(s));
  return v;
}

// Engages from parked with level-flight inputs; the frames it took.
int engage(MotionPlatform& platform) {
  EXPECT_TRUE(platform.engage());
  int frames = 0;
  while (platform.status() == MotionStatus::kEngaging && frames < 60 * 20) {
    platform.step(level());
    ++frames;
  }
  EXPECT_EQ(platform.status(), MotionStatus::kEngaged);
  return frames;
}

struct RunSummary {
  double min_soft_margin_m = 1e9;  // closest approach of any jack to its soft limit [m]
  double min_hard_margin_m = 1e9;  // ... to its stroke end [m]
  int limited_frames = 0;
  int slowed_frames = 0;
  bool stayed_engaged = true;
};

RunSummary run(MotionPlatform& platform, const std::vector<MotionInputs>& inputs) {
  const MotionPlatformParameters p;
  const double lower = p.geometry.min_length_m;
  const double upper = p.geometry.max_length_m;
  RunSummary summary;
  for (const MotionInputs& in : inputs) {
    const MotionPlatformOutputs& out = platform.step(in);
    for (double l : out.jack_length_m) {
      summary.min_hard_margin_m = std::min({summary.min_hard_margin_m, l - lower, upper - l});
      summary.min_soft_margin_m =
          std::min({summary.min_soft_margin_m, l - lower - p.soft_limit_margin_m,
                    upper - p.soft_limit_margin_m - l});
    }
    summary.limited_frames += out.workspace_limited ? 1 : 0;
    summary.slowed_frames += out.command_rate_limited ? 1 : 0;
    summary.stayed_engaged = summary.stayed_engaged && out.status == MotionStatus::kEngaged;
  }
  return summary;
}

TEST(MotionPlatform, EngagesSlowlyFromParkedToNeutral) {
  MotionPlatform platform(MotionPlatformParameters{}, kDt);
  EXPECT_EQ(platform.substeps_per_frame(), 17);  // 1020 Hz jack loop at 60 Hz
  EXPECT_EQ(platform.status(), MotionStatus::kParked);
  EXPECT_FALSE(platform.park());
  ASSERT_TRUE(platform.engage());
  double fastest = 0.0;
  int frames = 0;
  while (platform.status() == MotionStatus::kEngaging) {
    fastest = std::max(fastest, max_speed(platform.step(level())));
    ++frames;
  }
  EXPECT_EQ(platform.status(), MotionStatus::kEngaged);
  EXPECT_LE(fastest, 0.15 * 1.02);
  // 0.762 m at 0.15 m/s = 5.08 s, plus the servo's settling.
  EXPECT_GT(frames * kDt, 5.0);
  EXPECT_LT(frames * kDt, 6.5);
  for (int k = 0; k < kJackCount; ++k) {
    EXPECT_NEAR(platform.outputs().jack_length_m[k], platform.kinematics().neutral_lengths_m()[k],
                1e-3);
  }
  EXPECT_LT(to_vector(platform.outputs().pose).cwiseAbs().maxCoeff(), 2e-3);
}

TEST(MotionPlatform, StatedManoeuvresStayInsideTheSoftStrokeUnlimited) {
  for (int manoeuvre = 0; manoeuvre < 2; ++manoeuvre) {
    MotionPlatform platform(MotionPlatformParameters{}, kDt);
    engage(platform);
    const std::vector<MotionInputs> inputs =
        manoeuvre == 0 ? test::pitch_doublet(kDt, 40.0) : test::takeoff_roll(kDt, 60.0);
    const RunSummary summary = run(platform, inputs);
    EXPECT_TRUE(summary.stayed_engaged) << manoeuvre;
    EXPECT_EQ(summary.limited_frames, 0) << manoeuvre;
    EXPECT_EQ(summary.slowed_frames, 0) << manoeuvre;
    EXPECT_GT(summary.min_soft_margin_m, 0.0) << manoeuvre;
    std::printf("[figure] %s: closest jack approach to the soft limit %.3f m\n",
                manoeuvre == 0 ? "pitch doublet 6 deg/s at 70 m/s" : "takeoff roll 2.5 m/s^2",
                summary.min_soft_margin_m);
  }
}

TEST(MotionPlatform, LargerManoeuvresEngageTheLimiterAndStayInsideTheStroke) {
  test::ManoeuvreScale violent;
  violent.pitch_rate_radps = 25.0 * units::kDegToRad;
  violent.airspeed_mps = 120.0;
  violent.takeoff_acceleration_mps2 = 6.0;
  for (int manoeuvre = 0; manoeuvre < 2; ++manoeuvre) {
    MotionPlatformParameters p;
    p.washout.translational[0].gain = 1.0;  // cue everything: a badly tuned washout
    p.washout.translational[2].gain = 1.0;
    p.washout.rotational[1].gain = 1.0;
    MotionPlatform platform(p, kDt);
    engage(platform);
    const std::vector<MotionInputs> inputs = manoeuvre == 0
                                                 ? test::pitch_doublet(kDt, 40.0, violent)
                                                 : test::takeoff_roll(kDt, 60.0, violent);
    const RunSummary summary = run(platform, inputs);
    EXPECT_GT(summary.limited_frames, 10) << manoeuvre;
    EXPECT_TRUE(summary.stayed_engaged) << manoeuvre;
    EXPECT_GT(summary.min_hard_margin_m, 0.0) << manoeuvre;
    EXPECT_GT(summary.min_soft_margin_m, -0.01) << manoeuvre;  // servo overshoot only
    std::printf(
        "[figure] violent %s: limited in %d frames, slowed in %d, closest to the "
        "stroke end %.3f m\n",
        manoeuvre == 0 ? "doublet" : "takeoff", summary.limited_frames, summary.slowed_frames,
        summary.min_hard_margin_m);
  }
}

TEST(MotionPlatform, DeliversTheOnsetAndTheSustainedTakeoffCue) {
  MotionPlatform platform(MotionPlatformParameters{}, kDt);
  engage(platform);
  const std::vector<MotionInputs> inputs = test::takeoff_roll(kDt, 29.0);
  double onset_peak = 0.0;
  double sustained = 0.0;
  for (std::size_t n = 0; n < inputs.size(); ++n) {
    const MotionPlatformOutputs& out = platform.step(inputs[n]);
    if (n * kDt < 3.0) onset_peak = std::max(onset_peak, out.specific_force_cue_p_mps2.x());
    sustained = out.specific_force_cue_p_mps2.x();
  }
  // Onset: the high-pass passes K a = 1.25 m/s^2 at first while the tilt starts; the
  // sustained 2.5 m/s^2 comes from the 14.8 deg tilt (gravity), after the washout.
  EXPECT_GT(onset_peak, 1.0);
  EXPECT_NEAR(sustained, 2.5, 0.05);
  EXPECT_NEAR(platform.outputs().pose.attitude.theta_rad, std::asin(2.5 / kG), 2e-3);
  std::printf("[figure] takeoff cue: onset peak %.2f m/s^2, sustained %.3f m/s^2 (demand 2.5)\n",
              onset_peak, sustained);
}

// Parks (or faults) while the platform is tilted and moving mid-takeoff; checks the descent.
struct Descent {
  double seconds = 0.0;
  double fastest_after_1s_mps = 0.0;
  double min_length_m = 1e9;
};
Descent descend(MotionPlatform& platform) {
  const MotionPlatformParameters p;
  Descent d;
  int frames = 0;
  while (!(platform.status() == MotionStatus::kParked ||
           (platform.status() == MotionStatus::kFault && frames > 0 &&
            max_speed(platform.outputs()) < 1e-3 &&
            *std::max_element(platform.outputs().jack_length_m.begin(),
                              platform.outputs().jack_length_m.end()) <
                p.geometry.min_length_m + 1e-3)) &&
         frames < 60 * 60) {
    const MotionPlatformOutputs& out = platform.step(level());
    ++frames;
    if (frames * kDt > 1.0)
      d.fastest_after_1s_mps = std::max(d.fastest_after_1s_mps, max_speed(out));
    for (double l : out.jack_length_m) d.min_length_m = std::min(d.min_length_m, l);
  }
  d.seconds = frames * kDt;
  return d;
}

MotionPlatform platform_mid_takeoff() {
  MotionPlatform platform(MotionPlatformParameters{}, kDt);
  engage(platform);
  for (const MotionInputs& in : test::takeoff_roll(kDt, 8.0)) platform.step(in);
  return platform;
}

TEST(MotionPlatform, ParkingBringsEveryJackToItsMinimumAtABoundedSpeed) {
  MotionPlatform platform = platform_mid_takeoff();
  const double longest = *std::max_element(platform.outputs().jack_length_m.begin(),
                                           platform.outputs().jack_length_m.end());
  ASSERT_TRUE(platform.park());
  EXPECT_EQ(platform.status(), MotionStatus::kParking);
  const Descent d = descend(platform);
  EXPECT_EQ(platform.status(), MotionStatus::kParked);
  for (double l : platform.outputs().jack_length_m) EXPECT_NEAR(l, 2.21, 1e-3);
  EXPECT_GE(d.min_length_m, 2.21);
  EXPECT_LE(d.fastest_after_1s_mps, 0.10 * 1.02);
  EXPECT_LT(d.seconds, (longest - 2.21) / 0.10 + 2.0);
  std::printf("[figure] parked from mid-takeoff in %.2f s, jacks <= %.3f m/s\n", d.seconds,
              d.fastest_after_1s_mps);
}

TEST(MotionPlatform, NonFiniteInputFaultsWithinTheFrameAndParks) {
  MotionPlatform platform = platform_mid_takeoff();
  MotionInputs bad;
  bad.specific_force_eye_body_mps2.x() = std::nan("");
  EXPECT_EQ(platform.step(bad).status, MotionStatus::kFault);
  EXPECT_NE(platform.fault_reason().find("specific_force"), std::string::npos);
  EXPECT_FALSE(platform.clear_fault());  // not yet down
  EXPECT_FALSE(platform.engage());
  const Descent d = descend(platform);
  EXPECT_EQ(platform.status(), MotionStatus::kFault);  // latched
  EXPECT_GE(d.min_length_m, 2.21);
  EXPECT_LE(d.fastest_after_1s_mps, 0.10 * 1.02);
  EXPECT_TRUE(platform.clear_fault());
  EXPECT_EQ(platform.status(), MotionStatus::kParked);
  engage(platform);  // and it can be engaged again
}

TEST(MotionPlatform, EveryFaultPathParksWithinTheStroke) {
  struct Case {
    const char* name;
    std::string expected_reason;
  };
  for (int which = 0; which < 4; ++which) {
    MotionPlatformParameters p;
    if (which == 3) p.following_error_limit_m = 0.002;  // trips on the takeoff's motion
    MotionPlatform platform(p, kDt);
    engage(platform);
    std::string expected;
    const std::vector<MotionInputs> takeoff = test::takeoff_roll(kDt, 8.0);
    for (std::size_t n = 0; n < takeoff.size() && platform.status() == MotionStatus::kEngaged;
         ++n) {
      MotionInputs in = takeoff[n];
      if (n == 200 && which == 0) {
        platform.trip("instructor stop");
        expected = "instructor stop";
      }
      if (n == 200 && which == 1) {
        in.omega_body_radps.z() = 50.0;  // implausible rate
        expected = "omega_body_radps";
      }
      if (n == 200 && which == 2) {
        in.specific_force_eye_body_mps2.z() = INFINITY;
        expected = "specific_force";
      }
      if (which == 3) expected = "following error";
      platform.step(in);
    }
    ASSERT_EQ(platform.status(), MotionStatus::kFault) << which;
    EXPECT_NE(platform.fault_reason().find(expected), std::string::npos)
        << which << ": " << platform.fault_reason();
    const Descent d = descend(platform);
    EXPECT_GE(d.min_length_m, 2.21) << which;
    EXPECT_LE(d.fastest_after_1s_mps, 0.10 * 1.02) << which;
    for (double l : platform.outputs().jack_length_m) EXPECT_NEAR(l, 2.21, 1e-3) << which;
  }
}

TEST(MotionPlatform, FaultDuringEngagingAlsoParks) {
  MotionPlatform platform(MotionPlatformParameters{}, kDt);
  platform.engage();
  for (int n = 0; n < 120; ++n) platform.step(level());
  platform.trip("lost ticks");
  EXPECT_EQ(platform.status(), MotionStatus::kFault);
  platform.trip("second reason");
  EXPECT_EQ(platform.fault_reason(), "lost ticks");
  const Descent d = descend(platform);
  EXPECT_LE(d.fastest_after_1s_mps, 0.10 * 1.02);
  EXPECT_TRUE(platform.clear_fault());
}

TEST(MotionPlatform, RejectsBadParameters) {
  MotionPlatformParameters p;
  p.actuator_rate_hz = 200.0;
  EXPECT_THROW(MotionPlatform(p, kDt), std::invalid_argument);
  p = {};
  p.park_speed_mps = 2.0;  // faster than the jacks
  EXPECT_THROW(MotionPlatform(p, kDt), std::invalid_argument);
  p = {};
  p.soft_limit_margin_m = std::nan("");
  EXPECT_THROW(MotionPlatform(p, kDt), std::invalid_argument);
  EXPECT_THROW(MotionPlatform(MotionPlatformParameters{}, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::motion
