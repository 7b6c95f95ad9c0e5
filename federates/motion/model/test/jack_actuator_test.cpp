// Jack actuator: the small-signal step response against the analytic second-order response,
// the velocity and acceleration limits, the end-stop cushion (and its negative control), the
// mechanical stroke, validation.
#include "motion/model/jack_actuator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::motion {
namespace {

constexpr double kMin = 2.21;
constexpr double kMax = 2.21 + 1.524;
constexpr double kH = 1e-3;

TEST(JackActuator, SmallStepFollowsTheSecondOrderResponse) {
  const JackActuatorParameters p;  // wa 50 rad/s, zeta 0.8
  JackActuator jack(p, kMin, kMax, kH, 3.0);
  const double step_m = 0.001;  // small: no limit acts
  double peak = 0.0;
  double t_peak = 0.0;
  for (int n = 1; n <= 1000; ++n) {
    jack.step(3.0 + step_m);
    EXPECT_FALSE(jack.rate_limited());
    if (jack.length_m() - 3.0 > peak) {
      peak = jack.length_m() - 3.0;
      t_peak = n * kH;
    }
  }
  const double zeta = p.damping_ratio;
  const double wd = p.natural_frequency_radps * std::sqrt(1.0 - zeta * zeta);
  const double overshoot = std::exp(-M_PI * zeta / std::sqrt(1.0 - zeta * zeta));
  EXPECT_NEAR(peak / step_m - 1.0, overshoot, 0.1 * overshoot);
  EXPECT_NEAR(t_peak, M_PI / wd, 2.0 * kH);
  EXPECT_NEAR(jack.length_m(), 3.0 + step_m, 1e-9);
}

TEST(JackActuator, LargeStepIsVelocityAndAccelerationLimited) {
  const JackActuatorParameters p;
  JackActuator jack(p, kMin, kMax, kH, 2.5);
  double max_speed = 0.0;
  double max_acceleration = 0.0;
  bool limited = false;
  for (int n = 0; n < 3000; ++n) {
    jack.step(3.3);
    max_speed = std::max(max_speed, std::abs(jack.velocity_mps()));
    max_acceleration = std::max(max_acceleration, std::abs(jack.acceleration_mps2()));
    limited = limited || jack.rate_limited();
  }
  EXPECT_TRUE(limited);
  EXPECT_NEAR(max_speed, p.velocity_limit_mps, 1e-12);
  EXPECT_LE(max_acceleration, p.acceleration_limit_mps2 * (1.0 + 1e-9));
  EXPECT_NEAR(jack.length_m(), 3.3, 1e-6);
}

// Drives the jack at full speed into its upper end: the highest deceleration seen (the impact,
// if any) and the speed with which it passes 1 mm before the end.
struct EndRun {
  double max_deceleration_mps2 = 0.0;
  double speed_1mm_before_end_mps = -1.0;
  double final_length_m = 0.0;
  bool cushioned = false;
};
EndRun run_into_upper_end(const JackActuatorParameters& p) {
  JackActuator jack(p, kMin, kMax, kH, 3.0);
  EndRun run;
  double previous_velocity = 0.0;
  for (int n = 0; n < 4000; ++n) {
    jack.step(kMax + 1.0);  // a command beyond the stroke (a failed limiter)
    EXPECT_LE(jack.length_m(), kMax);
    run.max_deceleration_mps2 =
        std::max(run.max_deceleration_mps2, (previous_velocity - jack.velocity_mps()) / kH);
    if (run.speed_1mm_before_end_mps < 0.0 && jack.length_m() > kMax - 1e-3) {
      run.speed_1mm_before_end_mps = jack.velocity_mps();
    }
    run.cushioned = run.cushioned || jack.cushioned();
    previous_velocity = jack.velocity_mps();
  }
  run.final_length_m = jack.length_m();
  return run;
}

TEST(JackActuator, CushionBrakesTheJackBeforeItsEnd) {
  const JackActuatorParameters p;
  const EndRun run = run_into_upper_end(p);
  EXPECT_TRUE(run.cushioned);
  EXPECT_NEAR(run.final_length_m, kMax, 1e-9);
  // Braked at no more than the cushion's deceleration all the way: 1 mm before the end it runs
  // at about sqrt(2 a_c 1 mm) = 0.14 m/s, and arrives without an impact.
  EXPECT_LE(run.max_deceleration_mps2, p.cushion_deceleration_mps2 * (1.0 + 1e-6));
  EXPECT_LT(run.speed_1mm_before_end_mps, 0.15);
  // Negative control: a cushion a thousand times harder stops it within two sub-steps: an
  // impact of hundreds of m/s^2, arriving at full speed.
  JackActuatorParameters hard = p;
  hard.cushion_deceleration_mps2 = 1e4;
  const EndRun hit = run_into_upper_end(hard);
  EXPECT_GT(hit.max_deceleration_mps2, 300.0);
  EXPECT_GT(hit.speed_1mm_before_end_mps, 0.5);
}

TEST(JackActuator, Validation) {
  JackActuatorParameters p;
  EXPECT_THROW(JackActuator(p, kMin, kMax, 0.01, 3.0), std::invalid_argument);  // wa h = 0.5
  p.velocity_limit_mps = std::nan("");
  EXPECT_THROW(JackActuator(p, kMin, kMax, kH, 3.0), std::invalid_argument);
  p = {};
  EXPECT_THROW(JackActuator(p, kMax, kMin, kH, 3.0), std::invalid_argument);
  EXPECT_THROW(JackActuator(p, kMin, kMax, kH, 5.0), std::invalid_argument);
  JackActuator jack(p, kMin, kMax, kH, 3.0);
  EXPECT_THROW(jack.step(std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::motion
