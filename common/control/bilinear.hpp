// The bilinear (Tustin) transform: the one place fedsim turns a continuous transfer function into
// a discrete one. Every linear block of this library (lag, lead-lag, washout, second-order
// filters, the integrator, the PID's derivative roll-off) calls bilinear() below; none repeats
// the algebra.
//
// Tustin's rule substitutes  s = c (z - 1)/(z + 1) = c (1 - z^-1)/(1 + z^-1)  in H(s)
// (Franklin, Powell & Workman, Digital Control of Dynamic Systems, 3rd ed., section 6.3.2; the
// transfer-function simulation of Allerton, Principles of Flight Simulation, section 4.2).
//   - c = 2/T (tustin_constant_per_s) is the trapezoidal rule: the discrete response at a
//     frequency w is the continuous one at the warped frequency w_a = (2/T) tan(w T/2).
//   - c = w_p / tan(w_p T/2) (prewarped_tustin_constant_per_s) pre-warps: the discrete response
//     equals the continuous one exactly at w = w_p, and at any w it is H(j c tan(w T/2)).
// Both maps take s = 0 to z = 1, so the DC gain is kept exactly, and map the left half plane
// into the unit circle, so a stable H(s) gives a stable H(z).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace fedsim::control {

/// H(s) = (n0 + n1 s + ... + nN s^N) / (d0 + d1 s + ... + dN s^N): coefficients in ascending
/// powers of s (a lower order is written with zero leading coefficients).
template <std::size_t N>
struct ContinuousTransferFunction {
  std::array<double, N + 1> numerator{};    // n_k multiplies s^k
  std::array<double, N + 1> denominator{};  // d_k multiplies s^k
};

/// H(z) = (b0 + b1 z^-1 + ... + bN z^-N) / (1 + a1 z^-1 + ... + aN z^-N); a[0] is 1.
template <std::size_t N>
struct DiscreteTransferFunction {
  std::array<double, N + 1> b{};
  std::array<double, N + 1> a{};
};

/// c = 2/T [1/s]: the plain trapezoidal rule. T = dt_s must be > 0 (checked).
double tustin_constant_per_s(double dt_s);

/// c = w_p / tan(w_p T/2) [1/s]: the constant that makes the discrete response exact at w_p.
/// 0 < prewarp_radps < pi/dt_s (checked: at Nyquist the map has no finite constant).
double prewarped_tustin_constant_per_s(double dt_s, double prewarp_radps);

namespace detail {

/// Coefficients of (1 - q)^k (1 + q)^(N - k) in ascending powers of q = z^-1.
template <std::size_t N>
std::array<double, N + 1> bilinear_basis(std::size_t k) {
  std::array<double, N + 1> p{};
  p[0] = 1.0;
  for (std::size_t factor = 0; factor < N; ++factor) {
    const double sign = factor < k ? -1.0 : 1.0;  // multiply by (1 - q) or (1 + q)
    for (std::size_t i = N; i > 0; --i) p[i] += sign * p[i - 1];
  }
  return p;
}

}  // namespace detail

/// The bilinear transform of h with the constant c (tustin_constant_per_s or
/// prewarped_tustin_constant_per_s). Multiplying numerator and denominator by (1 + z^-1)^N,
///   sum_k h_k s^k  ->  sum_k h_k c^k (1 - z^-1)^k (1 + z^-1)^(N-k);
/// the result is divided by its z^0 denominator coefficient, D(c) = sum_k d_k c^k, which must
/// not vanish (it does not for a denominator with coefficients of one sign).
template <std::size_t N>
DiscreteTransferFunction<N> bilinear(const ContinuousTransferFunction<N>& h, double c) {
  DiscreteTransferFunction<N> d;
  double c_power = 1.0;
  for (std::size_t k = 0; k <= N; ++k) {
    const std::array<double, N + 1> basis = detail::bilinear_basis<N>(k);
    for (std::size_t i = 0; i <= N; ++i) {
      d.b[i] += h.numerator[k] * c_power * basis[i];
      d.a[i] += h.denominator[k] * c_power * basis[i];
    }
    c_power *= c;
  }
  const double a0 = d.a[0];
  if (a0 == 0.0 || !std::isfinite(a0)) {
    throw std::invalid_argument("bilinear: the denominator vanishes at s = c (no proper H(z))");
  }
  for (std::size_t i = 0; i <= N; ++i) {
    d.b[i] /= a0;
    d.a[i] /= a0;
  }
  return d;
}

}  // namespace fedsim::control
