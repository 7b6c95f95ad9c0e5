#include "flight/model/systems/wing_leveller.hpp"

#include <algorithm>
#include <cmath>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

namespace {
// |K| above this is no aileron gain an aircraft could fly (JSBSim's C172 uses 50 per rad).
constexpr double kMaxGain = 1000.0;
}  // namespace

void WingLeveller::Params::validate() const {
  namespace pc = param_checks;
  pc::in_range(bank_gain_per_rad, -kMaxGain, kMaxGain, "bank_gain_per_rad");
  pc::in_range(bank_integral_gain_per_rad_s, -kMaxGain, kMaxGain, "bank_integral_gain_per_rad_s");
  pc::in_range(bank_rate_gain_per_radps, -kMaxGain, kMaxGain, "bank_rate_gain_per_radps");
}

WingLeveller::WingLeveller(Params params) : params_(params) { params_.validate(); }

void WingLeveller::reset() { outputs_ = Outputs{}; }

double WingLeveller::bank_rate_radps(double p_radps, double q_radps, double r_radps,
                                     double bank_rad, double pitch_rad) {
  const double cos_theta = std::cos(pitch_rad);
  if (std::abs(cos_theta) < 1e-3) return p_radps;
  return p_radps + (q_radps * std::sin(bank_rad) + r_radps * std::cos(bank_rad)) *
                       (std::sin(pitch_rad) / cos_theta);
}

void WingLeveller::step(double dt_s, const Inputs& in) {
  const bool finite = std::isfinite(in.bank_rad) && std::isfinite(in.bank_rate_radps) &&
                      std::isfinite(in.pilot_aileron_command) && dt_s >= 0.0 && std::isfinite(dt_s);
  outputs_.active = in.engaged && finite && !(params_.airborne_only && in.weight_on_wheels);
  if (!outputs_.active) {
    outputs_.aileron_command = 0.0;
    outputs_.integral = 0.0;  // JSBSim's trigger -1: the integrator resets
    return;
  }
  const Params& k = params_;
  const double pilot = std::clamp(in.pilot_aileron_command, -1.0, 1.0);
  const double pd = -(k.bank_gain_per_rad * in.bank_rad + k.bank_rate_gain_per_radps * in.bank_rate_radps);
  const double integrated = outputs_.integral + k.bank_integral_gain_per_rad_s * in.bank_rad * dt_s;
  // Conditional integration: keep the integral when the sum is beyond a stop and the new
  // integral would push it further beyond.
  const double sum_now = pilot + pd - outputs_.integral;
  const double sum_next = pilot + pd - integrated;
  const bool winds_up = std::abs(sum_now) > 1.0 && std::abs(sum_next) > std::abs(sum_now);
  if (!winds_up) outputs_.integral = integrated;
  const double command = pd - outputs_.integral;
  outputs_.aileron_command = std::clamp(command, -1.0 - pilot, 1.0 - pilot);
}

}  // namespace fedsim::flight
