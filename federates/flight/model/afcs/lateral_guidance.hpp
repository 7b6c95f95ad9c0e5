// Lateral guidance laws: bank commands for a direction, the localizer's cross-track error,
// track command and capture point. Pure functions.
#pragma once

#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

/// An angle wrapped into (-pi, pi].
double wrap_angle_rad(double angle_rad);

/// The bank of the coordinated turn that removes a direction error at the exponential rate
/// 1/tau: psi_dot = g tan(phi) / V = error / tau  ->  phi = atan(V error / (g tau)), limited to
/// +-bank_limit (the flight director's law, nav_radio flight_director.hpp).
double bank_for_direction_error_rad(double error_rad, double speed_mps, double time_constant_s,
                                    double bank_limit_rad);

/// Distance left of the localizer course [m] (+ = left = fly right): the angular deviation
/// (deviation x half the course width) times the distance from the localizer antenna.
double localizer_cross_track_left_m(double deviation, double half_width_rad,
                                    double distance_from_antenna_m);

/// The track to fly on the localizer: course + asin(y / (V tau)), the intercept limited to
/// max_intercept: the cross-track error y then decays as exp(-t / tau) at any distance.
double localizer_track_command_rad(double cross_track_left_m, double course_true_rad,
                                   double ground_speed_mps, const LateralGains& gains);

/// The localizer capture point: the deviation is on scale, the aircraft closes on the course,
/// and its cross-track distance is within the lead of the capture turn, R (1 - cos(intercept))
/// with R = V^2 / (g tan(capture bank)), plus the distance closed during the roll-in
/// (V sin(intercept) x roll_in_time). With a 30 deg intercept at 145 kt: about 330 m.
bool localizer_capture_point(double deviation, double cross_track_left_m, double course_true_rad,
                             double track_true_rad, double ground_speed_mps,
                             const LateralGains& gains);

/// The lead distance of localizer_capture_point() [m] for an intercept angle [rad].
double localizer_capture_lead_m(double intercept_rad, double ground_speed_mps,
                                const LateralGains& gains);

}  // namespace fedsim::flight::afcs
