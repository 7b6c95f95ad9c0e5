// Lateral guidance laws: bank commands for a direction, the cross-track error of a localizer
// or a VOR, the track command onto a course and its capture point. Pure functions.
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

/// Distance left of a VOR course [m] (+ = left = fly right): the deviation is an angle about the
/// station (deviation x full scale, the same sense TO and FROM), so y = d sin(angle) with d the
/// distance from the station (the DME's, or a nominal one).
double vor_cross_track_left_m(double deviation, double full_scale_rad, double distance_m);

/// How a course (a localizer's or a VOR's) is captured and tracked.
struct CourseLaw {
  double track_time_constant_s = 16.0;  // tau: the cross track decays as exp(-t / tau)
  double max_intercept_rad = 45.0 * units::kDegToRad;
  double capture_bank_rad = 20.0 * units::kDegToRad;  // the capture turn's nominal bank
  double lead_time_s = 2.0;             // roll-in, plus the lag of any deviation filter
  double max_on_scale_deviation = 0.95;
};
CourseLaw localizer_course_law(const LateralGains& gains);
/// The VOR's: its time constant and filter lag; the capture turn's bank within 0.8 of the MCP
/// bank limit (the 737's bank angle selector limits VOR/LOC as it does HDG SEL).
CourseLaw vor_course_law(const LateralGains& lateral, const VorGains& vor, double mcp_bank_limit_rad);

/// The track to fly onto a course: course + asin(y / (V tau)), the intercept limited to
/// max_intercept: the cross-track error y then decays as exp(-t / tau) at any distance.
double course_track_command_rad(double cross_track_left_m, double course_true_rad, double ground_speed_mps,
                                const CourseLaw& law);

/// The capture point of a course: the deviation is on scale, the aircraft closes on the course,
/// and its cross-track distance is within the lead of the capture turn, R (1 - cos(intercept))
/// with R = V^2 / (g tan(capture bank)), plus the distance closed during the lead time
/// (V sin(intercept) x lead_time). With a 30 deg intercept at 145 kt: about 330 m.
bool course_capture_point(double deviation, double cross_track_left_m, double course_true_rad,
                          double track_true_rad, double ground_speed_mps, const CourseLaw& law);

/// The lead distance of course_capture_point() [m] for an intercept angle [rad].
double course_capture_lead_m(double intercept_rad, double ground_speed_mps, const CourseLaw& law);

/// The localizer's: course_*() with localizer_course_law(gains).
double localizer_track_command_rad(double cross_track_left_m, double course_true_rad,
                                   double ground_speed_mps, const LateralGains& gains);
bool localizer_capture_point(double deviation, double cross_track_left_m, double course_true_rad,
                             double track_true_rad, double ground_speed_mps,
                             const LateralGains& gains);
double localizer_capture_lead_m(double intercept_rad, double ground_speed_mps,
                                const LateralGains& gains);

}  // namespace fedsim::flight::afcs
