// Cubic spline: tridiagonal solve for the knot curvatures, then cubic evaluation per segment.
#include "common/math/cubic_spline.hpp"

#include <stdexcept>
#include <string>

#include "common/math/interpolation.hpp"

namespace fedsim {

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y, SplineEnd start,
                         SplineEnd end)
    : x_(std::move(x)), y_(std::move(y)) {
  check_breakpoints(x_, "cubic spline");
  if (x_.size() < 2) throw std::invalid_argument("cubic spline: needs at least two points");
  if (y_.size() != x_.size()) {
    throw std::invalid_argument("cubic spline: " + std::to_string(x_.size()) + " x but " +
                                std::to_string(y_.size()) + " y values");
  }
  solve(start, end);
}

void CubicSpline::solve(SplineEnd start, SplineEnd end) {
  // Continuity of slope at each interior knot gives a tridiagonal system in the second
  // derivatives y2; it is solved by forward elimination (u) and back substitution.
  const std::size_t n = x_.size();
  y2_.assign(n, 0.0);
  std::vector<double> u(n, 0.0);
  const auto chord = [&](std::size_t i) { return (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]); };
  const auto end_slope = [&](SplineEnd e, std::size_t segment) {
    return e.kind == SplineEnd::Kind::kChordSlope ? chord(segment) : e.slope;
  };
  if (start.kind != SplineEnd::Kind::kNatural) {
    y2_[0] = -0.5;
    u[0] = 3.0 / (x_[1] - x_[0]) * (chord(0) - end_slope(start, 0));
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double sig = (x_[i] - x_[i - 1]) / (x_[i + 1] - x_[i - 1]);
    const double p = sig * y2_[i - 1] + 2.0;
    y2_[i] = (sig - 1.0) / p;
    u[i] = (6.0 * (chord(i) - chord(i - 1)) / (x_[i + 1] - x_[i - 1]) - sig * u[i - 1]) / p;
  }
  double qn = 0.0;
  double un = 0.0;
  if (end.kind != SplineEnd::Kind::kNatural) {
    qn = 0.5;
    un = 3.0 / (x_[n - 1] - x_[n - 2]) * (end_slope(end, n - 2) - chord(n - 2));
  }
  y2_[n - 1] = (un - qn * u[n - 2]) / (qn * y2_[n - 2] + 1.0);
  for (std::size_t k = n - 1; k-- > 0;) y2_[k] = y2_[k] * y2_[k + 1] + u[k];
}

double CubicSpline::operator()(double x) const {
  const Bracket b = find_bracket(x_, x);
  const std::size_t i = b.index;
  const double h = x_[i + 1] - x_[i];
  const double bb = b.fraction;
  const double a = 1.0 - bb;
  return a * y_[i] + bb * y_[i + 1] +
         ((a * a * a - a) * y2_[i] + (bb * bb * bb - bb) * y2_[i + 1]) * h * h / 6.0;
}

double CubicSpline::derivative(double x) const {
  if (!(x >= x_.front() && x <= x_.back())) return 0.0;  // outside (or NaN): value is clamped
  const Bracket b = find_bracket(x_, x);
  const std::size_t i = b.index;
  const double h = x_[i + 1] - x_[i];
  const double bb = b.fraction;
  const double a = 1.0 - bb;
  return (y_[i + 1] - y_[i]) / h +
         (-(3.0 * a * a - 1.0) * y2_[i] + (3.0 * bb * bb - 1.0) * y2_[i + 1]) * h / 6.0;
}

std::vector<double> CubicSpline::tabulate(double x0, double dx, std::size_t n) const {
  std::vector<double> values(n);
  for (std::size_t k = 0; k < n; ++k) values[k] = (*this)(x0 + dx * static_cast<double>(k));
  return values;
}

}  // namespace fedsim
