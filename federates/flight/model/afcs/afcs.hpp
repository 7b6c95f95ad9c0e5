// The automatic flight control system (AFCS) of a 737-class aircraft: autopilot, flight
// director and autothrottle with their mode logic, up to an automatic landing and rollout.
// A pure library (std + common/control; no DDS, no wall clock, no threads): the flight federate
// hosts it next to the flight model (README.md "Where the AFCS runs"), the batch tests and the
// Monte Carlo drive it in-process.
//
// Per frame: step(AfcsInputs) -> AfcsOutputs (afcs_inputs.hpp, afcs_outputs.hpp).
//   1. the inputs are checked (a bad sample disengages with an alert: nothing reaches a law);
//   2. the guidance evaluates the capture points and heights (vertical_guidance, lateral_guidance,
//      vor_guidance);
//   3. the mode logic (mode_logic.hpp) moves the modes; each change is reported to the callback;
//   4. the laws of the active modes give a flight-path, pitch and bank command, faded on a mode
//      change (common/control Fader) and rate limited;
//   5. the inner loops (attitude_loops) turn them into elevator and aileron; the yaw channel,
//      rollout control and autothrottle give rudder, steering, brakes, spoilers and throttle.
// While the autopilot (or autothrottle) is off, its loops track the pilot's present commands,
// so that engagement is bumpless.
#pragma once

#include "common/control/fader.hpp"
#include "common/control/first_order_lag.hpp"
#include "common/control/pid.hpp"
#include "common/control/rate_limiter.hpp"
#include "flight/model/afcs/afcs_inputs.hpp"
#include "flight/model/afcs/afcs_outputs.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"
#include "flight/model/afcs/attitude_loops.hpp"
#include "flight/model/afcs/autothrottle.hpp"
#include "flight/model/afcs/flight_path_loop.hpp"
#include "flight/model/afcs/mode_logic.hpp"
#include "flight/model/afcs/rollout_control.hpp"
#include "flight/model/afcs/vertical_guidance.hpp"
#include "flight/model/afcs/vor_guidance.hpp"
#include "flight/model/afcs/yaw_channel.hpp"

namespace fedsim::flight::afcs {

class Afcs {
 public:
  using TransitionCallback = ModeLogic::TransitionCallback;

  /// Validates the parameters and dt_s (> 0, <= 0.1 s); throws std::invalid_argument.
  Afcs(const AfcsParameters& parameters, double dt_s, TransitionCallback on_transition = {});

  /// One frame (call at the dt_s of construction). Never throws for per-frame data.
  const AfcsOutputs& step(const AfcsInputs& inputs);

  const AfcsOutputs& outputs() const { return outputs_; }
  const ModeState& modes() const { return logic_.state(); }
  /// The input field that failed the last check (empty when the last sample was good).
  std::string_view last_input_problem() const { return input_problem_; }
  const AfcsParameters& parameters() const { return parameters_; }
  /// The altitude ALT HOLD holds [m].
  double hold_altitude_m() const { return hold_altitude_m_; }
  /// Everything off, as constructed (no transitions reported).
  void reset();

 private:
  struct Guidance;  // the frame's derived quantities
  Guidance evaluate_guidance(const AfcsInputs& in) const;
  ModeConditions conditions(const AfcsInputs& in, const Guidance& g) const;
  void enter_modes(const ModeState& before, const AfcsInputs& in, const Guidance& g);
  double bank_command_rad(const AfcsInputs& in, const Guidance& g);
  double vor_bank_command_rad(const AfcsInputs& in, const Guidance& g) const;
  double path_command_rad(const AfcsInputs& in, const Guidance& g);
  double pitch_command_rad(const AfcsInputs& in, const Guidance& g);
  void fly_surfaces(const AfcsInputs& in, const Guidance& g, double pitch_c, double bank_c);
  void fly_rudder_and_rollout(const AfcsInputs& in, const Guidance& g);
  void fly_throttle(const AfcsInputs& in, const Guidance& g);
  void auto_trim(const AfcsInputs& in, double schedule);
  void track_pilot(const AfcsInputs& in, const Guidance& g);
  void fill_annunciation(const Guidance& g, double pitch_c, double bank_c);
  void hold_after_bad_sample();

  AfcsParameters parameters_;
  double dt_s_;
  ModeLogic logic_;
  PitchAttitudeLoop pitch_loop_;
  RollAttitudeLoop roll_loop_;
  YawChannel yaw_;
  FlightPathLoop path_loop_;
  control::Pid speed_on_elevator_;
  Autothrottle autothrottle_;
  RolloutControl rollout_;
  VorGuidance vor_;
  control::Fader bank_fader_;
  control::Fader path_fader_;
  control::Fader pitch_fader_;
  control::Fader rudder_fader_;
  control::Fader elevator_fader_;
  control::RateLimiter bank_rate_;
  control::FirstOrderLag side_force_;  // lateral specific force, low-passed [m/s^2]
  control::FirstOrderLag trim_load_;   // elevator command, low-passed: the auto-trim's input
  control::FirstOrderLag pitch_command_rate_;  // d(theta_c)/dt, smoothed [rad/s]
  control::FirstOrderLag bank_command_rate_;   // d(phi_c)/dt, smoothed [rad/s]

  AfcsOutputs outputs_;
  std::string_view input_problem_;
  bool first_frame_ = true;
  double previous_mcp_altitude_m_ = 0.0;
  // Mode references captured at mode entry.
  double hold_altitude_m_ = 0.0;
  double hold_heading_rad_ = 0.0;
  double hold_bank_rad_ = 0.0;
  double hold_pitch_rad_ = 0.0;
  double hold_track_rad_ = 0.0;
  double over_station_course_rad_ = 0.0;  // the VOR course held over the station
  double go_around_speed_mps_ = 0.0;
  double level_change_direction_ = 1.0;  // +1 climbing, -1 descending
  FlareLaw flare_;
  double derotation_pitch_rad_ = 0.0;
  double pitch_command_rad_ = 0.0;   // this frame's (faded) pitch command
  double bank_command_rad_ = 0.0;
  double previous_pitch_command_rad_ = 0.0;  // last frame's: the command rates
  double previous_bank_command_rad_ = 0.0;
  double path_command_rad_ = 0.0;
  double trim_elevator_time_s_ = 0.0;
  int trim_command_ = 0;        // the motor's direction while trimming
  double trim_duty_credit_ = 0.0;  // pulse modulation of the trim motor [frames]
  int trim_output_ = 0;          // this frame's trim command (a pulse of trim_command_ or 0)
};

}  // namespace fedsim::flight::afcs
