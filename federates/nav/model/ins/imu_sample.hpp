// What an ideal or a modelled inertial measurement unit (IMU) at the CG delivers over one
// interval: the mean specific force and the mean angular rate, both resolved in body axes.
//
// Inputs come from the flight federate's AircraftState (idl/aircraft_state.idl): the specific
// force at the CG is force_body_n / mass_kg (gravity excluded, so a level aircraft at rest reads
// about (0, 0, -9.8) m/s^2), and the rate is omega_body_radps (body w.r.t. inertial space).
// Units: m/s^2, rad/s; frame: body (x forward, y right wing, z down), docs/frames.md.
#pragma once

#include <Eigen/Core>

#include <string_view>

namespace fedsim::nav {

/// Mean IMU outputs over one interval (f_ib^b and omega_ib^b of Titterton & Weston ch. 3).
struct ImuSample {
  Eigen::Vector3d specific_force_body_mps2 = Eigen::Vector3d::Zero();  // f_ib^b [m/s^2]
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();  // omega_ib^b, w.r.t. inertial [rad/s]
};

/// Largest specific force (about 100 g) and angular rate (about 1150 deg/s) accepted: beyond the
/// range of any aircraft IMU, so a value past them is a unit or data error.
inline constexpr double kMaxSpecificForceMps2 = 1000.0;
inline constexpr double kMaxAngularRateRadps = 20.0;

/// Throws std::invalid_argument naming `origin` if a component is NaN or infinite or beyond the
/// limits above.
void check_imu_sample(const ImuSample& sample, std::string_view origin);

/// The ideal IMU at the CG from the flight model's outputs: f = force_body_n / mass_kg, omega as
/// given. Throws std::invalid_argument for a non-finite input or a mass that is not positive.
ImuSample imu_sample_at_cg(const Eigen::Vector3d& force_body_n, double mass_kg,
                           const Eigen::Vector3d& omega_body_radps);

}  // namespace fedsim::nav
