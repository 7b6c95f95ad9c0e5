// Cubic spline through sparse data points (seed 2.8; algorithm of Press et al., Numerical Recipes).
// Built offline (tools/spline) or at pack load; evaluation does not allocate.
#pragma once

#include <cstddef>
#include <vector>

namespace fedsim {

/// Boundary condition at one end of the spline.
struct SplineEnd {
  enum class Kind {
    kNatural,     // second derivative zero (the "natural" spline of seed 2.8)
    kSlope,       // first derivative given (clamped spline)
    kChordSlope,  // first derivative equal to the slope of the end segment
  };
  Kind kind = Kind::kNatural;
  double slope = 0.0;  // used by kSlope only

  static SplineEnd natural() { return {Kind::kNatural, 0.0}; }
  static SplineEnd clamped(double slope) { return {Kind::kSlope, slope}; }
  static SplineEnd chord() { return {Kind::kChordSlope, 0.0}; }
};

/// Piecewise cubic through every point, continuous in value, slope and curvature.
class CubicSpline {
 public:
  /// Needs at least two points with strictly increasing, finite x; throws std::invalid_argument.
  CubicSpline(std::vector<double> x, std::vector<double> y, SplineEnd start = SplineEnd::natural(),
              SplineEnd end = SplineEnd::natural());

  /// Spline value; x outside the data range is clamped to the end points (no extrapolation).
  double operator()(double x) const;
  /// First derivative dy/dx (zero outside the data range, consistent with the clamping).
  double derivative(double x) const;
  /// Values at x0, x0 + dx, ..., n values (allocates: an offline helper).
  std::vector<double> tabulate(double x0, double dx, std::size_t n) const;

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  /// Second derivatives at the knots (the solution of the tridiagonal system).
  const std::vector<double>& second_derivatives() const { return y2_; }

 private:
  void solve(SplineEnd start, SplineEnd end);

  std::vector<double> x_;
  std::vector<double> y_;
  std::vector<double> y2_;
};

}  // namespace fedsim
