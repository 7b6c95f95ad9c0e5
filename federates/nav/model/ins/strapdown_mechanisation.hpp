// Strapdown inertial navigation in the local-level (NED) frame on the WGS-84 ellipsoid
// (seed 6.10.2; Titterton & Weston, Strapdown Inertial Navigation Technology, 2nd ed. 2004,
// section 3.5.3 "local geographic navigation frame mechanisation" and 3.7.1 (component form);
// the discrete form follows Groves, Principles of GNSS, Inertial, and Multisensor Integrated
// Navigation Systems, 2nd ed. 2013, section 5.4, eqs 5.44-5.77).
//
// Continuous equations (n = NED at the vehicle, b = body, e = earth, i = inertial):
//   (M1) attitude:  dC_b^n/dt = C_b^n [omega_nb^b x],
//        omega_nb^b = omega_ib^b - C_n^b (omega_ie^n + omega_en^n)        (T&W 3.5.3)
//   (M2) velocity:  dv^n/dt = C_b^n f^b - (2 omega_ie^n + omega_en^n) x v^n + g_l^n
//                   (specific force, Coriolis and transport terms, plumb-line gravity; T&W 3.5.3)
//   (M3) position:  dL/dt = v_N / (R_N + h),  dlambda/dt = v_E / ((R_E + h) cos L),
//                   dh/dt = -v_D                                           (T&W 3.7.1)
//   omega_ie^n, omega_en^n, R_N, R_E, g_l^n: navigation_earth.hpp.
//
// Discrete update over dt with the mean body rate and specific force of the interval:
//   (D1) alpha = omega_ib^b dt (body rotation vector, exact for a constant rate: no coning
//        correction), zeta = (omega_ie^n + omega_en^n) dt (rotation of the NED frame);
//   (D2) f^n = C_b^n(mid) f^b, with the attitude at mid-interval from alpha/2 and zeta/2
//        (Groves 5.84-5.86 to second order: sculling of a rotating specific force);
//   (D3) v_{k+1} = v_k + dt (f^n - (2 omega_ie^n + omega_en^n) x v_k + g_l^n(k)) (Groves 5.54);
//   (D4) h, L, lambda by the trapezoidal rule with the old and new velocities (Groves 5.56);
//   (D5) q_{k+1} = q(-zeta') q_k q(alpha), zeta' with the mean of the old and new transport
//        rates (Groves 5.73 and 5.77 in quaternion form).
// Vertical channel: on its own (D3)-(D4) are unstable (time constant sqrt(R/2g) ~ 570 s);
// a VerticalChannelCorrection (baro loop, baro_inertial_loop.hpp) may be added to dh/dt and
// dv_D/dt.
//
// Inputs per update: measured ImuSample (body, SI), dt [s]; output: NavigationState.
// Valid for |latitude| <= 89.5 deg (throws std::domain_error beyond).
#pragma once

#include "federates/nav/model/ins/imu_sample.hpp"
#include "federates/nav/model/ins/navigation_state.hpp"

namespace fedsim::nav {

/// Corrections a vertical-channel aiding loop adds for one update.
struct VerticalChannelCorrection {
  double height_rate_mps = 0.0;         // added to dh/dt [m/s]
  double down_acceleration_mps2 = 0.0;  // added to dv_D/dt [m/s^2]
};

class StrapdownMechanisation {
 public:
  /// Starts from an aligned state (checked: check_navigation_state).
  explicit StrapdownMechanisation(const NavigationState& initial);

  /// Integrates one interval. dt_s in (0, 60] s; the sample is checked (check_imu_sample).
  void update(const ImuSample& measured, double dt_s,
              const VerticalChannelCorrection& vertical = {});

  const NavigationState& state() const { return state_; }

 private:
  NavigationState state_;
};

}  // namespace fedsim::nav
