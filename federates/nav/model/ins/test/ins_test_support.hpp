// Test support for the INS tests: stationary truth and its ideal IMU computed independently of
// the mechanisation (earth rate from the ECEF rotation vector, gravity from common/geodesy),
// and zero-crossing period measurement.
#pragma once

#include "common/geodesy/wgs84.hpp"
#include "common/math/rotation.hpp"
#include "common/units/units.hpp"
#include "federates/nav/model/ins/imu_sample.hpp"
#include "federates/nav/model/ins/navigation_state.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace fedsim::nav::test {

inline constexpr double kDeg = units::kDegToRad;

/// At rest on the earth, level, at a heading.
inline NavigationState stationary_state(double lat_rad, double lon_rad, double height_m,
                                        double heading_rad = 0.0) {
  NavigationState s;
  s.position = {lat_rad, lon_rad, height_m};
  s.q_ned_from_body = quaternion_from_euler({0.0, 0.0, heading_rad});
  return s;
}

/// What a perfect IMU at rest reads: the reaction to plumb-line gravity and the earth's rate,
/// both taken from the ECEF description (Wgs84::gravity_ecef, earth_rate_ecef) and rotated.
inline ImuSample stationary_imu(const NavigationState& s) {
  const Eigen::Matrix3d ned_from_ecef = Wgs84::ned_from_ecef(s.position.lat_rad, s.position.lon_rad);
  const Eigen::Matrix3d body_from_ned = s.q_ned_from_body.toRotationMatrix().transpose();
  const Eigen::Vector3d g_ecef = Wgs84::gravity_ecef(Wgs84::ecef_from_geodetic(s.position));
  ImuSample imu;
  imu.specific_force_body_mps2 = -body_from_ned * ned_from_ecef * g_ecef;
  imu.omega_body_radps = body_from_ned * ned_from_ecef * Wgs84::earth_rate_ecef();
  return imu;
}

/// Times [s] where samples (t_i, x_i) change sign, by linear interpolation.
inline std::vector<double> zero_crossings(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if ((x[i - 1] < 0.0) != (x[i] < 0.0) && x[i] != x[i - 1]) {
      crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * x[i - 1] / (x[i - 1] - x[i]));
    }
  }
  return crossings;
}

/// The period of an oscillation from its zero crossings (two per period), first to last.
inline double period_from_crossings(const std::vector<double>& crossings) {
  if (crossings.size() < 3) return 0.0;
  return 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

}  // namespace fedsim::nav::test
