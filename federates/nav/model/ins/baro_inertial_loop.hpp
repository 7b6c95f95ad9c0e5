// Third-order baro-inertial loop damping the INS vertical channel (seed 6.10.2; Titterton &
// Weston 2nd ed. ch. 12 on the unstable free vertical channel and height aiding;
// the loop structure is the classic third-order one of Widnall & Sinha, "Optimizing the gains of
// the baro-inertial vertical channel", J. Guidance and Control 3(2), 1980).
//
// With dh = h_ins - h_baro, each update adds
//   dh/dt     += -k1 dh                   (height correction)
//   dv_D/dt   += +k2 dh - b_hat           (velocity correction and the estimated bias)
//   db_hat/dt  = -k3 dh                   (vertical accelerometer-bias estimate, down)
// The error dynamics of the aided channel are
//   dh''' + k1 dh'' + (k2 - 2 g/R) dh' + k3 dh = 0,
// where -2 g/R is the free channel's positive feedback (gravity falls as 1/r^2). The gains place
// a triple pole at -1/tau: k1 = 3/tau, k2 = 3/tau^2 + 2 g/R, k3 = 1/tau^3. A constant
// accelerometer bias leaves no steady height error.
// Inputs: INS height [m], baro height [m] (pressure altitude corrected to height, from the
// truth here), gravity g [m/s^2] and radius R [m] at the vehicle, dt [s].
#pragma once

#include "federates/nav/model/ins/strapdown_mechanisation.hpp"

namespace fedsim::nav {

class BaroInertialLoop {
 public:
  /// tau_s: the loop's time constant, in [1, 10000] s (typical 30-300 s).
  explicit BaroInertialLoop(double time_constant_s = 100.0);

  /// The corrections for the next update and the bias estimate advanced by dt_s.
  VerticalChannelCorrection step(double ins_height_m, double baro_height_m, double gravity_mps2,
                                 double radius_m, double dt_s);

  double time_constant_s() const { return time_constant_s_; }
  double accel_bias_estimate_down_mps2() const { return bias_estimate_down_mps2_; }

 private:
  double time_constant_s_;
  double bias_estimate_down_mps2_ = 0.0;
};

}  // namespace fedsim::nav
