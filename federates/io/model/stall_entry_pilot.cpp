#include "io/model/stall_entry_pilot.hpp"

#include "common/units/units.hpp"
#include "io/model/control_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fedsim::io {
namespace {
using units::kMpsToKt;
using units::kRadToDeg;
constexpr double kAftStop = -1.0 + 1e-9;

void require(double value, double lo, double hi, const char* name) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    char what[200];
    std::snprintf(what, sizeof what, "stall entry: %s = %g is not a finite number in %g..%g", name, value, lo, hi);
    throw std::invalid_argument(what);
  }
}
}  // namespace

void check(const StallEntryParameters& p) {
  require(p.entry_rate_kt_per_s, 0.1, 5.0, "entry_rate_kt_per_s");
  require(p.throttle, 0.0, 1.0, "throttle");
  require(p.recovery_throttle, 0.0, 1.0, "recovery_throttle");
  require(p.speed_to_pitch_deg_per_kt, 0.0, 10.0, "speed_to_pitch_deg_per_kt");
  require(p.speed_to_pitch_deg_per_kt_s, 0.0, 10.0, "speed_to_pitch_deg_per_kt_s");
  require(p.speed_rate_to_pitch_deg_per_kt_s, 0.0, 100.0, "speed_rate_to_pitch_deg_per_kt_s");
  require(p.speed_rate_filter_s, 0.01, 100.0, "speed_rate_filter_s");
  require(p.pitch_to_elevator_per_deg, 0.0, 1.0, "pitch_to_elevator_per_deg");
  require(p.pitch_to_elevator_per_deg_s, 0.0, 1.0, "pitch_to_elevator_per_deg_s");
  require(p.pitch_rate_to_elevator_per_dps, 0.0, 1.0, "pitch_rate_to_elevator_per_dps");
  require(p.roll_to_aileron_per_deg, 0.0, 1.0, "roll_to_aileron_per_deg");
  require(p.roll_rate_to_aileron_per_dps, 0.0, 1.0, "roll_rate_to_aileron_per_dps");
  require(p.aft_stop_hold_s, 0.1, 60.0, "aft_stop_hold_s");
  require(p.pitch_break_dps, 0.1, 90.0, "pitch_break_dps");
  require(p.pitch_break_hold_s, 0.0, 60.0, "pitch_break_hold_s");
}

const char* to_string(StallEntryPhase phase) {
  switch (phase) {
    case StallEntryPhase::kWaiting: return "waiting";
    case StallEntryPhase::kEntry: return "entry";
    case StallEntryPhase::kStalled: return "stalled";
  }
  return "?";
}

StallEntryPilot::StallEntryPilot(StallEntryParameters parameters) : p_(parameters) { check(p_); }

void StallEntryPilot::start(const PilotObservation& a) {
  phase_ = StallEntryPhase::kEntry;
  start_time_s_ = a.sim_time_s;
  start_cas_mps_ = a.cas_mps;
  start_theta_rad_ = a.theta_rad;
  start_elevator_ = a.elevator;
  elevator_trim_ = a.elevator_trim;
  elevator_ = previous_elevator_ = a.elevator;
  previous_cas_kt_ = a.cas_mps * kMpsToKt;
  speed_rate_kt_s_ = -p_.entry_rate_kt_per_s;  // as if already on the entry's slope
}

void StallEntryPilot::observe(const PilotObservation& a) {
  const bool finite = std::isfinite(a.sim_time_s) && std::isfinite(a.cas_mps) && std::isfinite(a.phi_rad) &&
                      std::isfinite(a.theta_rad) && std::isfinite(a.p_radps) && std::isfinite(a.q_radps) &&
                      std::isfinite(a.elevator) && std::isfinite(a.elevator_trim);
  if (!finite) return;  // a pilot does not act on a broken instrument: the controls stay put
  if (phase_ == StallEntryPhase::kWaiting) {
    start(a);
    last_time_s_ = a.sim_time_s;
    return;
  }
  const double dt_s = std::max(0.0, a.sim_time_s - last_time_s_);
  last_time_s_ = a.sim_time_s;
  // Wings level in every phase.
  aileron_ = std::clamp(-p_.roll_to_aileron_per_deg * a.phi_rad * kRadToDeg -
                            p_.roll_rate_to_aileron_per_dps * a.p_radps * kRadToDeg,
                        -1.0, 1.0);
  if (phase_ == StallEntryPhase::kEntry) {
    fly_entry(a, dt_s);
    watch_for_the_stall(a, dt_s);
  } else {
    fly_recovery(a, dt_s);
  }
}

void StallEntryPilot::fly_recovery(const PilotObservation& a, double dt_s) {
  // Lower the nose to the entry's pitch attitude and hold it (power up in sample()): the
  // angle of attack falls below the stall at once and the aircraft climbs away.
  const double pitch_error_deg = (start_theta_rad_ - a.theta_rad) * kRadToDeg;
  const double pitch_integral = recovery_integral_deg_s_ + pitch_error_deg * dt_s;
  const double wanted = elevator_for(pitch_error_deg, pitch_integral, a);
  elevator_ = std::clamp(wanted, -1.0, 1.0);
  if (wanted == elevator_) recovery_integral_deg_s_ = pitch_integral;
}

double StallEntryPilot::elevator_for(double pitch_error_deg, double pitch_integral_deg_s,
                                     const PilotObservation& a) const {
  return start_elevator_ - p_.pitch_to_elevator_per_deg * pitch_error_deg -
         p_.pitch_to_elevator_per_deg_s * pitch_integral_deg_s +
         p_.pitch_rate_to_elevator_per_dps * a.q_radps * kRadToDeg;
}

void StallEntryPilot::fly_entry(const PilotObservation& a, double dt_s) {
  const double cas_kt = a.cas_mps * kMpsToKt;
  const double reference_kt = start_cas_mps_ * kMpsToKt - p_.entry_rate_kt_per_s * (a.sim_time_s - start_time_s_);
  const double speed_error_kt = cas_kt - reference_kt;  // too fast: more nose up
  const double speed_integral = speed_integral_kt_s_ + speed_error_kt * dt_s;
  if (dt_s > 0) {
    const double raw_rate = (cas_kt - previous_cas_kt_) / dt_s;
    speed_rate_kt_s_ += (raw_rate - speed_rate_kt_s_) * std::min(1.0, dt_s / p_.speed_rate_filter_s);
  }
  previous_cas_kt_ = cas_kt;
  const double rate_error = speed_rate_kt_s_ + p_.entry_rate_kt_per_s;  // slowing too little: > 0
  const double pitch_command_deg = start_theta_rad_ * kRadToDeg + p_.speed_to_pitch_deg_per_kt * speed_error_kt +
                                   p_.speed_to_pitch_deg_per_kt_s * speed_integral +
                                   p_.speed_rate_to_pitch_deg_per_kt_s * rate_error;
  const double pitch_error_deg = pitch_command_deg - a.theta_rad * kRadToDeg;
  const double pitch_integral = pitch_integral_deg_s_ + pitch_error_deg * dt_s;
  const double wanted = elevator_for(pitch_error_deg, pitch_integral, a);
  previous_elevator_ = elevator_;
  elevator_ = std::clamp(wanted, -1.0, 1.0);
  // Integrate only while the elevator can still act on it (no wind-up against a stop).
  if (wanted == elevator_) {
    speed_integral_kt_s_ = speed_integral;
    pitch_integral_deg_s_ = pitch_integral;
  }
}

void StallEntryPilot::watch_for_the_stall(const PilotObservation& a, double dt_s) {
  aft_stop_s_ = elevator_ <= kAftStop ? aft_stop_s_ + dt_s : 0.0;
  if (aft_stop_s_ >= p_.aft_stop_hold_s) {
    identify(a, "elevator at the aft stop");
    return;
  }
  const bool nose_falling = a.q_radps * kRadToDeg < -p_.pitch_break_dps;
  const bool pulling = elevator_ <= previous_elevator_ && elevator_ < start_elevator_;
  pitch_break_s_ = nose_falling && pulling ? pitch_break_s_ + dt_s : 0.0;
  if (nose_falling && pulling && pitch_break_s_ >= p_.pitch_break_hold_s) identify(a, "pitch break");
}

void StallEntryPilot::identify(const PilotObservation& a, const char* indication) {
  phase_ = StallEntryPhase::kStalled;
  stall_time_s_ = a.sim_time_s;
  stall_cas_mps_ = a.cas_mps;
  stall_indication_ = indication;
}

void StallEntryPilot::sample(double /*sim_time_s*/, ControlInputs& controls) {
  if (phase_ == StallEntryPhase::kWaiting) return;
  controls[Channel::kElevator] = std::clamp(elevator_ - elevator_trim_, -1.0, 1.0);
  controls[Channel::kAileron] = aileron_;
  const double throttle = phase_ == StallEntryPhase::kStalled ? p_.recovery_throttle : p_.throttle;
  for (Channel c : {Channel::kThrottle1, Channel::kThrottle2, Channel::kThrottle3, Channel::kThrottle4}) {
    controls[c] = throttle;
  }
}

std::string StallEntryPilot::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "stall entry pilot (%.2g kt/s, throttle %.2g, wings level)",
                p_.entry_rate_kt_per_s, p_.throttle);
  return text;
}

}  // namespace fedsim::io
