// Helpers shared by the aircraft executive's tests: packs, standard trims, time histories and
// the identification of oscillatory modes from a response (Prony's method).
#pragma once

#include <Eigen/Dense>
#include "common/util/build_paths.hpp"
#include "common/units/units.hpp"
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/reposition.hpp"
#include "flight/model/scenario/trim.hpp"

namespace fedsim::flight::testing {

inline constexpr double kPi = units::kPi;
inline constexpr double kDeg = kPi / 180.0;
inline constexpr double kFt = units::kFtToM;
inline constexpr double kKt = units::kKtToMps;
inline constexpr double kG0 = units::kStandardGravityMps2;

inline AircraftPack load_pack(const std::string& name) {
  return load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/" + name);
}

inline std::unique_ptr<AircraftModel> make_model(const std::string& pack,
                                                 AircraftModel::Options options = {}) {
  return std::make_unique<AircraftModel>(load_pack(pack), options);
}

/// Cruise of each aircraft: the C172 at 4000 ft and 100 KTAS (about 65 % power, POH cruise
/// table), the 737 at FL300 and 440 KTAS (Mach 0.76), gear up.
inline TrimRequest cruise(const std::string& pack) {
  TrimRequest r;
  r.kind = TrimKind::kLevel;
  r.position = {28.0 * kDeg, -90.0 * kDeg, 4000.0 * kFt};
  r.heading_rad = 90.0 * kDeg;
  r.airspeed_mps = 100.0 * kKt;
  if (pack == "b737.yaml") {
    r.position.alt_m = 30000.0 * kFt;
    r.airspeed_mps = 440.0 * kKt;
    r.controls.gear_down = false;
  }
  return r;
}

/// One oscillatory (or real) mode found in a response.
struct Mode {
  std::complex<double> s;  ///< continuous-time root (1/s)
  double natural_frequency_radps() const { return std::abs(s); }
  double damping_ratio() const { return -s.real() / std::abs(s); }
  double damped_period_s() const { return 2.0 * kPi / std::abs(s.imag()); }
};

/// Prony's method (linear prediction, least squares): fits y[n] = sum_k a_k y[n-k] + c to
/// uniformly sampled data and returns the continuous-time roots s = ln(z) / dt of the
/// characteristic polynomial, oscillatory ones (Im s > 0) first, by decreasing frequency.
inline std::vector<Mode> prony_modes(const std::vector<double>& y, double dt_s, int order) {
  const int n = static_cast<int>(y.size());
  const int rows = n - order;
  Eigen::MatrixXd a(rows, order + 1);
  Eigen::VectorXd b(rows);
  for (int i = 0; i < rows; ++i) {
    for (int k = 0; k < order; ++k) a(i, k) = y[static_cast<std::size_t>(i + order - 1 - k)];
    a(i, order) = 1.0;  // the constant: a response about a shifted equilibrium
    b[i] = y[static_cast<std::size_t>(i + order)];
  }
  const Eigen::VectorXd coeff = a.colPivHouseholderQr().solve(b);
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(order, order);
  for (int k = 0; k < order; ++k) companion(0, k) = coeff[k];
  for (int k = 1; k < order; ++k) companion(k, k - 1) = 1.0;
  const Eigen::VectorXcd z = Eigen::EigenSolver<Eigen::MatrixXd>(companion).eigenvalues();
  std::vector<Mode> modes;
  for (int k = 0; k < order; ++k) {
    const std::complex<double> s = std::log(z[k]) / dt_s;
    if (s.imag() >= 0.0) modes.push_back({s});
  }
  std::sort(modes.begin(), modes.end(),
            [](const Mode& l, const Mode& r) { return l.s.imag() > r.s.imag(); });
  return modes;
}

/// Every `stride`th sample of `column` of a recorded history from sample `first` on, `count`
/// samples.
inline std::vector<double> decimate(const std::vector<double>& x, std::size_t first,
                                    std::size_t stride, std::size_t count) {
  std::vector<double> out;
  for (std::size_t i = first; i < x.size() && out.size() < count; i += stride) out.push_back(x[i]);
  return out;
}

}  // namespace fedsim::flight::testing
