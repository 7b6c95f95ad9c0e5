// Classical washout: the onset cue and washout of a sustained specific force, tilt
// coordination (and its negative control), the channels' frequency responses against the
// continuous transfer functions, reset, parameter and input validation.
#include "motion/model/classical_washout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "common/units/units.hpp"
#include "motion/model/test/sine_fit.hpp"

namespace fedsim::motion {
namespace {

using std::complex;
constexpr double kDt = 1.0 / 60.0;
constexpr double kG = 9.80665;

WashoutInput level_flight() { return WashoutInput{{0.0, 0.0, -kG}, Eigen::Vector3d::Zero()}; }

struct StepRun {
  double first_cue_mps2 = 0.0;  // delivered specific force x in the first frame
  double peak_surge_m = 0.0;
  double peak_time_s = 0.0;  // when |x| peaked
  double final_surge_m = 0.0;
  double final_pitch_rad = 0.0;
  double max_pitch_rate_radps = 0.0;
  double final_cue_x_mps2 = 0.0;
  double time_to_5pct_s = -1.0;  // after the peak, |x| stays below 5 % of the peak from then
};

StepRun run_surge_step(const ClassicalWashoutParameters& p, double a_mps2, double duration_s) {
  ClassicalWashout washout(p, kDt);
  washout.reset(level_flight());
  WashoutInput input = level_flight();
  input.specific_force_body_mps2.x() = a_mps2;
  StepRun run;
  double previous_pitch = 0.0;
  const int frames = static_cast<int>(duration_s / kDt);
  std::vector<double> surge;
  for (int n = 0; n < frames; ++n) {
    const WashoutOutput out = washout.step(input);
    if (n == 0) run.first_cue_mps2 = out.specific_force_cue_p_mps2.x();
    surge.push_back(out.pose.position_i_m.x());
    if (std::abs(out.pose.position_i_m.x()) > run.peak_surge_m) {
      run.peak_surge_m = std::abs(out.pose.position_i_m.x());
      run.peak_time_s = (n + 1) * kDt;
    }
    run.max_pitch_rate_radps = std::max(
        run.max_pitch_rate_radps, std::abs(out.pose.attitude.theta_rad - previous_pitch) / kDt);
    previous_pitch = out.pose.attitude.theta_rad;
    run.final_cue_x_mps2 = out.specific_force_cue_p_mps2.x();
  }
  run.final_surge_m = surge.back();
  run.final_pitch_rad = previous_pitch;
  for (int n = frames - 1; n >= 0; --n) {
    if (std::abs(surge[n]) > 0.05 * run.peak_surge_m) {
      run.time_to_5pct_s = (n + 1) * kDt;
      break;
    }
  }
  return run;
}

// What "washes out to neutral within the filter's time constant" can honestly mean for the surge
// chain x/a = K s / ((s^2 + 2 zeta wn s + wn^2)(s + wb)). Its slowest pole is the first-order
// washout's, tau_b = 1/wb (3.3 s as tuned); the second-order stage decays with tau_n, 1/(zeta wn)
// when not overdamped (0.5 s). After its peak the displacement is governed by tau_b, and a
// first-order decay still holds 37 % after one time constant: reaching 5 % of the peak takes
// ln(1/0.05) = 3.0 tau_b for that pole alone. So the "within the time constant" is read
// as "within N time constants of the slowest pole", N from the poles: ln 20 + 2 tau_n / tau_b.
// The second term: the second-order stage holds the response above the slow pole's asymptote a
// little longer, about 1.5 tau_n (1.3 to 1.7 tau_n for wn 1..4 rad/s, wb 0.1..0.5 rad/s, with
// and without tilt, in a continuous-time simulation of the chain); 2 tau_n is allowed. Counted
// from the peak, not the step: the peak comes only once the input stops changing (with tilt
// coordination the cab tilts in at its rate limit for asin(a/g)/rate, and the gravity it tilts
// into is an input to this chain), which is the tilt's time, not the filter's.
double slowest_second_order_decay_radps(double natural_frequency_radps, double damping_ratio) {
  if (damping_ratio <= 1.0) return damping_ratio * natural_frequency_radps;
  return natural_frequency_radps * (damping_ratio - std::sqrt(damping_ratio * damping_ratio - 1.0));
}

struct WashoutBound {
  double tau_b_s = 0.0;  // the washout's time constant 1/wb [s]
  double tau_n_s = 0.0;  // the second-order stage's slowest decay [s]
  double time_constants() const { return std::log(1.0 / 0.05) + 2.0 * tau_n_s / tau_b_s; }
  double after_peak_s() const { return time_constants() * tau_b_s; }
};

WashoutBound surge_washout_bound(const ClassicalWashoutParameters& p) {
  const TranslationalChannelParameters& x = p.translational[0];
  return {1.0 / x.break_frequency_radps,
          1.0 / slowest_second_order_decay_radps(x.natural_frequency_radps, x.damping_ratio)};
}

void expect_washout_within_bound(const ClassicalWashoutParameters& p, const StepRun& run,
                                 const char* label) {
  const WashoutBound bound = surge_washout_bound(p);
  const double after_peak_s = run.time_to_5pct_s - run.peak_time_s;
  EXPECT_GT(run.time_to_5pct_s, 0.0) << label;  // it did go out and come back
  EXPECT_LE(after_peak_s, bound.after_peak_s()) << label;
  std::printf(
      "[figure] %s: peak %.3f m at %.2f s, |x| < 5%% of peak from %.2f s: %.2f s after the peak "
      "= %.2f tau_b (tau_b %.2f s, tau_n %.2f s); bound N = ln 20 + 2 tau_n/tau_b = %.2f tau_b "
      "= %.2f s\n",
      label, run.peak_surge_m, run.peak_time_s, run.time_to_5pct_s, after_peak_s,
      after_peak_s / bound.tau_b_s, bound.tau_b_s, bound.tau_n_s, bound.time_constants(),
      bound.after_peak_s());
}

TEST(ClassicalWashout, SustainedSurgeGivesOnsetCueWashoutAndTiltAtTheRateLimit) {
  const ClassicalWashoutParameters p;
  const double a = 2.0;
  const StepRun run = run_surge_step(p, a, 90.0);
  // Onset: the first frame delivers the scaled step (the bilinear high-passes pass 96.5 % of a
  // step in its first sample at 60 Hz).
  EXPECT_GT(run.first_cue_mps2, 0.95 * p.translational[0].gain * a);
  EXPECT_GT(run.peak_surge_m, 0.05);
  // Washout: back to neutral (third-order high-pass: no residual displacement), within the
  // time constants of the chain's slowest pole (surge_washout_bound above).
  EXPECT_LT(std::abs(run.final_surge_m), 1e-4);
  expect_washout_within_bound(p, run, "2 m/s^2 surge step with tilt");
  // Tilt coordination: the cab settles at asin(a/g) and never tilts faster than 3 deg/s.
  EXPECT_NEAR(run.final_pitch_rad, std::asin(p.tilt.gain * a / kG), 1e-6);
  EXPECT_LE(run.max_pitch_rate_radps, p.tilt.rate_limit_radps * (1.0 + 1e-9));
  EXPECT_GT(run.max_pitch_rate_radps, 0.99 * p.tilt.rate_limit_radps);  // the limit acted
  // The sustained cue is delivered by gravity: g sin(theta) = a.
  EXPECT_NEAR(run.final_cue_x_mps2, a, 1e-5);
  std::printf(
      "[figure] 2 m/s^2 surge step: first-frame cue %.3f m/s^2, peak surge %.3f m, "
      "|x| < 5%% of peak after %.1f s, tilt %.3f deg at <= %.3f deg/s\n",
      run.first_cue_mps2, run.peak_surge_m, run.time_to_5pct_s,
      run.final_pitch_rad / units::kDegToRad, run.max_pitch_rate_radps / units::kDegToRad);
}

TEST(ClassicalWashout, WithoutTiltCoordinationNoSustainedTiltOrCue) {
  ClassicalWashoutParameters p;
  p.tilt.enabled = false;
  const StepRun run = run_surge_step(p, 2.0, 90.0);
  EXPECT_EQ(run.final_pitch_rad, 0.0);
  EXPECT_LT(std::abs(run.final_surge_m), 1e-4);
  EXPECT_NEAR(run.final_cue_x_mps2, 0.0, 1e-4);  // the onset only: the cue washes out
  EXPECT_GT(run.first_cue_mps2, 0.95 * p.translational[0].gain * 2.0);
  // The bare chain (no tilt feeding it): the same bound holds.
  expect_washout_within_bound(p, run, "2 m/s^2 surge step without tilt");
}

TEST(ClassicalWashout, SustainedLateralForceRollsTheCabTheRightWay) {
  const ClassicalWashoutParameters p;
  ClassicalWashout washout(p, kDt);
  WashoutInput input = level_flight();
  input.specific_force_body_mps2.y() = 1.5;  // pushed to the right (accelerating right)
  WashoutOutput out;
  for (int n = 0; n < 90 * 60; ++n) out = washout.step(input);
  // At rest with roll phi the specific force is -g sin(phi) along y: phi = -asin(1.5/g).
  EXPECT_NEAR(out.pose.attitude.phi_rad, -std::asin(1.5 / kG), 1e-6);
  EXPECT_NEAR(out.specific_force_cue_p_mps2.y(), 1.5, 1e-5);
  EXPECT_LT(out.pose.position_i_m.norm(), 1e-4);
}

TEST(ClassicalWashout, TiltIsClampedToItsAngleLimit) {
  const ClassicalWashoutParameters p;
  ClassicalWashout washout(p, kDt);
  WashoutInput input = level_flight();
  input.specific_force_body_mps2.x() = 6.0;  // asin(6/g) = 37.7 deg > 20 deg
  WashoutOutput out;
  for (int n = 0; n < 60 * 60; ++n) out = washout.step(input);
  EXPECT_NEAR(out.tilt_pitch_rad, p.tilt.angle_limit_rad, 1e-9);
}

// Continuous transfer functions of the channels.
complex<double> translational_displacement_per_force(const TranslationalChannelParameters& t,
                                                     double w) {
  const complex<double> s(0.0, w);
  const double wn = t.natural_frequency_radps;
  return t.gain * s /
         ((s * s + 2.0 * t.damping_ratio * wn * s + wn * wn) * (s + t.break_frequency_radps));
}

complex<double> rotational_angle_per_rate(const RotationalChannelParameters& r, double w) {
  const complex<double> s(0.0, w);
  const double wn = r.natural_frequency_radps;
  return r.gain * s / (s * s + 2.0 * r.damping_ratio * wn * s + wn * wn);
}

enum class Channel { kSurge, kHeave, kPitch, kYaw };

// The measured response of one channel to a sine of frequency w (after 12 s + 8 periods of
// transient, fitted over 10 periods).
complex<double> measured_response(const ClassicalWashoutParameters& p, Channel channel, double w,
                                  double amplitude) {
  ClassicalWashout washout(p, kDt);
  const double period_s = 2.0 * units::kPi / w;
  const int settle = static_cast<int>((12.0 + 8.0 * period_s) / kDt);
  const int fit = static_cast<int>(10.0 * period_s / kDt);
  std::vector<double> t;
  std::vector<double> y;
  for (int n = 1; n <= settle + fit; ++n) {
    const double time_s = n * kDt;
    const double u = amplitude * std::sin(w * time_s);
    WashoutInput input = level_flight();
    if (channel == Channel::kSurge) input.specific_force_body_mps2.x() = u;
    if (channel == Channel::kHeave) input.specific_force_body_mps2.z() = -kG + u;
    if (channel == Channel::kPitch) input.omega_body_radps.y() = u;
    if (channel == Channel::kYaw) input.omega_body_radps.z() = u;
    const WashoutOutput out = washout.step(input);
    if (n <= settle) continue;
    t.push_back(time_s);
    if (channel == Channel::kSurge) y.push_back(out.pose.position_i_m.x());
    if (channel == Channel::kHeave) y.push_back(out.pose.position_i_m.z());
    if (channel == Channel::kPitch) y.push_back(out.pose.attitude.theta_rad);
    if (channel == Channel::kYaw) y.push_back(out.pose.attitude.psi_rad);
  }
  return test::fit_sine(t, y, w) / amplitude;
}

// Against the continuous response: the bilinear blocks' frequency warping, at most
// (w dt)^2/12 for each of the two trapezoidal integrators (common/control/README.md), plus the
// fit's 1e-3.
void expect_response(complex<double> measured, complex<double> expected, double w,
                     const char* what) {
  const double warping = (w * kDt) * (w * kDt) / 6.0;
  EXPECT_NEAR(std::abs(measured) / std::abs(expected), 1.0, 1e-3 + warping) << what << " " << w;
  EXPECT_NEAR(std::arg(measured / expected), 0.0, 1e-3 + warping) << what << " " << w;
}

TEST(ClassicalWashout, TranslationalChannelsMatchTheirTransferFunctions) {
  ClassicalWashoutParameters p;
  p.tilt.enabled = false;  // the pure high-pass chain
  for (int axis : {0, 2}) {
    const TranslationalChannelParameters& t = p.translational[axis];
    const Channel channel = axis == 0 ? Channel::kSurge : Channel::kHeave;
    for (double w : {t.break_frequency_radps, 0.5 * t.natural_frequency_radps,
                     t.natural_frequency_radps, 3.0 * t.natural_frequency_radps}) {
      const complex<double> measured = measured_response(p, channel, w, 0.5);
      const complex<double> expected = translational_displacement_per_force(t, w);
      expect_response(measured, expected, w, axis == 0 ? "surge" : "heave");
      std::printf(
          "[figure] %s at %.2f rad/s: |x/f| %.5f s^2 (analytic %.5f), phase %.2f deg "
          "(%.2f)\n",
          axis == 0 ? "surge" : "heave", w, std::abs(measured), std::abs(expected),
          std::arg(measured) / units::kDegToRad, std::arg(expected) / units::kDegToRad);
      // Negative control: the response tells a 20 % different break frequency apart.
      TranslationalChannelParameters other = t;
      other.natural_frequency_radps *= 1.2;
      EXPECT_GT(std::abs(measured - translational_displacement_per_force(other, w)),
                0.03 * std::abs(measured));
    }
  }
}

TEST(ClassicalWashout, RotationalChannelsMatchTheirTransferFunctions) {
  const ClassicalWashoutParameters p;
  for (int axis : {1, 2}) {
    const RotationalChannelParameters& r = p.rotational[axis];
    const Channel channel = axis == 1 ? Channel::kPitch : Channel::kYaw;
    for (double w : {0.3 * r.natural_frequency_radps, r.natural_frequency_radps,
                     4.0 * r.natural_frequency_radps}) {
      const complex<double> measured = measured_response(p, channel, w, 0.02);
      expect_response(measured, rotational_angle_per_rate(r, w), w, axis == 1 ? "pitch" : "yaw");
    }
    // At wn the angle lags the rate by 0 deg and has gain K/(2 zeta wn).
    const complex<double> at_wn = measured_response(p, channel, r.natural_frequency_radps, 0.02);
    EXPECT_NEAR(std::abs(at_wn), r.gain / (2.0 * r.damping_ratio * r.natural_frequency_radps),
                5e-3 * std::abs(at_wn));
  }
}

TEST(ClassicalWashout, TiltLowPassBreakFrequency) {
  // Small sustained-force sine below the rate limit: theta_tilt = LP(f)/g; at wn the low-pass
  // gives 1/(2 zeta) and -90 deg.
  const ClassicalWashoutParameters p;
  const double w = p.tilt.natural_frequency_radps;
  ClassicalWashout washout(p, kDt);
  std::vector<double> t;
  std::vector<double> y;
  const double amplitude = 0.2;
  for (int n = 1; n <= 60 * 60; ++n) {
    WashoutInput input = level_flight();
    input.specific_force_body_mps2.x() = amplitude * std::sin(w * n * kDt);
    const WashoutOutput out = washout.step(input);
    EXPECT_FALSE(out.tilt_rate_limited);
    if (n < 20 * 60) continue;
    t.push_back(n * kDt);
    y.push_back(out.tilt_pitch_rad);
  }
  const complex<double> response = test::fit_sine(t, y, w) * kG / amplitude;
  EXPECT_NEAR(std::abs(response), 1.0 / (2.0 * p.tilt.damping_ratio), 2e-3);
  EXPECT_NEAR(std::arg(response), -0.5 * units::kPi, 0.2 * units::kDegToRad);
}

TEST(ClassicalWashout, ResetUnderAHeldInputGivesNoTransient) {
  const ClassicalWashoutParameters p;
  ClassicalWashout washout(p, kDt);
  WashoutInput held = level_flight();
  held.specific_force_body_mps2.z() = -1.3 * kG;  // a steady turn
  held.omega_body_radps = {0.0, 0.05, 0.1};
  washout.reset(held);
  for (int n = 0; n < 600; ++n) {
    const WashoutOutput out = washout.step(held);
    EXPECT_EQ(out.pose.position_i_m.norm(), 0.0);
    EXPECT_LT(std::abs(out.pose.attitude.theta_rad), 1e-12);
    EXPECT_LT(std::abs(out.pose.attitude.psi_rad), 1e-12);
  }
}

TEST(ClassicalWashout, RejectsBadParametersNamingTheField) {
  auto message_of = [](const ClassicalWashoutParameters& p) -> std::string {
    try {
      ClassicalWashout washout(p, kDt);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  ClassicalWashoutParameters p;
  p.translational[2].damping_ratio = 0.0;
  EXPECT_NE(message_of(p).find("translational[2].damping_ratio"), std::string::npos);
  p = {};
  p.rotational[0].gain = 1.5;
  EXPECT_NE(message_of(p).find("rotational[0].gain"), std::string::npos);
  p = {};
  p.translational[0].natural_frequency_radps = 200.0;  // above Nyquist at 60 Hz
  EXPECT_NE(message_of(p).find("translational[0].natural_frequency_radps"), std::string::npos);
  p = {};
  p.tilt.rate_limit_radps = std::nan("");
  EXPECT_NE(message_of(p).find("tilt.rate_limit_radps"), std::string::npos);
  p = {};
  p.tilt.angle_limit_rad = -0.1;
  EXPECT_NE(message_of(p).find("tilt.angle_limit_rad"), std::string::npos);
  p = {};
  EXPECT_THROW(ClassicalWashout(p, 0.0), std::invalid_argument);
  EXPECT_EQ(message_of(ClassicalWashoutParameters{}), "");
}

TEST(ClassicalWashout, RejectsNonFiniteInputLeavingTheStateUntouched) {
  ClassicalWashout washout(ClassicalWashoutParameters{}, kDt);
  WashoutInput input = level_flight();
  input.specific_force_body_mps2.x() = 1.0;
  washout.step(input);
  const WashoutOutput before = washout.output();
  WashoutInput bad = input;
  bad.omega_body_radps.x() = std::nan("");
  EXPECT_THROW(washout.step(bad), std::invalid_argument);
  EXPECT_EQ(washout.output().pose.position_i_m, before.pose.position_i_m);
  ClassicalWashout twin(ClassicalWashoutParameters{}, kDt);
  twin.step(input);
  EXPECT_EQ(washout.step(input).pose.position_i_m, twin.step(input).pose.position_i_m);
}

}  // namespace
}  // namespace fedsim::motion
