// A test pilot that flies the wings-level 1 g stall entry of a qualification test guide: power
// set (idle by default), airspeed brought down at a steady rate (1 kt/s, as 14 CFR 25.103(c)
// prescribes for the stall-speed manoeuvre and Part 60's Table A2A stall test asks for), wings
// held level with the ailerons, until the stall is identified; then the recovery (the nose
// lowered to the entry's pitch attitude and held there, power up).
//
// The control law is a cascade a pilot flies by eye:
//   speed reference  V_ref(t) = V_0 - r (t - t_0)                  (V_0, t_0: the first sample)
//   pitch command    theta_c  = theta_0 + K_v e_V + K_vi int(e_V) + K_vd (dV/dt + r)
//                                                                   e_V = V - V_ref  (too fast,
//                                                                   or slowing too little: more
//                                                                   nose up); dV/dt filtered
//   elevator         d_e = d_0 - K_th (theta_c - theta) - K_thi int(theta_c - theta) + K_q q
//                                                                   (+ elevator is nose down)
//   ailerons         d_a = -K_phi phi - K_p p                        (+ aileron rolls right)
// The integrators stop while the elevator is against a stop (no wind-up).
//
// Stall identification (the acceptable indications of 14 CFR 25.201(d), as far as a program can
// see them):
//   - the elevator held against its aft stop for `aft_stop_hold_s` (the control reaches the stop
//     and the pitch attitude no longer increases: the C172 pack, whose elevator cannot reach its
//     maximum lift, ends its entry this way);
//   - a nose-down pitch the pilot cannot arrest: pitch rate below -`pitch_break_dps` for
//     `pitch_break_hold_s` while the elevator is held or moving aft.
// The stall speed itself is measured from the recording (tools/qtg: `stall_speed_1g`, the
// speed at the maximum load-factor-corrected lift coefficient), not here.
//
// Pure: no DDS. The I/O component gives it the aircraft's state each frame (observe), then
// samples it (sample); before the first observation it leaves the controls as they are (the
// start's trimmed controls).
#pragma once

#include "io/model/input_source.hpp"

#include <string>

namespace fedsim::io {

/// What the pilot sees of the aircraft (SI; the flight federate's state of the frame before).
struct PilotObservation {
  double sim_time_s = 0.0;
  double cas_mps = 0.0;        // calibrated airspeed
  double phi_rad = 0.0;        // roll
  double theta_rad = 0.0;      // pitch
  double p_radps = 0.0;        // body roll rate
  double q_radps = 0.0;        // body pitch rate
  double elevator = 0.0;       // elevator command flown, incl. trim (-1..1, + nose down)
  double elevator_trim = 0.0;  // its pitch-trim part
};

struct StallEntryParameters {
  double entry_rate_kt_per_s = 1.0;     // airspeed decrease (0.1..5)
  double throttle = 0.0;                // every engine during the entry (0 idle .. 1)
  double recovery_throttle = 1.0;       // after the stall is identified
  // Gains (defaults work for both fedsim packs; see the unit tests and the QTG stall tests).
  double speed_to_pitch_deg_per_kt = 1.0;        // K_v
  double speed_to_pitch_deg_per_kt_s = 0.1;      // K_vi
  double speed_rate_to_pitch_deg_per_kt_s = 3.0; // K_vd: on the deceleration's error (damping)
  double speed_rate_filter_s = 1.0;              // time constant of the deceleration estimate
  double pitch_to_elevator_per_deg = 0.04;       // K_th
  double pitch_to_elevator_per_deg_s = 0.02;     // K_thi
  double pitch_rate_to_elevator_per_dps = 0.02;  // K_q
  double roll_to_aileron_per_deg = 0.03;         // K_phi
  double roll_rate_to_aileron_per_dps = 0.01;    // K_p
  // Stall identification.
  double aft_stop_hold_s = 2.0;
  double pitch_break_dps = 2.0;
  double pitch_break_hold_s = 0.5;
};

/// Checks every parameter (finite, in range); throws std::invalid_argument naming it.
void check(const StallEntryParameters& parameters);

enum class StallEntryPhase { kWaiting, kEntry, kStalled };
const char* to_string(StallEntryPhase phase);

class StallEntryPilot final : public InputSource {
 public:
  explicit StallEntryPilot(StallEntryParameters parameters);

  bool closed_loop() const override { return true; }
  void observe(const PilotObservation& aircraft) override;
  /// Drives elevator, aileron, rudder (centred) and the four throttles.
  void sample(double sim_time_s, ControlInputs& controls) override;
  std::string describe() const override;

  StallEntryPhase phase() const { return phase_; }
  /// When the stall was identified, and the airspeed then [s, m/s] (phase kStalled).
  double stall_time_s() const { return stall_time_s_; }
  double stall_cas_mps() const { return stall_cas_mps_; }
  /// Which indication identified it ("elevator at the aft stop", "pitch break"); empty before.
  const std::string& stall_indication() const { return stall_indication_; }

 private:
  void start(const PilotObservation& aircraft);
  void fly_entry(const PilotObservation& aircraft, double dt_s);
  void fly_recovery(const PilotObservation& aircraft, double dt_s);
  /// The inner loop: the elevator command (unclamped, incl. trim) for a pitch error (command -
  /// attitude) and its integral, about the entry's trimmed elevator, damped by the pitch rate.
  double elevator_for(double pitch_error_deg, double pitch_integral_deg_s, const PilotObservation& aircraft) const;
  void watch_for_the_stall(const PilotObservation& aircraft, double dt_s);
  void identify(const PilotObservation& aircraft, const char* indication);

  StallEntryParameters p_;
  StallEntryPhase phase_ = StallEntryPhase::kWaiting;
  double last_time_s_ = 0.0;
  double start_time_s_ = 0.0, start_cas_mps_ = 0.0, start_theta_rad_ = 0.0;
  double start_elevator_ = 0.0;  // the entry's trimmed elevator command, incl. trim
  double elevator_trim_ = 0.0;
  double speed_integral_kt_s_ = 0.0;
  double previous_cas_kt_ = 0.0;
  double speed_rate_kt_s_ = 0.0;  // filtered dV/dt
  double pitch_integral_deg_s_ = 0.0;
  double recovery_integral_deg_s_ = 0.0;
  double elevator_ = 0.0;        // commanded, incl. trim
  double previous_elevator_ = 0.0;
  double aileron_ = 0.0;
  double aft_stop_s_ = 0.0;      // time held at the aft stop
  double pitch_break_s_ = 0.0;   // time the nose has been falling against the pilot
  double stall_time_s_ = 0.0, stall_cas_mps_ = 0.0;
  std::string stall_indication_;
};

}  // namespace fedsim::io
