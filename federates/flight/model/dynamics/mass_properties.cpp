// Mass and inertia tensor validation.
#include "flight/model/dynamics/mass_properties.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

namespace fedsim::flight {

MassProperties MassProperties::from_moments(double mass_kg, double ixx_kgm2, double iyy_kgm2,
                                            double izz_kgm2, double ixz_kgm2, double ixy_kgm2,
                                            double iyz_kgm2) {
  MassProperties mass;
  mass.mass_kg = mass_kg;
  mass.inertia_kgm2 << ixx_kgm2, -ixy_kgm2, -ixz_kgm2,  //
      -ixy_kgm2, iyy_kgm2, -iyz_kgm2,                    //
      -ixz_kgm2, -iyz_kgm2, izz_kgm2;
  return mass;
}

void MassProperties::validate() const {
  if (!(mass_kg > 0.0) || !std::isfinite(mass_kg)) {
    throw std::invalid_argument("mass properties: mass must be positive and finite");
  }
  if (!inertia_kgm2.allFinite() || !inertia_kgm2.isApprox(inertia_kgm2.transpose(), 1e-12)) {
    throw std::invalid_argument("mass properties: inertia tensor must be finite and symmetric");
  }
  // Principal moments of any real body are positive and each is at most the sum of the others.
  const Eigen::Vector3d principal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia_kgm2, Eigen::EigenvaluesOnly)
          .eigenvalues();
  const double slack = 1e-9 * principal.sum();
  if (!(principal.minCoeff() > 0.0) || principal.maxCoeff() > principal.sum() - principal.maxCoeff() + slack) {
    throw std::invalid_argument(
        "mass properties: inertia tensor is not that of a physical body (principal moments must "
        "be positive and obey the triangle inequality)");
  }
}

}  // namespace fedsim::flight
