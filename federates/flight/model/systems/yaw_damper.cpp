#include "flight/model/systems/yaw_damper.hpp"

#include <algorithm>
#include <cmath>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

void YawDamper::Params::validate() const {
  namespace pc = param_checks;
  if (gain_per_radps.empty()) throw std::invalid_argument("gain_per_radps must not be empty");
  for (double k : gain_per_radps.values()) pc::finite(k, "gain_per_radps");
  pc::non_negative(washout_time_constant_s, "washout_time_constant_s");
  if (!(authority > 0.0 && authority <= 1.0)) pc::fail("authority", "must lie in (0, 1]", authority);
}

YawDamper::YawDamper(Params params) : params_(std::move(params)) { params_.validate(); }

double YawDamper::command(double washed_rate_radps, double mach) const {
  const double c = params_.gain_per_radps(mach) * washed_rate_radps;
  return std::clamp(c, -params_.authority, params_.authority);
}

void YawDamper::reset(double yaw_rate_radps, double mach, bool engaged) {
  const double r = std::isfinite(yaw_rate_radps) ? yaw_rate_radps : 0.0;
  const double m = std::isfinite(mach) ? mach : 0.0;
  const bool washout = params_.washout_time_constant_s > 0.0;
  low_pass_radps_ = washout ? r : 0.0;
  outputs_.rudder_command = engaged && !washout ? command(r, m) : 0.0;
}

void YawDamper::step(double dt_s, const Inputs& in) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) return;
  const double r = std::isfinite(in.yaw_rate_radps) ? in.yaw_rate_radps : 0.0;
  const double m = std::isfinite(in.mach) ? in.mach : 0.0;
  double washed = r;
  if (params_.washout_time_constant_s > 0.0) {
    low_pass_radps_ += (r - low_pass_radps_) * (1.0 - std::exp(-dt_s / params_.washout_time_constant_s));
    washed = r - low_pass_radps_;
  }
  outputs_.rudder_command = in.engaged ? command(washed, m) : 0.0;
}

}  // namespace fedsim::flight
