// Propeller blade-angle control: fixed pitch, or a constant-speed unit with feathering.
#include "flight/model/systems/propeller_governor.hpp"

#include <algorithm>
#include <cmath>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

void PropellerGovernor::Params::validate() const {
  namespace pc = param_checks;
  pc::finite(fine_pitch_rad, "fine_pitch_rad");
  if (!constant_speed) return;
  if (!(coarse_pitch_rad > fine_pitch_rad)) {
    pc::fail("coarse_pitch_rad", "must exceed fine_pitch_rad", coarse_pitch_rad);
  }
  if (!(feather_pitch_rad >= coarse_pitch_rad) || !std::isfinite(feather_pitch_rad)) {
    pc::fail("feather_pitch_rad", "must be finite and >= coarse_pitch_rad", feather_pitch_rad);
  }
  pc::positive(governor_max_rpm, "governor_max_rpm");
  pc::in_range(governor_min_rpm, 0.0, governor_max_rpm, "governor_min_rpm");
  pc::positive(gain_radps_per_rpm, "gain_radps_per_rpm");
  pc::positive(pitch_rate_limit_radps, "pitch_rate_limit_radps");
}

PropellerGovernor::PropellerGovernor(Params params) : params_(params) {
  params_.validate();
  reset();
}

void PropellerGovernor::reset() { reset(params_.fine_pitch_rad); }

void PropellerGovernor::reset(double blade_angle_rad) {
  const double upper = params_.constant_speed ? params_.feather_pitch_rad : params_.fine_pitch_rad;
  outputs_.blade_angle_rad = std::clamp(blade_angle_rad, params_.fine_pitch_rad, upper);
  outputs_.selected_rpm = selected_rpm(1.0);
}

double PropellerGovernor::selected_rpm(double lever) const {
  const double pl = std::isnan(lever) ? 1.0 : std::clamp(lever, 0.0, 1.0);
  return std::max(params_.governor_min_rpm, params_.governor_max_rpm * pl * pl);  // eq. 3.113
}

double PropellerGovernor::blade_rate_radps(const Inputs& in) const {
  const double limit = params_.pitch_rate_limit_radps;
  if (in.feather) return limit;
  const double beta = outputs_.blade_angle_rad;
  if (beta > params_.coarse_pitch_rad) return -limit;  // unfeathering back into range
  const double overspeed_rpm =
      std::isnan(in.engine_rpm) ? 0.0 : in.engine_rpm - outputs_.selected_rpm;
  return std::clamp(params_.gain_radps_per_rpm * overspeed_rpm, -limit, limit);
}

void PropellerGovernor::step(double dt_s, const Inputs& in) {
  outputs_.selected_rpm = selected_rpm(in.lever);
  if (!params_.constant_speed || !(dt_s > 0.0)) return;
  const double beta = outputs_.blade_angle_rad;
  const double next = beta + blade_rate_radps(in) * dt_s;
  if (in.feather) {
    outputs_.blade_angle_rad = std::min(next, params_.feather_pitch_rad);
  } else if (beta > params_.coarse_pitch_rad) {
    outputs_.blade_angle_rad = std::max(next, params_.coarse_pitch_rad);
  } else {
    outputs_.blade_angle_rad = std::clamp(next, params_.fine_pitch_rad, params_.coarse_pitch_rad);
  }
}

}  // namespace fedsim::flight
