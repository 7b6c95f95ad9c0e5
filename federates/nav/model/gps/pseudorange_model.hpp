// Pseudoranges a receiver measures (seed 6.11):
//   rho_k = |r_sat,k - r_rx| + c dt_rx + T_k + I_k + w_k
// geometric range (satellite at the reception time, no light-time or Sagnac term), receiver
// clock bias dt_rx [s] times c, and optionally
//   T_k = T_zenith m(E),  m(E) = 1.001 / sqrt(0.002001 + sin^2 E)
//         (troposphere: RTCA DO-229 Appendix A mapping function; T_zenith ~ 2.4 m at sea level),
//   I_k = I_zenith F(E), F = 1 + 16 (0.53 - E)^3, E in semicircles
//         (ionosphere: the obliquity factor of the IS-GPS-200 single-frequency model,
//         section 20.3.3.5.2.5; I_zenith ~ 1-10 m at L1 by day),
// both uncorrected biases (the receiver does not model them), and white noise
// w_k ~ N(0, sigma^2) (the user-equivalent range error: satellite clock and ephemeris,
// residual atmosphere, multipath, receiver noise) from std::mt19937_64 with an explicit seed.
// Satellite clock errors and the ephemeris are taken as perfect (broadcast = truth).
// Visibility: a satellite is used if its elevation is at or above the mask angle.
#pragma once

#include "federates/nav/model/gps/gps_constellation.hpp"
#include "federates/nav/model/gps/satellite_geometry.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

namespace fedsim::nav {

struct PseudorangeConfig {
  double mask_angle_rad = kDefaultMaskAngleRad;   // [0, pi/2)
  double noise_sigma_m = 2.0;                     // 1-sigma UERE, [0, 1000] m
  double troposphere_zenith_delay_m = 0.0;        // 0 = off, [0, 10] m
  double ionosphere_zenith_delay_m = 0.0;         // 0 = off, [0, 100] m
  std::uint64_t seed = 1;

  /// Throws std::invalid_argument for a value out of range or not finite.
  void check() const;
};

struct Pseudorange {
  std::size_t satellite = 0;                                   // index in the constellation
  Eigen::Vector3d satellite_ecef_m = Eigen::Vector3d::Zero();  // broadcast position
  double pseudorange_m = 0.0;
  double elevation_rad = 0.0;
  double azimuth_rad = 0.0;
};

/// Troposphere mapping m(E) and ionosphere obliquity F(E) as above (E in radians).
double troposphere_mapping(double elevation_rad);
double ionosphere_obliquity(double elevation_rad);

class PseudorangeModel {
 public:
  explicit PseudorangeModel(const PseudorangeConfig& config = {});

  /// The pseudoranges of every satellite above the mask at t (seconds since the constellation
  /// epoch), for a receiver at receiver_ecef_m with clock bias clock_bias_s.
  std::vector<Pseudorange> measure(const GpsConstellation& constellation, double time_since_epoch_s,
                                   const Eigen::Vector3d& receiver_ecef_m, double clock_bias_s);

  /// The satellites above the mask (no noise drawn).
  std::vector<std::size_t> visible(const GpsConstellation& constellation, double time_since_epoch_s,
                                   const Eigen::Vector3d& receiver_ecef_m) const;

  const PseudorangeConfig& config() const { return config_; }

 private:
  PseudorangeConfig config_;
  std::mt19937_64 generator_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
};

/// Throws std::invalid_argument unless the receiver position is finite and between 1000 km
/// below and 3000 km above the ellipsoid's equatorial radius (the SPS terrestrial service volume
/// reaches 3000 km altitude).
void check_receiver_position(const Eigen::Vector3d& receiver_ecef_m, const char* origin);

}  // namespace fedsim::nav
