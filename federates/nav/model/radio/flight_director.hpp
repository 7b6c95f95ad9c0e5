// Flight director (seed 6.9): the pitch and bank attitudes the pilot (or autopilot) should fly
// to hold a selected heading, track a VOR radial or localizer, track the glide slope or hold an
// altitude. Stateless: each command follows from the inputs of the frame.
//
// Inputs (FlightDirectorInputs): the pose (true heading, pitch, true airspeed, rate of climb,
// altitude MSL), the modes, the selections (heading true [rad], altitude MSL [m]) and the NAV
// source: course true [rad], course deviation (-1..1, + = fly right), glide-slope deviation
// (-1..1, + = fly up), the glide path angle [rad] and their validity. Optional ground track.
// Outputs (FlightDirectorCommand): bank command [rad] (+ right wing down) and pitch command
// [rad] (+ nose up), each with a validity flag: invalid when its mode is off, when the mode's
// source signal is invalid or when an input is not finite (per-frame data: flagged, never thrown).
//
// Lateral laws. A commanded direction chi_c gives the bank of the coordinated turn that removes
// the direction error at an exponential rate 1/tau_psi: psi_dot = g tan(phi) / V = err / tau_psi,
// so phi_c = atan(V err / (g tau_psi)), limited to +-bank_limit.
//   heading select: chi_c = selected heading, error against the heading;
//   VOR/LOC track:  chi_c = course + intercept_at_full_scale x deviation (deviation clamped to
//                   +-1, + = fly right -> intercept to the right), error against the ground track
//                   when given (no standing offset in a crosswind) else the heading.
// Gains: tau_psi = 5 s, several times the ~1 s bank response of an aircraft, so the heading
// loop does not fight the roll loop; bank limit 25 deg (a rate-one turn, 3 deg/s, at 150 kt TAS
// needs 22 deg); 30 deg intercept at full scale, the largest intercept ATC gives onto a final
// approach course (FAA JO 7110.65 5-9-2). Linearised, the cross-track offset y then obeys
// tau_psi y'' + y' + y / tau_y = 0 with tau_y = y_fullscale / (V K), damping
// 0.5 sqrt(tau_y / tau_psi) (roll lag neglected): on a localizer ~0.8 at 5 NM and ~0.4 at the
// threshold at 60 m/s, ~0.7 and ~0.37 at a jet's 75 m/s: stable without a gain schedule to the
// threshold (the damping falls as the beam narrows; an autoland would schedule the gain).
// Vertical laws. A commanded flight-path angle gamma_c gives the pitch command about the current
// pitch: theta_c = theta + (gamma_c - gamma), gamma = asin(climb rate / V) — at constant angle of
// attack a change of pitch is a change of flight path. Limited to [-pitch_down, +pitch_up].
//   glide-slope track: gamma_c = -theta_gs + correction_at_full_scale x theta_gs x deviation:
//     full-scale low levels the aircraft, full-scale high doubles the descent; the height error
//     then decays with a time constant 0.24 D / V (D the distance to the antenna): 37 s at 5 NM,
//     7 s at 1 NM for 60 m/s, slower than the pitch response down to 0.5 NM;
//   altitude hold: climb rate command (h_sel - h) / tau_h, tau_h = 10 s (twice the heading
//     loop's: the path loop stays slower than the ~1 s pitch response), limited to
//     +-1000 ft/min, gamma_c = asin(climb rate command / V).
// Pitch limits +15 / -10 deg keep the bars inside a normal attitude envelope.
// Below 1 m/s (on the ground) the flight path is taken as level and the bank command is 0.
#pragma once

#include "common/radio/aircraft_pose.hpp"
#include "common/units/units.hpp"

#include <cstdint>
#include <optional>

namespace fedsim::radio {
struct NavReading;
}  // namespace fedsim::radio

namespace fedsim::nav {

enum class LateralMode : std::uint8_t { kOff, kHeadingSelect, kNavTrack };
enum class VerticalMode : std::uint8_t { kOff, kAltitudeHold, kGlideSlopeTrack };

struct FlightDirectorGains {
  double heading_time_constant_s = 5.0;
  double bank_limit_rad = 25.0 * units::kDegToRad;
  double intercept_at_full_scale_rad = 30.0 * units::kDegToRad;
  double glide_path_correction_at_full_scale = 1.0;  // x glide path angle [-]
  double altitude_time_constant_s = 10.0;
  double max_climb_rate_mps = 1000.0 * units::kFpmToMps;
  double pitch_up_limit_rad = 15.0 * units::kDegToRad;
  double pitch_down_limit_rad = 10.0 * units::kDegToRad;  // magnitude
};

struct FlightDirectorInputs {
  radio::AircraftPose pose;
  LateralMode lateral_mode = LateralMode::kOff;
  VerticalMode vertical_mode = VerticalMode::kOff;
  double selected_heading_true_rad = 0.0;
  double selected_altitude_msl_m = 0.0;
  double course_true_rad = 0.0;          // the course the deviation refers to [rad]
  double course_deviation = 0.0;         // -1..1, + = fly right [-]
  bool course_valid = false;
  double glide_slope_deviation = 0.0;    // -1..1, + = fly up [-]
  double glide_path_angle_rad = 0.0;     // [rad]
  bool glide_slope_valid = false;
  std::optional<double> ground_track_true_rad;  // over the ground [rad]
};

/// Copies a NAV receiver's course and glide-slope signals (and their validity) into `inputs`.
void set_nav_source(const radio::NavReading& nav, FlightDirectorInputs& inputs);

struct FlightDirectorCommand {
  double roll_command_rad = 0.0;   // + right wing down
  bool roll_valid = false;
  double pitch_command_rad = 0.0;  // + nose up
  bool pitch_valid = false;
};

class FlightDirector {
 public:
  /// Throws std::invalid_argument naming the gain that is not finite and positive (or a limit
  /// outside (0, 90 deg)).
  explicit FlightDirector(FlightDirectorGains gains = {});

  FlightDirectorCommand command(const FlightDirectorInputs& inputs) const;

  const FlightDirectorGains& gains() const { return gains_; }

 private:
  std::optional<double> roll_command(const FlightDirectorInputs& inputs) const;
  std::optional<double> pitch_command(const FlightDirectorInputs& inputs) const;
  double bank_for_direction_error(double error_rad, double airspeed_mps) const;
  double pitch_for_flight_path(double gamma_command_rad, const radio::AircraftPose& pose) const;

  FlightDirectorGains gains_;
};

}  // namespace fedsim::nav
