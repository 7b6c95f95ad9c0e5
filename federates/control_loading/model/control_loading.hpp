// The control-loading system of fedsim-control-loading: three axes (pitch, roll, yaw), each a
// ControlAxis, run by an inner loop sub-stepped inside the frame at >= inner_rate_hz (1 kHz by
// default, raised if the stiffest element needs it; see control_axis.hpp for the stability
// condition), with the stick shaker and the safety supervisor.
//
// The loop (one call of step per frame, dt_s): the inputs are checked; the watchdog and input
// checks may cut the forces off; then for each of the N = substeps sub-steps: the shaker
// oscillator, the simulated pilot's force (if the pilot is simulated), each axis' sub-step, the
// overspeed check. The pilot's force (force sensor) and the flight data are held over the
// frame. The outputs (position, velocity, forces) are those at the end of the frame: the
// position is what the I/O federate reports as the pilot's input when the loader is in the
// loop.
//
// Safety (seed 1.4.10: forces "very closely monitored ..., which can remove any control
// loading within a few milliseconds"):
//   - the loader force on every axis is clamped to motor_force_limit_n, always;
//   - SAFE state: the feel, the drive and the shaker are off; only a damping -c_safe v acts,
//     so a released control does not run away and the pilot can still move it;
//   - cut-off to SAFE (effective from the sub-step it is detected in): a non-finite or
//     out-of-range input, flight data older than watchdog_timeout_s, a velocity beyond
//     velocity_trip_mps, or cut_off(reason) (instructor, the adapter's wall-clock watchdog);
//   - engage() from SAFE fades the forces in over fade_in_s (no jolt), then ACTIVE.
// The model starts SAFE ("not engaged").
#pragma once

#include <array>
#include <limits>
#include <string>

#include "control_loading/model/control_axis.hpp"
#include "control_loading/model/control_axis_parameters.hpp"
#include "control_loading/model/simulated_pilot.hpp"
#include "control_loading/model/stick_shaker.hpp"

namespace fedsim::control_loading {

enum class Axis { kPitch = 0, kRoll = 1, kYaw = 2 };
inline constexpr int kAxisCount = 3;
const char* to_string(Axis axis);

enum class LoaderStatus { kSafe, kFadingIn, kActive };
const char* to_string(LoaderStatus status);

struct ControlLoadingParameters {
  std::array<ControlAxisParameters, kAxisCount> axes{default_pitch_axis(), default_roll_axis(),
                                                     default_yaw_axis()};
  double inner_rate_hz = 1000.0;        // minimum inner-loop rate, >= 1000 [Hz]
  double shaker_alpha_rad = 0.24;       // stick shaker on at this angle of attack [rad]
  double shaker_hysteresis_rad = 0.01;  // ... off below shaker_alpha - this [rad]
  double watchdog_timeout_s = 0.1;      // flight data older than this cuts off [s]
  double fade_in_s = 0.5;               // forces fade in over this after engage() [s]
  double pilot_force_limit_n = 1500.0;  // force sensor range: beyond it the input is invalid [N]
  double qbar_limit_pa = 1.0e5;         // dynamic pressure beyond this is invalid [Pa]
  SimulatedPilotParameters pilot;
};

/// Checks every field (std::invalid_argument naming it).
void validate(const ControlLoadingParameters& parameters);

enum class PilotSource { kForceSensor, kSimulatedPilot };

struct AxisInputs {
  double pilot_force_n = 0.0;          // force sensor: the pilot's force, + along + travel [N]
  double pilot_target_norm = 0.0;      // simulated pilot: where the hand wants the control, -1..1
  double trim_norm = 0.0;              // trim input, -1..1 [-]
  bool backdrive_active = false;       // the autopilot drives this axis
  double backdrive_target_norm = 0.0;  // the autopilot's position command, -1..1 [-]
};

struct ControlLoadingInputs {
  PilotSource pilot_source = PilotSource::kForceSensor;
  std::array<AxisInputs, kAxisCount> axes{};  // indexed by Axis
  double qbar_pa = 0.0;                       // dynamic pressure (AircraftState.air.qbar_pa) [Pa]
  double alpha_rad = 0.0;                     // angle of attack (AircraftState.air.alpha_rad) [rad]
  double flight_data_age_s = 0.0;             // how old qbar/alpha are (sim time) [s]
  // The aircraft's stall-warning angle at its present flap setting [rad] (the adapter's, from
  // the pack); NaN or outside (hysteresis, pi/2): the parameters' shaker_alpha_rad.
  double shaker_alpha_rad = std::numeric_limits<double>::quiet_NaN();
};

struct AxisOutputs {
  double position_m = 0.0;             // at the grip, + along + travel [m]
  double velocity_mps = 0.0;           // [m/s]
  double position_norm = 0.0;          // -1..1 of the travel on its side (clamped) [-]
  double velocity_norm_ps = 0.0;       // [1/s]
  double feel_force_n = 0.0;           // loader + physical stop on the control, + along + travel;
                                       //   -pilot force at rest [N]
  double pilot_force_n = 0.0;          // the pilot's force in the last sub-step [N]
  double trim_norm = 0.0;              // trim datum as a fraction of the trim travel [-]
  double gradient_npm = 0.0;           // scheduled gradient [N/m]
  double max_loader_force_n = 0.0;     // largest |loader force| over the frame's sub-steps [N]
  double max_backdrive_force_n = 0.0;  // largest |back-drive servo force| over the frame [N]
  bool in_soft_stop = false;
  bool in_hard_stop = false;
  bool on_mechanical_stop = false;
};

struct ControlLoadingOutputs {
  LoaderStatus status = LoaderStatus::kSafe;
  std::array<AxisOutputs, kAxisCount> axes{};
  bool stick_shaker = false;
  int substeps = 0;        // sub-steps in the last frame
  double substep_s = 0.0;  // their length [s]
};

class ControlLoading {
 public:
  explicit ControlLoading(const ControlLoadingParameters& parameters);

  /// One frame of dt_s (> 0, finite; std::invalid_argument otherwise).
  const ControlLoadingOutputs& step(const ControlLoadingInputs& inputs, double dt_s);

  /// SAFE -> FADING_IN (forces fade in); false in any other state.
  bool engage();
  /// -> SAFE with the reason (the first reason is kept until engage()).
  void cut_off(const std::string& reason);

  LoaderStatus status() const { return outputs_.status; }
  const std::string& cut_off_reason() const { return reason_; }
  const ControlLoadingOutputs& outputs() const { return outputs_; }
  const ControlAxis& axis(Axis a) const { return axes_[static_cast<int>(a)]; }
  /// The longest sub-step the stability condition allows [s].
  double max_stable_substep_s() const { return max_stable_substep_s_; }
  /// The sub-step count for a frame of dt_s.
  int substeps_for(double dt_s) const;

 private:
  bool inputs_valid(const ControlLoadingInputs& inputs, std::string& problem) const;
  void run_substep(const ControlLoadingInputs& inputs, double h);
  void publish_axes(const ControlLoadingInputs& inputs);

  ControlLoadingParameters parameters_;
  std::array<ControlAxis, kAxisCount> axes_;
  StickShaker shaker_;
  double max_stable_substep_s_ = 0.0;
  double force_gain_ = 0.0;
  std::array<double, kAxisCount> gradient_npm_{};
  ControlLoadingOutputs outputs_;
  std::string reason_ = "not engaged";
};

}  // namespace fedsim::control_loading
