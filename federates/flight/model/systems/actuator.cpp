// Control-surface actuator: normalised command to surface deflection with lag, rate and
// position limits.
#include "flight/model/systems/actuator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

void Actuator::Params::validate() const {
  namespace pc = param_checks;
  pc::in_range(command_min, -1.0, 0.0, "command_min");
  pc::finite(deflection_at_plus_one_rad, "deflection_at_plus_one_rad");
  pc::finite(deflection_at_minus_one_rad, "deflection_at_minus_one_rad");
  pc::non_negative(time_constant_s, "time_constant_s");
  if (!(rate_limit_radps > 0.0)) pc::fail("rate_limit_radps", "must be positive", rate_limit_radps);
  if (std::isnan(position_min_rad))
    pc::fail("position_min_rad", "must not be NaN", position_min_rad);
  if (!(position_max_rad > position_min_rad)) {
    pc::fail("position_max_rad", "must exceed position_min_rad", position_max_rad);
  }
}

Actuator::Actuator(Params params) : params_(params) {
  params_.validate();
  reset();
}

void Actuator::reset(double position_rad) {
  outputs_.position_rad = clamp_to_stops(position_rad);
  outputs_.rate_radps = 0.0;
  outputs_.demand_rad = outputs_.position_rad;
}

double Actuator::demand_for(double command) const {
  if (std::isnan(command)) command = 0.0;  // a lost input centres the demand, never NaN
  const double c = std::clamp(command, params_.command_min, 1.0);
  return c >= 0.0 ? c * params_.deflection_at_plus_one_rad
                  : -c * params_.deflection_at_minus_one_rad;
}

double Actuator::clamp_to_stops(double position_rad) const {
  return std::clamp(position_rad, params_.position_min_rad, params_.position_max_rad);
}

void Actuator::step(double dt_s, const Inputs& inputs) {
  if (!(dt_s > 0.0)) return;
  const double demand = demand_for(inputs.command);
  const double previous = outputs_.position_rad;

  // Exact solution of the first-order lag over the step (no step-size stability limit).
  double change = demand - previous;
  if (params_.time_constant_s > 0.0) change *= -std::expm1(-dt_s / params_.time_constant_s);

  const double max_change = params_.rate_limit_radps * dt_s;
  change = std::clamp(change, -max_change, max_change);

  outputs_.position_rad = clamp_to_stops(previous + change);
  outputs_.rate_radps = (outputs_.position_rad - previous) / dt_s;
  outputs_.demand_rad = demand;
}

}  // namespace fedsim::flight
