// Microburst wind shear: the Oseguera-Bowles analytic downburst model (NASA TM-100632).
#include "flight/model/weather/wind_shear.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::flight {

namespace {
// x = r / R where (1 - exp(-x^2)) / x peaks: the root of (2 x^2 + 1) exp(-x^2) = 1.
constexpr double kPeakRadiusRatio = 1.1209;

[[noreturn]] void fail(const std::string& field, const std::string& rule, double value) {
  throw std::invalid_argument("wind shear: " + field + " " + rule + " (got " +
                              std::to_string(value) + ")");
}

// (1 - exp(-x^2)) / x, the radial shape of the outflow; x / 1 near the axis.
double radial_shape(double x) {
  if (x < 1e-4) return x;  // series: x - x^3 / 2 + ...
  return -std::expm1(-x * x) / x;
}

double peak_radius_ratio() {
  // Newton on f(x) = (2x^2 + 1) e^{-x^2} - 1 from the tabulated value.
  double x = kPeakRadiusRatio;
  for (int i = 0; i < 20; ++i) {
    const double e = std::exp(-x * x);
    const double f = (2.0 * x * x + 1.0) * e - 1.0;
    const double df = 4.0 * x * e - 2.0 * x * (2.0 * x * x + 1.0) * e;
    x -= f / df;
  }
  return x;
}
}  // namespace

void WindShear::Params::validate() const {
  if (!std::isfinite(centre_north_m)) fail("centre_north_m", "must be finite", centre_north_m);
  if (!std::isfinite(centre_east_m)) fail("centre_east_m", "must be finite", centre_east_m);
  if (!(downdraft_radius_m > 0.0) || !std::isfinite(downdraft_radius_m)) {
    fail("downdraft_radius_m", "must be positive", downdraft_radius_m);
  }
  if (!(max_outflow_mps >= 0.0) || !std::isfinite(max_outflow_mps)) {
    fail("max_outflow_mps", "must be >= 0", max_outflow_mps);
  }
  if (!(boundary_layer_height_scale_m > 0.0)) {
    fail("boundary_layer_height_scale_m", "must be positive", boundary_layer_height_scale_m);
  }
  if (!(outflow_height_scale_m > boundary_layer_height_scale_m) ||
      !std::isfinite(outflow_height_scale_m)) {
    fail("outflow_height_scale_m", "must exceed boundary_layer_height_scale_m",
         outflow_height_scale_m);
  }
}

WindShear::WindShear(Params params) : params_(params) {
  params_.validate();
  const double zs = params_.outflow_height_scale_m;
  const double eps = params_.boundary_layer_height_scale_m;
  peak_height_m_ = std::log(zs / eps) * zs * eps / (zs - eps);
  const double r = params_.downdraft_radius_m;
  // u_max = lambda R / 2 * shape(x_peak) * profile(z_m)
  lambda_per_s_ = 2.0 * params_.max_outflow_mps /
                  (r * radial_shape(peak_radius_ratio()) * vertical_profile(peak_height_m_));
}

double WindShear::peak_outflow_radius_m() const {
  return peak_radius_ratio() * params_.downdraft_radius_m;
}

double WindShear::core_downdraft_mps() const {
  return lambda_per_s_ * (params_.outflow_height_scale_m - params_.boundary_layer_height_scale_m);
}

double WindShear::vertical_profile(double height_m) const {
  return std::exp(-height_m / params_.outflow_height_scale_m) -
         std::exp(-height_m / params_.boundary_layer_height_scale_m);
}

Eigen::Vector3d WindShear::wind_ned_mps(double north_m, double east_m, double height_agl_m) const {
  if (lambda_per_s_ == 0.0 || !(height_agl_m > 0.0)) return Eigen::Vector3d::Zero();
  const double zs = params_.outflow_height_scale_m;
  const double eps = params_.boundary_layer_height_scale_m;
  const double big_r = params_.downdraft_radius_m;
  const double dn = north_m - params_.centre_north_m;
  const double de = east_m - params_.centre_east_m;
  const double r = std::hypot(dn, de);
  if (!std::isfinite(r)) return Eigen::Vector3d::Zero();
  const double x = r / big_r;

  // u / r = lambda R / (2 r) * shape(x): divide the shape by x to get the per-metre factor
  // that turns the offset (dn, de) into the radial velocity components.
  const double z = height_agl_m;
  const double outward_per_m =
      x > 1e-4 ? 0.5 * lambda_per_s_ * big_r * radial_shape(x) / r : 0.5 * lambda_per_s_;
  const double horizontal_factor = outward_per_m * vertical_profile(z);
  const double w_up =
      -lambda_per_s_ * std::exp(-x * x) * (eps * std::expm1(-z / eps) - zs * std::expm1(-z / zs));
  return {horizontal_factor * dn, horizontal_factor * de, -w_up};
}

}  // namespace fedsim::flight
