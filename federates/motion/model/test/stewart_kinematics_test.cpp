// Stewart platform kinematics: the geometry of the typical 60-inch design, inverse kinematics
// against hand computations (neutral, pure heave, pure yaw), the analytic Jacobian against
// finite differences, the forward/inverse round trip over seeded random poses, the documented
// single-axis excursions, and the workspace limiter.
#include "motion/model/stewart_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "common/units/units.hpp"
#include "motion/model/stewart_geometry.hpp"
#include "motion/model/workspace_limiter.hpp"

namespace fedsim::motion {
namespace {

using units::kDegToRad;

// Hand figures of the typical design: base radius 2.0 m, upper 1.5 m, every jack spanning
// 60 - 10 - 10 = 40 deg of azimuth; horizontal span by the law of cosines, neutral height from
// the mid-stroke length 2.21 + 1.524/2 = 2.972 m.
constexpr double kBaseRadius = 2.0;
constexpr double kTopRadius = 1.5;
constexpr double kMidStroke = 2.21 + 0.762;
double span_sq(double azimuth_difference_deg) {
  return kBaseRadius * kBaseRadius + kTopRadius * kTopRadius -
         2.0 * kBaseRadius * kTopRadius * std::cos(azimuth_difference_deg * kDegToRad);
}
const double kNeutralHeight = std::sqrt(kMidStroke * kMidStroke - span_sq(40.0));

StewartKinematics typical() {
  return StewartKinematics(make_symmetric_geometry(typical_60_inch_design()));
}

TEST(StewartGeometry, TypicalDesignFigures) {
  const StewartGeometry g = make_symmetric_geometry(typical_60_inch_design());
  EXPECT_NEAR(g.stroke_m(), 1.524, 1e-12);
  EXPECT_NEAR(kNeutralHeight, 2.6794, 1e-4);
  EXPECT_NEAR(neutral_height_m(typical_60_inch_design()), kNeutralHeight, 1e-12);
  // Jack 0: base joint at -10 deg, upper joint at -60 + 10 = -50 deg.
  EXPECT_NEAR(g.base_joints_i_m[0].x(), 2.0 * std::cos(-10.0 * kDegToRad), 1e-12);
  EXPECT_NEAR(g.base_joints_i_m[0].y(), 2.0 * std::sin(-10.0 * kDegToRad), 1e-12);
  EXPECT_NEAR(g.base_joints_i_m[0].z(), kNeutralHeight, 1e-12);
  EXPECT_NEAR(g.top_joints_p_m[0].x(), 1.5 * std::cos(-50.0 * kDegToRad), 1e-12);
  EXPECT_NEAR(g.top_joints_p_m[0].y(), 1.5 * std::sin(-50.0 * kDegToRad), 1e-12);
  // Jack 3: base joint at 120 + 10 = 130 deg, upper joint at 180 - 10 = 170 deg.
  EXPECT_NEAR(g.base_joints_i_m[3].y(), 2.0 * std::sin(130.0 * kDegToRad), 1e-12);
  EXPECT_NEAR(g.top_joints_p_m[3].x(), 1.5 * std::cos(170.0 * kDegToRad), 1e-12);
}

TEST(StewartKinematics, NeutralPoseHasEveryJackAtMidStroke) {
  const StewartKinematics k = typical();
  for (double length : k.inverse(PlatformPose{})) EXPECT_NEAR(length, kMidStroke, 1e-12);
  EXPECT_EQ(k.neutral_lengths_m(), k.inverse(PlatformPose{}));
}

TEST(StewartKinematics, PureHeaveAgainstHandComputation) {
  const StewartKinematics k = typical();
  for (double heave_m : {-0.5, -0.2, 0.3, 0.6}) {  // z down: -0.5 is 0.5 m up
    PlatformPose pose;
    pose.position_i_m.z() = heave_m;
    const double vertical = kNeutralHeight - heave_m;
    const double expected = std::sqrt(span_sq(40.0) + vertical * vertical);
    for (double length : k.inverse(pose)) EXPECT_NEAR(length, expected, 1e-12) << heave_m;
  }
}

TEST(StewartKinematics, PureYawAgainstHandComputation) {
  // Yaw by psi turns every upper joint by +psi in azimuth. Jack 0 runs from the base joint at
  // -10 deg to the upper joint at -50 deg: it then spans 40 - psi deg, as every even jack; the
  // odd jacks (jack 1: base +10 deg, upper +50 deg) span 40 + psi.
  const StewartKinematics k = typical();
  const double psi_deg = 12.0;
  PlatformPose pose;
  pose.attitude.psi_rad = psi_deg * kDegToRad;
  const JackArray lengths = k.inverse(pose);
  const double h2 = kNeutralHeight * kNeutralHeight;
  for (int j = 0; j < kJackCount; ++j) {
    const double span = j % 2 == 0 ? span_sq(40.0 - psi_deg) : span_sq(40.0 + psi_deg);
    EXPECT_NEAR(lengths[j], std::sqrt(span + h2), 1e-12) << j;
  }
}

TEST(StewartKinematics, JacobianMatchesFiniteDifferences) {
  const StewartKinematics k = typical();
  PlatformPose pose;
  pose.position_i_m = {0.2, -0.1, 0.15};
  pose.attitude = {0.1, -0.15, 0.2};
  const PoseJacobian j = k.jacobian(pose);
  const double h = 1e-6;
  for (int c = 0; c < 6; ++c) {
    PoseVector plus = to_vector(pose);
    PoseVector minus = plus;
    plus(c) += h;
    minus(c) -= h;
    const JackArray lp = k.inverse(from_vector(plus));
    const JackArray lm = k.inverse(from_vector(minus));
    for (int r = 0; r < kJackCount; ++r) {
      EXPECT_NEAR(j(r, c), (lp[r] - lm[r]) / (2.0 * h), 1e-8) << r << "," << c;
    }
  }
}

TEST(StewartKinematics, ForwardOfInverseIsThePoseOverSeededRandomPoses) {
  const StewartKinematics k = typical();
  std::mt19937_64 rng(20240612);
  std::uniform_real_distribution<double> position(-0.5, 0.5);
  std::uniform_real_distribution<double> angle(-15.0 * kDegToRad, 15.0 * kDegToRad);
  double worst_position_m = 0.0;
  double worst_angle_rad = 0.0;
  int worst_iterations = 0;
  int tested = 0;
  for (int i = 0; i < 2000; ++i) {
    PlatformPose pose;
    pose.position_i_m = {position(rng), position(rng), position(rng)};
    pose.attitude = {angle(rng), angle(rng), angle(rng)};
    const JackArray lengths = k.inverse(pose);
    if (!within(lengths, k.geometry().min_length_m, k.geometry().max_length_m)) continue;
    ++tested;
    const ForwardSolution solution = k.forward(lengths);  // from neutral: the hardest start
    ASSERT_TRUE(solution.converged) << i;
    worst_position_m = std::max(
        worst_position_m, (solution.pose.position_i_m - pose.position_i_m).cwiseAbs().maxCoeff());
    worst_angle_rad =
        std::max(worst_angle_rad,
                 (to_vector(solution.pose) - to_vector(pose)).tail<3>().cwiseAbs().maxCoeff());
    worst_iterations = std::max(worst_iterations, solution.iterations);
  }
  EXPECT_GT(tested, 1500);
  EXPECT_LT(worst_position_m, 1e-9);
  EXPECT_LT(worst_angle_rad, 1e-9);
  EXPECT_LE(worst_iterations, 8);
  std::printf("[figure] round trip over %d poses: %.2e m, %.2e rad, <= %d Newton iterations\n",
              tested, worst_position_m, worst_angle_rad, worst_iterations);
}

TEST(StewartKinematics, WarmStartedForwardConvergesInFewIterations) {
  const StewartKinematics k = typical();
  PlatformPose previous;
  previous.position_i_m = {0.3, 0.1, -0.2};
  previous.attitude = {0.05, 0.1, -0.05};
  PlatformPose next = previous;  // a frame later at 0.5 m/s and 10 deg/s
  next.position_i_m.x() += 0.5 / 60.0;
  next.attitude.theta_rad += 10.0 * kDegToRad / 60.0;
  const ForwardSolution solution = k.forward(k.inverse(next), previous);
  EXPECT_TRUE(solution.converged);
  EXPECT_LE(solution.iterations, 3);
  EXPECT_LT((to_vector(solution.pose) - to_vector(next)).cwiseAbs().maxCoeff(), 1e-10);
}

// The most a single pose component can move from neutral with every jack within the stroke.
double excursion(const StewartKinematics& k, int component, double sign) {
  double inside = 0.0;
  double outside = 3.0;
  for (int i = 0; i < 60; ++i) {
    const double middle = 0.5 * (inside + outside);
    PoseVector q = PoseVector::Zero();
    q(component) = sign * middle;
    const bool ok =
        within(k.inverse(from_vector(q)), k.geometry().min_length_m, k.geometry().max_length_m);
    (ok ? inside : outside) = middle;
  }
  return inside;
}

TEST(StewartKinematics, DocumentedSingleAxisExcursions) {
  // The figures stated in stewart_geometry.hpp and the README.
  const StewartKinematics k = typical();
  EXPECT_NEAR(excursion(k, 0, +1), 1.361, 1e-3);
  EXPECT_NEAR(excursion(k, 0, -1), 1.469, 1e-3);
  EXPECT_NEAR(excursion(k, 1, +1), 1.322, 1e-3);
  EXPECT_NEAR(excursion(k, 2, +1), 0.882, 1e-3);
  EXPECT_NEAR(excursion(k, 2, -1), 0.826, 1e-3);
  EXPECT_NEAR(excursion(k, 3, +1) / kDegToRad, 33.88, 0.01);
  EXPECT_NEAR(excursion(k, 4, +1) / kDegToRad, 36.29, 0.01);
  EXPECT_NEAR(excursion(k, 4, -1) / kDegToRad, 34.23, 0.01);
  EXPECT_NEAR(excursion(k, 5, +1) / kDegToRad, 54.91, 0.01);
}

TEST(WorkspaceLimiter, PoseInsideIsPassedUnchanged) {
  const StewartKinematics k = typical();
  const WorkspaceLimiter limiter(k, 0.05);
  PlatformPose pose;
  pose.position_i_m = {0.4, -0.2, 0.1};
  pose.attitude.theta_rad = 0.1;
  const LimitedPose limited = limiter.limit(pose);
  EXPECT_FALSE(limited.limited);
  EXPECT_EQ(limited.scale, 1.0);
  EXPECT_EQ(to_vector(limited.pose), to_vector(pose));
}

TEST(WorkspaceLimiter, PoseBeyondTheWorkspaceIsScaledOntoTheSoftLimit) {
  const StewartKinematics k = typical();
  const double margin = 0.05;
  const WorkspaceLimiter limiter(k, margin);
  PlatformPose pose;
  pose.position_i_m = {2.0, 0.5, -0.3};  // far outside
  pose.attitude = {0.2, 0.3, 0.0};
  const LimitedPose limited = limiter.limit(pose);
  EXPECT_TRUE(limited.limited);
  EXPECT_GT(limited.scale, 0.0);
  EXPECT_LT(limited.scale, 1.0);
  // Same direction, every jack inside the soft stroke, one on its boundary.
  EXPECT_LT((to_vector(limited.pose) - limited.scale * to_vector(pose)).norm(), 1e-15);
  const double lower = k.geometry().min_length_m + margin;
  const double upper = k.geometry().max_length_m - margin;
  EXPECT_TRUE(within(limited.lengths_m, lower, upper));
  double closest = 1.0;
  for (double l : limited.lengths_m) closest = std::min({closest, l - lower, upper - l});
  EXPECT_LT(closest, 1e-9);
  // Negative control: without the margin the same demand is limited less.
  const WorkspaceLimiter no_margin(k, 0.0);
  EXPECT_GT(no_margin.limit(pose).scale, limited.scale);
}

TEST(StewartKinematics, RejectsBadGeometryAndPoses) {
  SymmetricStewartDesign d = typical_60_inch_design();
  d.top_radius_m = -1.0;
  EXPECT_THROW(make_symmetric_geometry(d), std::invalid_argument);
  d = typical_60_inch_design();
  d.base_half_separation_rad = 35.0 * kDegToRad;
  EXPECT_THROW(make_symmetric_geometry(d), std::invalid_argument);
  d = typical_60_inch_design();
  d.base_radius_m = 6.0;  // the jacks cannot reach across
  EXPECT_THROW(make_symmetric_geometry(d), std::invalid_argument);
  d = typical_60_inch_design();
  d.neutral_height_m = 1.5;  // a named neutral below the retracted jacks' reach
  EXPECT_THROW(make_symmetric_geometry(d), std::invalid_argument);
  EXPECT_NO_THROW(place_symmetric_joints(d));  // the joints alone, for a loader to diagnose
  d.neutral_height_m = 2.5;  // inside the stroke: accepted, at that height
  EXPECT_EQ(make_symmetric_geometry(d).base_joints_i_m[0].z(), 2.5);
  const StewartKinematics k = typical();
  PlatformPose bad;
  bad.attitude.phi_rad = std::nan("");
  EXPECT_THROW(k.inverse(bad), std::invalid_argument);
  JackArray lengths = k.neutral_lengths_m();
  lengths[2] = -1.0;
  EXPECT_THROW(k.forward(lengths), std::invalid_argument);
  EXPECT_THROW(WorkspaceLimiter(k, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::motion
