// Autothrottle: the thrust-lever command for the active thrust mode.
//   SPEED    throttle = PID(CAS_sel - CAS) (derivative filtered: it damps the speed loop through
//            the engines' 1.3-2.3 s spool lag), 0..1;
//   N1       the climb setting;   THR HLD / RETARD: idle;
//   GA       throttle = PI(climb-rate target - climb rate): the 737's reduced go-around thrust
//            (a 1000-2000 ft/min climb, FCOM "Automatic Flight: go-around");
//   ARM      the levers stay where they are (the pilot's).
// Every setting reaches the levers through a rate limit (lever_rate, retard_rate for RETARD and
// THR HLD), so no mode change moves the levers in a step; the PID and PI engage bumplessly
// from the present lever position when their mode starts.
#pragma once

#include "common/control/pid.hpp"
#include "common/control/rate_limiter.hpp"
#include "flight/model/afcs/afcs_modes.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

class Autothrottle {
 public:
  Autothrottle(const AutothrottleGains& gains, double dt_s);
  /// Takes over at the present lever position (engagement or a mode change).
  void engage(double throttle);
  /// The lever command for the mode; `cas_error_mps` = selected - measured CAS,
  /// `climb_rate_error_mps` = target - measured climb rate (GA).
  double step(ThrustMode mode, double cas_error_mps, double climb_rate_error_mps, double throttle_now);
  double throttle() const { return limiter_.output(); }

 private:
  AutothrottleGains gains_;
  control::Pid speed_;
  control::Pid climb_;
  control::RateLimiter limiter_;
  control::RateLimiter retard_;
  ThrustMode mode_ = ThrustMode::kNone;
};

}  // namespace fedsim::flight::afcs
