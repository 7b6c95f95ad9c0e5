// The flow angles an aircraft pack's aerodynamic data cover, and how the model leaves them.
#include "flight/model/aircraft/aero_flow_envelope.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight {

namespace {

// The span [lo, hi] of one flow angle over the tables that read it (directly or as |angle|).
struct Span {
  bool found = false;
  double lo = 0.0;
  double hi = 0.0;  // starts at 0: the data are about the undisturbed flow

  void add(double from, double to) {
    if (!std::isfinite(from) || !std::isfinite(to)) return;
    found = true;
    lo = std::min(lo, from);
    hi = std::max(hi, to);
  }
};

void collect(const AeroLookup& lookup, Span& alpha, Span& beta) {
  for (int i = 0; i < lookup.dimensions(); ++i) {
    const std::size_t slot = lookup.input_slots()[static_cast<std::size_t>(i)];
    const AeroLookup::Range& r = lookup.input_ranges()[static_cast<std::size_t>(i)];
    if (slot == slot_of(AeroVariable::alpha_rad)) alpha.add(r.lo, r.hi);
    if (slot == slot_of(AeroVariable::abs_alpha_rad)) alpha.add(-r.hi, r.hi);
    if (slot == slot_of(AeroVariable::beta_rad)) beta.add(r.lo, r.hi);
    if (slot == slot_of(AeroVariable::abs_beta_rad)) beta.add(-r.hi, r.hi);
  }
}

// 1 at and inside the edge, cos^2 down to 0 at kTransitionRad beyond it (smooth at both ends).
double fade(double beyond_edge_rad) {
  if (!(beyond_edge_rad > 0.0)) return 1.0;
  if (beyond_edge_rad >= AeroFlowEnvelope::kTransitionRad) return 0.0;
  const double c = std::cos(0.5 * units::kPi * beyond_edge_rad / AeroFlowEnvelope::kTransitionRad);
  return c * c;
}
}  // namespace

AeroFlowEnvelope::AeroFlowEnvelope(const AeroModelSpec& model) {
  Span alpha, beta;
  for (const AeroTerm& factor : model.factors) collect(factor.lookup, alpha, beta);
  for (const auto& axis : model.axes) {
    for (const AeroTerm& term : axis) collect(term.lookup, alpha, beta);
  }
  // Caps: the weight is 0 at alpha = +-180 deg (alpha flips sign there), and at beta = +-90
  // deg whenever the coefficients depend on alpha (alpha is undefined in a sideways flow).
  const double alpha_cap = units::kPi - kTransitionRad;
  const double beta_cap = 0.5 * units::kPi - kTransitionRad;
  if (alpha.found) {
    limits_alpha_ = true;
    alpha_min_rad_ = std::max(alpha.lo, -alpha_cap);
    alpha_max_rad_ = std::min(alpha.hi, alpha_cap);
  }
  if (beta.found || alpha.found) {
    limits_beta_ = true;
    beta_min_rad_ = beta.found ? std::max(beta.lo, -beta_cap) : -beta_cap;
    beta_max_rad_ = beta.found ? std::min(beta.hi, beta_cap) : beta_cap;
  }
}

double AeroFlowEnvelope::limited_alpha(double alpha_rad) const {
  return limits_alpha_ ? std::clamp(alpha_rad, alpha_min_rad_, alpha_max_rad_) : alpha_rad;
}

double AeroFlowEnvelope::limited_beta(double beta_rad) const {
  return limits_beta_ ? std::clamp(beta_rad, beta_min_rad_, beta_max_rad_) : beta_rad;
}

double AeroFlowEnvelope::attached_weight(double alpha_rad, double beta_rad) const {
  double weight = 1.0;
  if (limits_alpha_) {
    weight *= fade(std::max(alpha_min_rad_ - alpha_rad, alpha_rad - alpha_max_rad_));
  }
  if (limits_beta_) {
    weight *= fade(std::max(beta_min_rad_ - beta_rad, beta_rad - beta_max_rad_));
  }
  return weight;
}

double AeroFlowEnvelope::wing_plane_incidence(double alpha_rad, double beta_rad) {
  // Unit air-relative velocity (cos a cos b, sin b, sin a cos b): its body-z component.
  return std::asin(std::clamp(std::sin(alpha_rad) * std::cos(beta_rad), -1.0, 1.0));
}

double AeroFlowEnvelope::forward_equivalent_alpha(double alpha_rad) {
  if (std::abs(alpha_rad) <= 0.5 * units::kPi) return alpha_rad;
  return std::copysign(units::kPi, alpha_rad) - alpha_rad;
}

}  // namespace fedsim::flight
