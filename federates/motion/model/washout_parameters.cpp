#include "motion/model/washout_parameters.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "common/control/parameter_checks.hpp"
#include "common/units/units.hpp"

namespace fedsim::motion {
namespace {

constexpr const char* kBlock = "ClassicalWashoutParameters";

[[noreturn]] void fail(const std::string& field, double value, const std::string& problem) {
  std::ostringstream message;
  message.precision(9);
  message << kBlock << ": " << field << " = " << value << " " << problem;
  throw std::invalid_argument(message.str());
}

// lower < value <= upper (lower_open) or lower <= value <= upper.
void require_range(const std::string& field, double value, double lower, double upper,
                   bool lower_open) {
  const bool above = lower_open ? value > lower : value >= lower;
  if (!std::isfinite(value) || !above || !(value <= upper)) {
    std::ostringstream range;
    range << "must be in " << (lower_open ? "(" : "[") << lower << ", " << upper << "]";
    fail(field, value, range.str());
  }
}

void require_frequency(const std::string& field, double value, double dt_s) {
  require_range(field, value, 0.0, units::kPi / dt_s, true);
  if (value == units::kPi / dt_s) fail(field, value, "must be below Nyquist pi/dt_s");
}

// What every channel has, a gain K in [0, 1] and a second-order filter (wn below Nyquist, zeta
// in (0, 5]), checked as "<channel>.gain", "<channel>.natural_frequency_radps", ...
void require_channel(const std::string& channel, double gain, double natural_frequency_radps,
                     double damping_ratio, double dt_s) {
  constexpr double kMaxDamping = 5.0;
  require_range(channel + ".gain", gain, 0.0, 1.0, false);
  require_frequency(channel + ".natural_frequency_radps", natural_frequency_radps, dt_s);
  require_range(channel + ".damping_ratio", damping_ratio, 0.0, kMaxDamping, true);
}

std::string indexed(const char* group, int i) {
  return std::string(group) + "[" + std::to_string(i) + "]";
}

}  // namespace

void validate(const ClassicalWashoutParameters& p, double dt_s) {
  control::require_sample_period(kBlock, dt_s);
  for (int i = 0; i < 3; ++i) {
    const TranslationalChannelParameters& t = p.translational[i];
    const std::string translational = indexed("translational", i);
    require_channel(translational, t.gain, t.natural_frequency_radps, t.damping_ratio, dt_s);
    require_frequency(translational + ".break_frequency_radps", t.break_frequency_radps, dt_s);
    const RotationalChannelParameters& r = p.rotational[i];
    require_channel(indexed("rotational", i), r.gain, r.natural_frequency_radps, r.damping_ratio,
                    dt_s);
  }
  const TiltCoordinationParameters& tilt = p.tilt;
  require_channel("tilt", tilt.gain, tilt.natural_frequency_radps, tilt.damping_ratio, dt_s);
  require_range("tilt.rate_limit_radps", p.tilt.rate_limit_radps, 0.0, 20.0 * units::kDegToRad,
                true);
  require_range("tilt.angle_limit_rad", p.tilt.angle_limit_rad, 0.0, 45.0 * units::kDegToRad, true);
  require_range("specific_force_limit_mps2", p.specific_force_limit_mps2, 0.0, 100.0, true);
  require_range("gravity_mps2", p.gravity_mps2, 9.0, 10.5, false);
}

}  // namespace fedsim::motion
