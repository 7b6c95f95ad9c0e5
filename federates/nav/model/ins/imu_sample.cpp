// Checks and construction of IMU samples.
#include "federates/nav/model/ins/imu_sample.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

void check_vector(const Eigen::Vector3d& v, double limit, std::string_view origin,
                  std::string_view field) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i]) || std::abs(v[i]) > limit) {
      throw std::invalid_argument(std::string(origin) + ": " + std::string(field) + "[" +
                                  std::to_string(i) + "] = " + std::to_string(v[i]) +
                                  " is not finite or beyond +-" + std::to_string(limit));
    }
  }
}

}  // namespace

void check_imu_sample(const ImuSample& sample, std::string_view origin) {
  check_vector(sample.specific_force_body_mps2, kMaxSpecificForceMps2, origin,
               "specific_force_body_mps2");
  check_vector(sample.omega_body_radps, kMaxAngularRateRadps, origin, "omega_body_radps");
}

ImuSample imu_sample_at_cg(const Eigen::Vector3d& force_body_n, double mass_kg,
                           const Eigen::Vector3d& omega_body_radps) {
  if (!std::isfinite(mass_kg) || mass_kg <= 0.0) {
    throw std::invalid_argument("imu_sample_at_cg: mass_kg = " + std::to_string(mass_kg) +
                                " must be finite and positive");
  }
  if (!force_body_n.allFinite()) {
    throw std::invalid_argument("imu_sample_at_cg: force_body_n is not finite");
  }
  ImuSample sample{force_body_n / mass_kg, omega_body_radps};
  check_imu_sample(sample, "imu_sample_at_cg");
  return sample;
}

}  // namespace fedsim::nav
