// Parameters of the classical washout (Reid & Nahon 1985; classical_washout.hpp has the
// equations). Defaults: fedsim's tuning for the typical 60-inch platform (stewart_geometry.hpp),
// chosen here so that the manoeuvres of the tests (a pitch doublet, a takeoff roll with
// rotation) stay inside the soft stroke; they are not copied from a paper. The tilt rate limit
// of 3 deg/s is the perception threshold for tilt of Groen & Bles (2004), "How to use body tilt
// for the simulation of linear self motion", J. Vestibular Research 14(5).
#pragma once

#include <array>

namespace fedsim::motion {

/// One translational axis (x surge, y sway, z heave): specific force -> platform displacement
/// through  K s / ((s^2 + 2 zeta wn s + wn^2)(s + wb))  (a third-order high-pass of the
/// acceleration, integrated twice).
struct TranslationalChannelParameters {
  double gain = 0.5;                     // K applied to the specific-force deviation [-], 0..1
  double natural_frequency_radps = 2.0;  // wn of the second-order high-pass [rad/s]
  double damping_ratio = 1.0;            // zeta [-]
  double break_frequency_radps = 0.3;    // wb of the first-order washout [rad/s]
};

/// One rotational axis (roll, pitch, yaw): angular rate -> platform angle through
/// K s / (s^2 + 2 zeta wn s + wn^2)  (a second-order high-pass of the Euler rate, integrated).
struct RotationalChannelParameters {
  double gain = 0.6;                     // K on the angular rate [-], 0..1
  double natural_frequency_radps = 1.0;  // wn [rad/s]
  double damping_ratio = 1.0;            // zeta [-]
};

/// Tilt coordination: the sustained longitudinal and lateral specific force, low-passed, becomes
/// a pitch and roll of the cab so that gravity supplies it; the tilt moves no faster than the
/// rate limit, below the pilot's threshold.
struct TiltCoordinationParameters {
  bool enabled = true;
  double gain = 1.0;                     // K_tilt on the low-passed specific force [-], 0..1
  double natural_frequency_radps = 2.0;  // wn of the second-order low-pass [rad/s]
  double damping_ratio = 1.0;            // zeta [-]
  double rate_limit_radps = 0.0523598775598298873;  // 3 deg/s [rad/s]
  double angle_limit_rad = 0.349065850398865915;    // 20 deg [rad]
};

struct ClassicalWashoutParameters {
  std::array<TranslationalChannelParameters, 3> translational{
      TranslationalChannelParameters{},                     // x surge
      TranslationalChannelParameters{},                     // y sway
      TranslationalChannelParameters{0.5, 4.0, 1.0, 0.5}};  // z heave
  std::array<RotationalChannelParameters, 3> rotational{
      RotationalChannelParameters{},                // roll
      RotationalChannelParameters{},                // pitch
      RotationalChannelParameters{0.6, 0.7, 1.0}};  // yaw
  TiltCoordinationParameters tilt;
  /// |K (f - f_ref)| per axis is limited to this before the filters [m/s^2].
  double specific_force_limit_mps2 = 10.0;
  /// Gravity used for the alignment and the tilt (the flight model's g0) [m/s^2].
  double gravity_mps2 = 9.80665;
};

/// Checks every field for the sample period dt_s (gains in [0, 1], frequencies positive and
/// below Nyquist pi/dt_s, damping ratios in (0, 5], tilt rate limit in (0, 20 deg/s], tilt angle
/// limit in (0, 45 deg], force limit positive, gravity in [9, 10.5] m/s^2); throws
/// std::invalid_argument naming the field, e.g. "ClassicalWashoutParameters:
/// translational[2].damping_ratio = 0 must be in (0, 5]".
void validate(const ClassicalWashoutParameters& parameters, double dt_s);

}  // namespace fedsim::motion
