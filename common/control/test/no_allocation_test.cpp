// Stepping any block allocates nothing (the counting operator new of fedsim_allocation_counter).
#include <gtest/gtest.h>

#include <cmath>

#include "common/control/dead_band.hpp"
#include "common/control/fader.hpp"
#include "common/control/first_order_lag.hpp"
#include "common/control/gain.hpp"
#include "common/control/integrator.hpp"
#include "common/control/lead_lag.hpp"
#include "common/control/limiter.hpp"
#include "common/control/pid.hpp"
#include "common/control/rate_limiter.hpp"
#include "common/control/second_order_filters.hpp"
#include "common/control/washout.hpp"
#include "common/util/allocation_counter.hpp"

namespace fedsim::control {
namespace {

TEST(NoAllocation, StepAndResetAllocateNothing) {
  const double dt = 0.01;
  Gain gain(2.0);
  FirstOrderLag lag(0.5, dt);
  LeadLag lead(0.3, 0.1, dt);
  Washout washout(1.0, dt);
  SecondOrderLowPass low(10.0, 0.5, dt);
  SecondOrderHighPass high(10.0, 0.5, dt);
  BandPass band(10.0, 0.5, dt);
  Notch notch(10.0, 0.5, dt);
  Integrator integrator(1.0, dt, -1.0, 1.0);
  PidParameters p;
  p.proportional_gain = 1.0;
  p.integral_gain_per_s = 0.5;
  p.derivative_gain_s = 0.1;
  p.derivative_filter_time_constant_s = 0.05;
  p.output_min = -1.0;
  p.output_max = 1.0;
  Pid pid(p, dt);
  RateLimiter rate(1.0, dt);
  Limiter limiter(-1.0, 1.0);
  DeadBand dead_band(0.1);
  Fader fader(0.5, dt);
  double sum = 0.0;
  const util::AllocationScope scope;
  for (int n = 0; n < 1000; ++n) {
    const double u = std::sin(0.01 * n);
    sum += gain.step(u) + lag.step(u) + lead.step(u) + washout.step(u) + low.step(u) +
           high.step(u) + band.step(u) + notch.step(u) + integrator.step(u) + pid.step(u) +
           rate.step(u) + limiter.step(u) + dead_band.step(u) + fader.step(n / 300, u);
  }
  lag.reset(1.0);
  washout.reset_to_input(1.0);
  pid.engage(0.1, 0.2);
  integrator.reset(0.0);
  EXPECT_EQ(scope.allocations(), 0u);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace fedsim::control
