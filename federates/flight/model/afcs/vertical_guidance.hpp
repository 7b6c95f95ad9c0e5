// Vertical guidance laws: each gives the climb rate or flight-path angle its mode flies, and
// the capture predicates the mode logic needs. Pure functions of the frame's inputs.
#pragma once

#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

/// Altitude capture and hold (ALT ACQ, ALT HOLD): the climb rate that takes the altitude error
/// dh = target - h to zero without overshoot,
///   hdot_c = sign(dh) (sqrt((a tau)^2 + 2 a |dh|) - a tau),
/// a = capture_acceleration (0.05 g), tau = time_constant_s. Far from the target it is the
/// constant-deceleration parabola sqrt(2 a |dh|); near it, |dh| / tau (an exponential approach
/// that never crosses the target); flown exactly, its vertical acceleration a hdot / (hdot + a tau)
/// never exceeds a (the plain minimum of the two laws would jump to 2 a where they meet).
double altitude_rate_command_mps(double altitude_error_m, const AltitudeGains& gains);

/// True when the capture law's climb-rate demand has fallen to the present climb rate: the
/// aircraft moves towards the target and |law(dh)| <= |climb rate| (ALT ACQ starts here, so its
/// demand starts at the present rate and the level-off is continuous).
bool altitude_capture_point(double altitude_error_m, double vertical_speed_mps,
                            const AltitudeGains& gains);

/// The height of the aircraft below the glide path [m] (+ below, fly up) from the receiver's
/// deviation: the angular error below the path is deviation x 0.24 theta_gs (full scale at
/// 0.24 theta_gs, ICAO Annex 10 Vol I 3.1.5.6), times the distance from the glide-slope antenna.
double glide_path_height_error_m(double deviation, double glide_path_angle_rad,
                                 double distance_from_antenna_m);

/// G/S track: gamma_c = -theta_gs + atan(e / (V tau)), e the height below the path: the error
/// decays as exp(-t / tau) whatever the distance (the angular deviation's gain rises as the
/// antenna approaches; the linear error's does not), limited to [-factor theta_gs, 0] (the
/// aircraft is never commanded to climb to the beam nor to dive at more than twice its angle).
double glide_slope_path_command_rad(double height_error_m, double glide_path_angle_rad,
                                    double ground_speed_mps, const GlideSlopeGains& gains);

/// G/S capture: the track law's command has reached the present path from the side the
/// aircraft is on (from below: it asks for no more climb than flown; from above: no steeper a
/// descent) within the margin, with the deviation on scale.
bool glide_slope_capture_point(double deviation, double height_error_m, double glide_path_angle_rad,
                               double ground_speed_mps, double path_rad, const GlideSlopeGains& gains);

/// Flare: the exponential sink-rate law  hdot_c = -(h / tau) - hdot_td  on the main-gear height
/// h, with tau chosen at flare entry so that the demand equals the entry sink rate (no pitch
/// step): tau = h_entry / (|hdot_entry| - hdot_td). The wheels would reach the runway at the
/// asymptotic sink rate hdot_td (Etkin, Dynamics of Atmospheric Flight, 1972, autoland
/// example; McLean 1990, 11.4 "automatic landing").
struct FlareLaw {
  double time_constant_s = 0.0;
  double touchdown_sink_rate_mps = 0.0;
  /// Sets tau from the entry (height [m] > 0, climb rate [m/s]), bounded to 2..10 s.
  static FlareLaw at_entry(double height_m, double vertical_speed_mps, const AutolandGains& gains);
  double climb_rate_command_mps(double height_m) const;
};

}  // namespace fedsim::flight::afcs
