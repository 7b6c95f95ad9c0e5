// Tests of the integrators: orders of accuracy, AB starter and restart, sub-stepping, no allocation.
#include "common/math/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "common/util/allocation_counter.hpp"

namespace fedsim {
namespace {

using Scalar = Integrator<1>::Vector;
using Oscillator = Integrator<2>::Vector;

// y' = -y, y(0) = 1: error at t_end against exp(-t_end).
double decay_error(IntegrationMethod method, double h, double t_end) {
  Integrator<1> integrator(method);
  Scalar y(1.0);
  const auto f = [](double, const Scalar& x) { return Scalar(-x); };
  const int steps = static_cast<int>(std::lround(t_end / h));
  for (int i = 0; i < steps; ++i) integrator.step(i * h, h, y, f);
  return std::abs(y[0] - std::exp(-t_end));
}

// x'' = -w^2 x, x(0) = 1, x'(0) = 0: error at t_end against cos(w t_end).
double oscillator_error(IntegrationMethod method, double h, double t_end) {
  constexpr double w = 2.0;
  Integrator<2> integrator(method);
  Oscillator y(1.0, 0.0);
  const auto f = [](double, const Oscillator& s) { return Oscillator(s[1], -w * w * s[0]); };
  const int steps = static_cast<int>(std::lround(t_end / h));
  for (int i = 0; i < steps; ++i) integrator.step(i * h, h, y, f);
  return std::hypot(y[0] - std::cos(w * t_end), y[1] + w * std::sin(w * t_end));
}

class IntegratorOrder : public ::testing::TestWithParam<IntegrationMethod> {};

TEST_P(IntegratorOrder, ErrorFallsAsTwoToTheOrderWhenTheStepIsHalved) {
  const IntegrationMethod method = GetParam();
  const double expected = std::pow(2.0, order_of(method));
  const double decay_ratio = decay_error(method, 0.02, 2.0) / decay_error(method, 0.01, 2.0);
  const double osc_ratio = oscillator_error(method, 0.01, 3.0) / oscillator_error(method, 0.005, 3.0);
  EXPECT_NEAR(decay_ratio / expected, 1.0, 0.15) << to_string(method) << " " << decay_ratio;
  EXPECT_NEAR(osc_ratio / expected, 1.0, 0.15) << to_string(method) << " " << osc_ratio;
}

INSTANTIATE_TEST_SUITE_P(AllMethods, IntegratorOrder,
                         ::testing::Values(IntegrationMethod::kEuler, IntegrationMethod::kRk4,
                                           IntegrationMethod::kAb2, IntegrationMethod::kAb3,
                                           IntegrationMethod::kAb4),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(Integrator, ErrorsHaveTheExpectedSize) {
  // Global errors at h = 0.01 on y' = -y to t = 2 (e^-2 = 0.135): Euler ~ t e^-t h / 2.
  EXPECT_NEAR(decay_error(IntegrationMethod::kEuler, 0.01, 2.0), 2.0 * std::exp(-2.0) * 0.005,
              2e-5);
  EXPECT_LT(decay_error(IntegrationMethod::kRk4, 0.01, 2.0), 1e-10);
  EXPECT_LT(decay_error(IntegrationMethod::kAb4, 0.01, 2.0), 1e-8);
}

TEST(Integrator, AdamsBashforthStartsWithRk4StepsAndRestarts) {
  const auto f = [](double t, const Scalar& x) { return Scalar(std::cos(t) - x[0]); };
  Integrator<1> ab4(IntegrationMethod::kAb4);
  Integrator<1> rk4(IntegrationMethod::kRk4);
  Scalar ya(0.5);
  Scalar yr(0.5);
  const double h = 0.1;
  for (int i = 0; i < 3; ++i) {  // AB4 needs f_n..f_(n-3): the first three steps are RK4
    ab4.step(i * h, h, ya, f);
    rk4.step(i * h, h, yr, f);
    EXPECT_DOUBLE_EQ(ya[0], yr[0]) << i;
  }
  ab4.step(3 * h, h, ya, f);
  rk4.step(3 * h, h, yr, f);
  EXPECT_NE(ya[0], yr[0]);  // fourth step is a true AB4 step
  EXPECT_EQ(ab4.history_size(), 4);
  ab4.restart();
  EXPECT_EQ(ab4.history_size(), 0);
  ya = yr;
  ab4.step(4 * h, h, ya, f);
  rk4.step(4 * h, h, yr, f);
  EXPECT_DOUBLE_EQ(ya[0], yr[0]);  // after restart the starter runs again
}

TEST(Integrator, ChangingTheStepRestartsTheHistory) {
  const auto f = [](double, const Scalar& x) { return Scalar(-x); };
  Integrator<1> ab2(IntegrationMethod::kAb2);
  Scalar y(1.0);
  for (int i = 0; i < 5; ++i) ab2.step(i * 0.1, 0.1, y, f);
  EXPECT_EQ(ab2.history_size(), 4);
  ab2.step(0.5, 0.05, y, f);
  EXPECT_EQ(ab2.history_size(), 1);
}

TEST(Integrator, SubStepsMatchSeparateSteps) {
  const auto f = [](double t, const Oscillator& s) { return Oscillator(s[1], -s[0] + t); };
  Integrator<2> framed(IntegrationMethod::kAb3);
  Integrator<2> manual(IntegrationMethod::kAb3);
  Oscillator a(1.0, 0.0);
  Oscillator b(1.0, 0.0);
  for (int frame = 0; frame < 10; ++frame) {
    framed.step_frame(frame * 0.02, 0.02, 4, a, f);
    for (int k = 0; k < 4; ++k) manual.step(frame * 0.02 + k * 0.005, 0.005, b, f);
  }
  EXPECT_DOUBLE_EQ(a[0], b[0]);
  EXPECT_DOUBLE_EQ(a[1], b[1]);
}

TEST(Integrator, MethodNames) {
  EXPECT_EQ(integration_method_from_name("RK4"), IntegrationMethod::kRk4);
  EXPECT_EQ(integration_method_from_name("ab3"), IntegrationMethod::kAb3);
  EXPECT_EQ(to_string(IntegrationMethod::kEuler), "euler");
  EXPECT_THROW(integration_method_from_name("midpoint"), std::invalid_argument);
}

TEST(Integrator, StepsDoNotAllocate) {
  using State = Integrator<13>::Vector;
  const auto f = [](double, const State& s) { return State(-0.5 * s); };
  for (IntegrationMethod method : {IntegrationMethod::kEuler, IntegrationMethod::kRk4,
                                   IntegrationMethod::kAb2, IntegrationMethod::kAb4}) {
    Integrator<13> integrator(method);
    State y = State::Ones();
    const util::AllocationScope scope;
    for (int i = 0; i < 100; ++i) integrator.step(i * 0.01, 0.01, y, f);
    integrator.restart();
    integrator.step_frame(1.0, 0.02, 2, y, f);
    EXPECT_EQ(scope.allocations(), 0u) << to_string(method);
  }
}

}  // namespace
}  // namespace fedsim
