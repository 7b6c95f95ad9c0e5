// Least-squares fit of y(t) ~ a sin(w t) + b cos(w t) + c over samples, for frequency responses
// measured by simulation: gain = |(a, b)| / input amplitude, phase = atan2(b, a).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <vector>

namespace fedsim::motion::test {

inline std::complex<double> fit_sine(const std::vector<double>& t_s, const std::vector<double>& y,
                                     double w_radps) {
  Eigen::MatrixXd a(static_cast<Eigen::Index>(y.size()), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(y.size()));
  for (std::size_t i = 0; i < y.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    a(row, 0) = std::sin(w_radps * t_s[i]);
    a(row, 1) = std::cos(w_radps * t_s[i]);
    a(row, 2) = 1.0;
    b(row) = y[i];
  }
  const Eigen::Vector3d x = a.colPivHouseholderQr().solve(b);
  // a sin + b cos = Im{(a + j b) e^{j w t}}: the phasor relative to sin(w t).
  return {x(0), x(1)};
}

}  // namespace fedsim::motion::test
