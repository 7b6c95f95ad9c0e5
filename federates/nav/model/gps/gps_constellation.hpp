// GPS satellite positions from the nominal constellation (seed 6.11): circular Keplerian orbits
// (the SPS Performance Standard's slots, gps_constellation_data.hpp) with the earth's rotation.
//
//   u(t)     = u0 + n t,   n = sqrt(mu / a^3)               (argument of latitude)
//   RAAN(t)  = RAAN0 + RAAN_dot t                          (optional J2 nodal regression,
//              RAAN_dot = -3/2 n J2 (R_e / a)^2 cos i for a circular orbit: the secular J2
//              effect, Vallado, Fundamentals of Astrodynamics and Applications, section 9.6)
//   r_eci    = R3(-RAAN) R1(-i) [a cos u, a sin u, 0]
//   r_ecef   = R3(theta_G) r_eci,  theta_G(t) = theta_G0 + omega_e t  (Greenwich hour angle)
// t: seconds since the constellation epoch (0000Z 1 July 1993). mu, J2, R_e, omega_e: WGS-84
// (common/geodesy). Not modelled: eccentricity, other perturbations, the signal's travel time
// (positions are taken at the reception time) and the Sagnac effect; a receiver using the same
// positions sees a consistent geometry.
// Outputs: positions in ECI (x to the vernal equinox of the epoch) and ECEF, metres.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace fedsim::nav {

struct GpsOrbit {
  std::string slot;                       // e.g. "A1"
  double raan_at_epoch_rad = 0.0;
  double argument_of_latitude_at_epoch_rad = 0.0;
  double inclination_rad = 0.0;
  double semi_major_axis_m = 0.0;
};

class GpsConstellation {
 public:
  /// The 24 baseline slots of the SPS Performance Standard (2020, Table 3.2-1).
  static GpsConstellation baseline_24(bool j2_nodal_regression = true);

  /// Any set of circular orbits (checked: finite, a above the earth, 0 <= i <= pi).
  explicit GpsConstellation(std::vector<GpsOrbit> orbits, bool j2_nodal_regression = true);

  std::size_t size() const { return orbits_.size(); }
  const GpsOrbit& orbit(std::size_t index) const { return orbits_.at(index); }

  /// Position of a satellite at t seconds since the epoch, ECI and ECEF [m].
  Eigen::Vector3d position_eci_m(std::size_t index, double time_since_epoch_s) const;
  Eigen::Vector3d position_ecef_m(std::size_t index, double time_since_epoch_s) const;

  /// Keplerian period 2 pi sqrt(a^3 / mu) [s] (11 h 58 min for the baseline).
  double orbital_period_s(std::size_t index) const;
  /// The nodal regression rate applied to an orbit [rad/s] (0 when switched off).
  double raan_rate_radps(std::size_t index) const;
  /// Greenwich hour angle of the vernal equinox at t [rad].
  static double greenwich_hour_angle_rad(double time_since_epoch_s);

 private:
  std::vector<GpsOrbit> orbits_;
  bool j2_nodal_regression_;
};

/// Throws std::invalid_argument unless t is finite and within +-100 years of the epoch.
void check_gps_time(double time_since_epoch_s, const char* origin);

}  // namespace fedsim::nav
