// A strapdown inertial navigation system (seed 6.10): an IMU with sensor errors
// (imu_error_model.hpp), the NED mechanisation (strapdown_mechanisation.hpp) integrated at a
// stated rate, and optional baro damping of the vertical channel (baro_inertial_loop.hpp).
//
// Inputs per step: the TRUE IMU sample at the CG (body: specific force m/s^2, rate w.r.t.
// inertial rad/s, e.g. imu_sample_at_cg(force_body_n, mass_kg, omega_body_radps) from the
// AircraftState), the step dt [s] (split into ceil(dt * integration_rate_hz) equal sub-steps
// with the same mean sample), and, for a baro-damped channel, the barometric height [m].
// Outputs: the INS solution (geodetic position, ECEF position, NED velocity, attitude as
// q_ned_from_body and Euler angles) and its errors against a given truth (navigation_state.hpp).
//
// Vertical channel: VerticalChannel::kFree integrates (M2)-(M3) alone and DIVERGES (time
// constant sqrt(R/2g) ~ 570 s: any height error grows like cosh(t sqrt(2g/R))). kBaroDamped
// (the default) closes the third-order baro loop on each step that brings a baro height; a
// step without one coasts free.
// Alignment: from the truth, with optional initial position, velocity and tilt errors (an
// "ideal transfer alignment"; gyrocompassing is not modelled).
// The IMU sees the round, rotating earth: omega must include the earth rate. A flat-earth
// flight model's rates (w.r.t. its local frame) must be converted first (imu_from_kinematics).
#pragma once

#include "federates/nav/model/ins/baro_inertial_loop.hpp"
#include "federates/nav/model/ins/imu_error_model.hpp"
#include "federates/nav/model/ins/navigation_state.hpp"
#include "federates/nav/model/ins/strapdown_mechanisation.hpp"

#include <cstdint>
#include <optional>

namespace fedsim::nav {

enum class VerticalChannel { kFree, kBaroDamped };

struct InsConfig {
  double integration_rate_hz = 100.0;  // sub-step rate of the mechanisation, (0, 10000] [Hz]
  VerticalChannel vertical_channel = VerticalChannel::kBaroDamped;
  double baro_loop_time_constant_s = 100.0;  // [1, 10000] s
  ImuErrors imu_errors = ImuErrors::none();
  std::uint64_t noise_seed = 1;  // seeds the random walks (std::mt19937_64)

  /// Throws std::invalid_argument for an out-of-range or non-finite value.
  void check() const;
};

/// Initial alignment errors (all zero: perfect alignment to the truth).
struct InitialErrors {
  Eigen::Vector3d position_ned_m = Eigen::Vector3d::Zero();    // [m]
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();  // [m/s]
  Eigen::Vector3d tilt_ned_rad = Eigen::Vector3d::Zero();      // attitude error, NED [rad]
};

struct InsSolution {
  double time_s = 0.0;                 // time since alignment [s]
  NavigationState state;               // lat, lon, h; velocity NED; q_ned_from_body
  Eigen::Vector3d position_ecef_m = Eigen::Vector3d::Zero();
  EulerAngles euler;                   // 3-2-1 angles of q_ned_from_body [rad]
  bool vertical_channel_aided = false; // the last step closed the baro loop
  double baro_accel_bias_estimate_down_mps2 = 0.0;  // the loop's vertical bias estimate
};

class InertialNavigationSystem {
 public:
  InertialNavigationSystem(const InsConfig& config, const NavigationState& alignment_truth,
                           const InitialErrors& initial_errors = {});

  /// Advances by dt_s in (0, 60] s. baro_height_m is used in kBaroDamped mode only.
  void step(const ImuSample& true_imu, double dt_s,
            std::optional<double> baro_height_m = std::nullopt);

  InsSolution solution() const;
  NavigationErrors errors_against(const NavigationState& truth) const;

  double time_s() const { return time_s_; }
  const InsConfig& config() const { return config_; }

 private:
  void sub_step(const ImuSample& true_imu, double dt_s, std::optional<double> baro_height_m);

  InsConfig config_;
  ImuErrorModel imu_;
  StrapdownMechanisation mechanisation_;
  BaroInertialLoop baro_loop_;
  double time_s_ = 0.0;
  bool vertical_channel_aided_ = false;
};

/// An ideal IMU sample from kinematics on the round earth, for flight models that give the
/// motion relative to the local level frame (a flat-earth model): with v^n the velocity, a^n
/// its rate of change seen in NED (dv^n/dt) and omega_nb^b the body rate relative to NED,
///   f^b = C_n^b (a^n + (2 omega_ie^n + omega_en^n) x v^n - g_l^n)   (M2 solved for f)
///   omega_ib^b = omega_nb^b + C_n^b (omega_ie^n + omega_en^n)        (M1 solved for omega_ib)
ImuSample imu_from_kinematics(const NavigationState& truth,
                              const Eigen::Vector3d& acceleration_ned_mps2,
                              const Eigen::Vector3d& omega_body_wrt_ned_radps);

}  // namespace fedsim::nav
