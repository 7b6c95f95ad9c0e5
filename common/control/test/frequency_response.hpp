// Test support: measures a discrete block's frequency response by simulation, independently of
// its coefficients. The block is driven with u_n = sin(w n dt); after the transient has decayed
// (settle_s) the output of an LTI system is exactly A sin(w t) + B cos(w t) (+ a constant C for a
// block with a pole at z = 1, whose constant depends on the start), and a least-squares fit of
// A, B, C over a whole number of cycles gives H(e^{jw dt}) = A + jB.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <functional>

#include "common/units/units.hpp"

namespace fedsim::control::test {

using Complex = std::complex<double>;

/// The map of the bilinear transform with constant c [1/s]: the analogue frequency whose
/// continuous response the discrete block has at w: w_a = c tan(w dt/2) [rad/s].
inline double warped_frequency_radps(double omega_radps, double dt_s, double c_per_s) {
  return c_per_s * std::tan(0.5 * omega_radps * dt_s);
}
/// c = 2/T (plain Tustin) and c = w_p/tan(w_p T/2) (pre-warped at w_p), written out here
/// rather than taken from the library.
inline double plain_c(double dt_s) { return 2.0 / dt_s; }
inline double prewarped_c(double dt_s, double prewarp_radps) {
  return prewarp_radps / std::tan(0.5 * prewarp_radps * dt_s);
}

/// Solves the 3x3 normal equations M x = r by Cramer's rule (M symmetric positive definite).
inline std::array<double, 3> solve3(const std::array<std::array<double, 3>, 3>& m,
                                    const std::array<double, 3>& r) {
  const auto det = [](const std::array<std::array<double, 3>, 3>& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double d = det(m);
  std::array<double, 3> x{};
  for (int j = 0; j < 3; ++j) {
    auto mj = m;
    for (int i = 0; i < 3; ++i) mj[i][j] = r[i];
    x[j] = det(mj) / d;
  }
  return x;
}

/// H(e^{jw dt}) of `step` (one sample in, one out), measured at w = omega_radps.
inline Complex measure_response(const std::function<double(double)>& step, double omega_radps,
                                double dt_s, double settle_s, int cycles = 20) {
  const double period_s = units::kTwoPi / omega_radps;
  const long settle_steps = static_cast<long>(std::ceil(settle_s / dt_s));
  long fit_steps = static_cast<long>(std::lround(cycles * period_s / dt_s));
  if (fit_steps < 2000) fit_steps = 2000;
  for (long n = 0; n < settle_steps; ++n) step(std::sin(omega_radps * n * dt_s));
  std::array<std::array<double, 3>, 3> m{};
  std::array<double, 3> r{};
  for (long n = settle_steps; n < settle_steps + fit_steps; ++n) {
    const double phase = omega_radps * n * dt_s;
    const double y = step(std::sin(phase));
    const std::array<double, 3> basis{std::sin(phase), std::cos(phase), 1.0};
    for (int i = 0; i < 3; ++i) {
      r[i] += basis[i] * y;
      for (int j = 0; j < 3; ++j) m[i][j] += basis[i] * basis[j];
    }
  }
  const std::array<double, 3> x = solve3(m, r);
  return {x[0], x[1]};
}

/// |measured - expected| / |expected| (or the plain difference where |expected| < 1e-12).
inline double relative_error(Complex measured, Complex expected) {
  const double scale = std::abs(expected) < 1e-12 ? 1.0 : std::abs(expected);
  return std::abs(measured - expected) / scale;
}

}  // namespace fedsim::control::test
