// Trim (seed 4.4): the controls and attitude that make the aircraft's accelerations vanish in
// straight-and-level flight, a steady climb or descent, a steady coordinated level turn, or at
// rest on the ground; all axes solved together by Levenberg-Marquardt.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "flight/model/aircraft/aircraft_controls.hpp"
#include "flight/model/aircraft/initial_conditions.hpp"

namespace fedsim::flight {

class AircraftModel;

enum class TrimKind {
  kLevel,   ///< straight and level (flight path 0)
  kClimb,   ///< straight steady climb or descent at a flight-path angle
  kTurn,    ///< steady coordinated level turn at a bank angle
  kGround,  ///< at rest on the runway: gear settled, brakes set, engines at ground_throttle
};

/// "level", "climb", "turn", "ground"; throws std::invalid_argument.
TrimKind trim_kind_from_name(std::string_view name);
std::string_view to_string(TrimKind kind);

/// What to trim for.
struct TrimRequest {
  TrimKind kind = TrimKind::kLevel;
  /// Latitude and longitude (rad) and, in flight, the CG height above MSL (m). On the ground
  /// the height follows from the runway elevation and the gear.
  GeodeticPosition position;
  double heading_rad = 0.0;   ///< true heading of the body x axis
  double airspeed_mps = 0.0;  ///< true airspeed, or calibrated if airspeed_is_cas
  bool airspeed_is_cas = false;
  double flight_path_rad = 0.0;  ///< kClimb: air-relative flight-path angle, + climbing
  double bank_rad = 0.0;         ///< kTurn: bank angle, + right wing down (turning right)
  /// Configuration held during the trim (flaps, gear, mixture, propeller levers, speedbrake,
  /// trims). The trim writes elevator, aileron, rudder and the throttles of all engines (and
  /// on the ground sets the throttles to ground_throttle and the brakes on).
  AircraftControls controls;
  /// kGround: the throttle of every engine while parked, 0 (idle) .. 1 (full), e.g. a
  /// full-power run-up held on the brakes before a take-off; the engines are settled at it.
  double ground_throttle = 0.0;
  int max_iterations = 60;
};

/// The equations a trim drives to zero and the tolerances it accepts (SI: m/s^2, rad/s^2).
/// In flight: the body-frame accelerations u', v', w', p', q', r' and, in a turn, the lateral
/// specific force (a centred slip ball: the coordination constraint). On the ground: w', p',
/// q' (u', v', r' are reported; a braked wheel at rest has no Coulomb holding force in the
/// gear model, so idle thrust creeps at millimetres per second).
enum TrimAxis { kUDot, kVDot, kWDot, kPDot, kQDot, kRDot, kLateralForce, kTrimAxisCount };
std::string_view trim_axis_name(int axis);  ///< "u_dot_mps2", ..., "lateral_specific_force_mps2"

struct TrimResult {
  bool converged = false;
  /// Why it failed (empty when converged), e.g. "throttle saturated at 1.0: the aircraft
  /// cannot hold 4000 ft at 180 kt (u_dot -0.42 m/s^2)".
  std::string reason;
  int iterations = 0;
  TrimKind kind = TrimKind::kLevel;

  // The solution.
  AircraftControls controls;
  double alpha_rad = 0.0, beta_rad = 0.0;
  double phi_rad = 0.0, theta_rad = 0.0, psi_rad = 0.0;
  double flight_path_rad = 0.0;
  double turn_rate_radps = 0.0;  ///< heading rate (kTurn)
  double tas_mps = 0.0, cas_mps = 0.0;
  double altitude_m = 0.0;  ///< CG height above MSL
  double elevator_rad = 0.0, aileron_rad = 0.0, rudder_rad = 0.0;
  double total_thrust_n = 0.0;
  /// The state to reset to (engines settled); the model is left in it.
  AircraftInitialConditions initial_conditions;

  // Per axis (TrimAxis order): the residual at the solution, the tolerance, and whether the
  // axis is one of the trim's equations.
  std::array<double, kTrimAxisCount> residuals{};
  std::array<double, kTrimAxisCount> tolerances{};
  std::array<bool, kTrimAxisCount> constrained{};
};

/// Solves a TrimRequest on an AircraftModel. Unknowns in flight: alpha, beta, throttle,
/// elevator, aileron, rudder (+ heading rate in a turn); on the ground: CG height, pitch, roll.
/// Pitch follows from alpha, beta, bank and the flight path (rate-of-climb constraint of
/// Stevens & Lewis, Aircraft Control and Simulation, 2nd ed., eq. 3.6-7); body rates follow
/// from the heading rate (a turn) plus the earth's and the transport rates on the WGS-84
/// earth. Every residual evaluation puts the model in the trial state with the actuators at
/// their commanded positions and the engines run to steady state, so the trimmed state is a
/// true equilibrium of the same model that then flies.
/// Method: Levenberg-Marquardt on all equations together (residuals scaled by their
/// tolerances), numerical central-difference Jacobian, bounds by projection (throttle 0..1,
/// controls -1..1, alpha within the pack's limits or -20..30 deg).
class Trim {
 public:
  explicit Trim(AircraftModel& model) : model_(model) {}

  /// Leaves the model in the trimmed state (or, if it fails, the best state found) with the
  /// trimmed controls set. Never throws for an unreachable trim: converged is false and
  /// reason says why. Throws std::invalid_argument for a malformed request.
  TrimResult solve(const TrimRequest& request);

 private:
  AircraftModel& model_;
};

}  // namespace fedsim::flight
