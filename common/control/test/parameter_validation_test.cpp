// Every block rejects bad parameters and non-finite inputs with std::invalid_argument naming the
// parameter. Each case pairs the bad construction with a good one differing only in that
// parameter (the negative control: the check is on that value, not on the block).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/control/bilinear.hpp"
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

namespace fedsim::control {
namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

struct Case {
  std::string name;
  std::function<void()> bad;
  std::function<void()> good;
  std::string expected_in_message;
};

// The message of the std::invalid_argument f throws, or "" if it throws none.
std::string invalid_argument_message(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

void expect_all(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    const std::string message = invalid_argument_message(c.bad);
    EXPECT_NE(message.find(c.expected_in_message), std::string::npos)
        << c.name << ": message '" << message << "' lacks '" << c.expected_in_message << "'";
    EXPECT_NO_THROW(c.good()) << c.name;
  }
}

TEST(ParameterValidation, LinearBlocks) {
  const double dt = 0.01;
  expect_all({
      {"lag tau NaN", [&] { FirstOrderLag(kNan, dt); }, [&] { FirstOrderLag(0.5, dt); },
       "FirstOrderLag: time_constant_s = nan must be finite"},
      {"lag tau < 0", [&] { FirstOrderLag(-0.5, dt); }, [&] { FirstOrderLag(0.5, dt); },
       "time_constant_s = -0.5 must be positive"},
      {"lag tau 0", [&] { FirstOrderLag(0.0, dt); }, [&] { FirstOrderLag(0.5, dt); },
       "time_constant_s"},
      {"lag dt 0", [&] { FirstOrderLag(0.5, 0.0); }, [&] { FirstOrderLag(0.5, dt); }, "dt_s"},
      {"lag dt inf", [&] { FirstOrderLag(0.5, kInf); }, [&] { FirstOrderLag(0.5, dt); },
       "dt_s = inf must be finite"},
      {"lag corner above Nyquist", [&] { FirstOrderLag(0.003, dt); },
       [&] { FirstOrderLag(0.0032, dt); }, "corner 1/time_constant_s = 333.3"},
      {"lag gain 0", [&] { FirstOrderLag(0.5, dt, 0.0); }, [&] { FirstOrderLag(0.5, dt, 1.0); },
       "gain"},
      {"lead-lag lead", [&] { LeadLag(-1.0, 0.1, dt); }, [&] { LeadLag(1.0, 0.1, dt); },
       "lead_time_constant_s"},
      {"lead-lag lag Nyquist", [&] { LeadLag(1.0, 0.001, dt); }, [&] { LeadLag(1.0, 0.01, dt); },
       "Nyquist"},
      {"washout tau", [&] { Washout(kInf, dt); }, [&] { Washout(1.0, dt); }, "time_constant_s"},
      {"low-pass wn Nyquist", [&] { SecondOrderLowPass(400.0, 0.5, dt); },
       [&] { SecondOrderLowPass(300.0, 0.5, dt); }, "natural_frequency_radps = 400"},
      {"low-pass zeta < 0", [&] { SecondOrderLowPass(10.0, -0.1, dt); },
       [&] { SecondOrderLowPass(10.0, 0.0, dt); }, "damping_ratio = -0.1 must not be negative"},
      {"high-pass wn 0", [&] { SecondOrderHighPass(0.0, 0.5, dt); },
       [&] { SecondOrderHighPass(1.0, 0.5, dt); }, "natural_frequency_radps"},
      {"band-pass zeta 0", [&] { BandPass(10.0, 0.0, dt); }, [&] { BandPass(10.0, 0.1, dt); },
       "damping_ratio"},
      {"notch zeta 0", [&] { Notch(10.0, 0.0, dt); }, [&] { Notch(10.0, 0.1, dt); },
       "damping_ratio"},
      {"notch dt", [&] { Notch(10.0, 0.1, -dt); }, [&] { Notch(10.0, 0.1, dt); }, "dt_s"},
      {"prewarp at Nyquist", [&] { prewarped_tustin_constant_per_s(dt, 314.16); },
       [&] { prewarped_tustin_constant_per_s(dt, 314.15); }, "prewarp_radps"},
  });
}

TEST(ParameterValidation, IntegratorAndPid) {
  const double dt = 0.01;
  PidParameters good;
  good.proportional_gain = 1.0;
  good.derivative_gain_s = 0.1;
  good.derivative_filter_time_constant_s = 0.05;
  const auto with = [&](auto change) {
    PidParameters p = good;
    change(p);
    return p;
  };
  expect_all({
      {"integrator gain", [&] { Integrator(kNan, dt); }, [&] { Integrator(1.0, dt); },
       "gain_per_s"},
      {"integrator limits", [&] { Integrator(1.0, dt, 1.0, -1.0); },
       [&] { Integrator(1.0, dt, -1.0, 1.0); }, "lower_limit = 1 must be below upper_limit = -1"},
      {"integrator NaN limit", [&] { Integrator(1.0, dt, kNan, 1.0); },
       [&] { Integrator(1.0, dt, -kInf, 1.0); }, "lower_limit"},
      {"pid kp", [&] { Pid(with([](PidParameters& p) { p.proportional_gain = kInf; }), dt); },
       [&] { Pid(good, dt); }, "proportional_gain"},
      {"pid filter 0",
       [&] { Pid(with([](PidParameters& p) { p.derivative_filter_time_constant_s = 0.0; }), dt); },
       [&] {
         Pid(with([](PidParameters& p) {
               p.derivative_filter_time_constant_s = 0.0;
               p.derivative_gain_s = 0.0;
             }),
             dt);
       },
       "derivative_filter_time_constant_s"},
      {"pid roll-off Nyquist",
       [&] {
         Pid(with([](PidParameters& p) { p.derivative_filter_time_constant_s = 0.001; }), dt);
       },
       [&] { Pid(good, dt); }, "roll-off 1/derivative_filter_time_constant_s"},
      {"pid limits", [&] { Pid(with([](PidParameters& p) { p.output_max = kNan; }), dt); },
       [&] { Pid(good, dt); }, "output_max"},
      {"pid tracking",
       [&] {
         Pid(with([](PidParameters& p) {
               p.anti_windup = AntiWindup::kBackCalculation;
               p.tracking_time_constant_s = 0.005;
             }),
             dt);
       },
       [&] {
         Pid(with([](PidParameters& p) {
               p.anti_windup = AntiWindup::kBackCalculation;
               p.tracking_time_constant_s = 0.5;
             }),
             dt);
       },
       "tracking_time_constant_s = 0.005 must be at least dt_s"},
      {"pid dt", [&] { Pid(good, 0.0); }, [&] { Pid(good, dt); }, "dt_s"},
  });
}

TEST(ParameterValidation, NonlinearBlocks) {
  const double dt = 0.01;
  expect_all({
      {"gain", [&] { Gain g(kNan); }, [&] { Gain g(0.0); }, "gain"},
      {"rate", [&] { RateLimiter(0.0, dt); }, [&] { RateLimiter(1.0, dt); }, "rate_limit_per_s"},
      {"fall rate", [&] { RateLimiter(1.0, -1.0, dt); }, [&] { RateLimiter(1.0, 1.0, dt); },
       "fall_rate_per_s"},
      {"limiter", [&] { Limiter(2.0, 2.0); }, [&] { Limiter(2.0, 3.0); }, "lower_limit"},
      {"dead-band width", [&] { DeadBand d(-1.0); }, [&] { DeadBand d(1.0); }, "half_width"},
      {"dead-band order", [&] { DeadBand(1.0, -1.0); }, [&] { DeadBand(-1.0, 1.0); }, "lower"},
      {"fader shorter than dt", [&] { Fader(0.005, dt); }, [&] { Fader(0.01, dt); },
       "fade_time_s = 0.005 must be at least dt_s"},
      {"fader NaN", [&] { Fader(kNan, dt); }, [&] { Fader(1.0, dt); }, "fade_time_s"},
  });
}

TEST(ParameterValidation, NonFiniteInputsAreRejected) {
  const double dt = 0.01;
  FirstOrderLag lag(0.5, dt);
  SecondOrderLowPass low(10.0, 0.5, dt);
  Integrator integrator(1.0, dt);
  PidParameters p;
  p.proportional_gain = 1.0;
  Pid pid(p, dt);
  RateLimiter rate(1.0, dt);
  Fader fader(1.0, dt);
  EXPECT_NE(invalid_argument_message([&] { lag.step(kNan); }).find("FirstOrderLag: input"),
            std::string::npos);
  EXPECT_THROW(low.step(kInf), std::invalid_argument);
  EXPECT_THROW(integrator.step(kNan), std::invalid_argument);
  EXPECT_THROW(pid.step(-kInf), std::invalid_argument);
  EXPECT_THROW(rate.step(kNan), std::invalid_argument);
  EXPECT_THROW(fader.step(1, kNan), std::invalid_argument);
  EXPECT_THROW(lag.reset(kNan), std::invalid_argument);
  // The state survived the rejected inputs: the blocks still work.
  EXPECT_EQ(lag.step(0.0), 0.0);
  EXPECT_TRUE(std::isfinite(low.step(1.0)));
}

}  // namespace
}  // namespace fedsim::control
