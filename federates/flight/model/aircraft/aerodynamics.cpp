// Aerodynamic coefficient build-up and wind-to-body force transformation (seed 3.3-3.5).
#include "flight/model/aircraft/aerodynamics.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <stdexcept>

namespace fedsim::flight {

namespace {

double flap_travel_of(const AircraftPack& pack) {
  return pack.flight_controls.flaps ? pack.flight_controls.flaps->full_travel_rad : 0.0;
}
}  // namespace

Aerodynamics::Aerodynamics(const AircraftPack& pack)
    : Aerodynamics(pack.aerodynamics, pack.geometry, flap_travel_of(pack)) {}

Aerodynamics::Aerodynamics(const AeroModelSpec& model, const aircraft_pack::ReferenceGeometry& geometry,
                           double flap_full_travel_rad)
    : model_(model),
      geometry_(geometry),
      flap_full_travel_deg_(flap_full_travel_rad * units::kRadToDeg),
      envelope_(model_) {
  if (model_.factors.size() > AeroModelSpec::kMaxFactors) {
    throw std::invalid_argument("Aerodynamics: too many factors");
  }
  if (!(geometry_.wing_area_m2 > 0.0 && geometry_.wing_span_m > 0.0 &&
        geometry_.mean_chord_m > 0.0)) {
    throw std::invalid_argument("Aerodynamics: reference area, span and chord must be positive");
  }
}

Eigen::Matrix3d Aerodynamics::body_from_wind(double alpha_rad, double beta_rad) {
  // Columns are the wind axes expressed in body axes: x_w along the air-relative velocity
  // (cos a cos b, sin b, sin a cos b), z_w in the plane of symmetry (seed 3.5.3).
  const double ca = std::cos(alpha_rad), sa = std::sin(alpha_rad);
  const double cb = std::cos(beta_rad), sb = std::sin(beta_rad);
  Eigen::Matrix3d m;
  m << ca * cb, -ca * sb, -sa,  //
      sb, cb, 0.0,              //
      sa * cb, -sa * sb, ca;
  return m;
}

void Aerodynamics::fill_variables(const Inputs& in, double alpha_rad, double beta_rad,
                                  bool stall_hysteresis, Slots& s) const {
  auto set = [&s](AeroVariable v, double value) { s[slot_of(v)] = value; };
  const double b = geometry_.wing_span_m;
  const double c = geometry_.mean_chord_m;
  // b/2V and c/2V: zero at (near) rest, where every rate term vanishes with V.
  const bool moving = in.tas_mps > kMinAirspeedForRatesMps;
  const double b_2v = moving ? b / (2.0 * in.tas_mps) : 0.0;
  const double c_2v = moving ? c / (2.0 * in.tas_mps) : 0.0;

  set(AeroVariable::alpha_rad, alpha_rad);
  set(AeroVariable::abs_alpha_rad, std::abs(alpha_rad));
  set(AeroVariable::beta_rad, beta_rad);
  set(AeroVariable::abs_beta_rad, std::abs(beta_rad));
  set(AeroVariable::mach, in.mach);
  set(AeroVariable::qbar_pa, in.qbar_pa);
  set(AeroVariable::p_hat, in.omega_air_body.x() * b_2v);
  set(AeroVariable::q_hat, in.omega_air_body.y() * c_2v);
  set(AeroVariable::r_hat, in.omega_air_body.z() * b_2v);
  set(AeroVariable::alphadot_hat, in.alphadot_radps * c_2v);
  set(AeroVariable::betadot_hat, in.betadot_radps * b_2v);
  set(AeroVariable::elevator_rad, in.elevator_rad);
  set(AeroVariable::abs_elevator_rad, std::abs(in.elevator_rad));
  set(AeroVariable::aileron_rad, in.aileron_rad);
  set(AeroVariable::abs_aileron_rad, std::abs(in.aileron_rad));
  set(AeroVariable::rudder_rad, in.rudder_rad);
  set(AeroVariable::abs_rudder_rad, std::abs(in.rudder_rad));
  set(AeroVariable::flap_norm, in.flap_norm);
  set(AeroVariable::flap_deg, in.flap_norm * flap_full_travel_deg_);
  set(AeroVariable::gear_norm, in.gear_norm);
  set(AeroVariable::speedbrake_norm, in.speedbrake_norm);
  set(AeroVariable::spoiler_norm, in.spoiler_norm);
  set(AeroVariable::h_over_b, in.aero_rp_height_agl_m / b);
  set(AeroVariable::stall_hysteresis, stall_hysteresis ? 1.0 : 0.0);
  set(AeroVariable::cl_squared, 0.0);  // filled once the lift axis is summed
  // Factors read variables only, so one pass in pack order fills them.
  for (std::size_t i = 0; i < model_.factors.size(); ++i) {
    s[kAeroVariableCount + i] = model_.factors[i].evaluate(s);
  }
}

double Aerodynamics::sum_axis(AeroAxis axis, const Slots& slots) const {
  double sum = 0.0;
  for (const auto& term : model_.terms(axis)) sum += term.evaluate(slots);
  return sum;
}

Aerodynamics::Outputs Aerodynamics::evaluate(const Inputs& in) {
  if (model_.stall_hysteresis) {
    // A flow from behind (alpha near +-180 deg) is not a stall of the wing.
    const double alpha = AeroFlowEnvelope::forward_equivalent_alpha(in.alpha_rad);
    if (alpha > model_.stall_hysteresis->alpha_set_rad) stalled_ = true;
    if (alpha < model_.stall_hysteresis->alpha_clear_rad) stalled_ = false;
  }
  return compute(in, stalled_);
}

void Aerodynamics::sum_coefficients(const Inputs& in, double alpha_rad, double beta_rad,
                                    bool stall_hysteresis, Outputs& out) const {
  Slots slots{};
  fill_variables(in, alpha_rad, beta_rad, stall_hysteresis, slots);
  out.CL = sum_axis(AeroAxis::lift, slots);
  slots[slot_of(AeroVariable::cl_squared)] = out.CL * out.CL;
  out.CD = sum_axis(AeroAxis::drag, slots);
  out.CY = sum_axis(AeroAxis::side_force, slots);
  out.Cl = sum_axis(AeroAxis::roll_moment, slots);
  out.Cm = sum_axis(AeroAxis::pitch_moment, slots);
  out.Cn = sum_axis(AeroAxis::yaw_moment, slots);
}

void Aerodynamics::blend_separated_flow(const Inputs& in, bool stall_hysteresis, double w,
                                        Outputs& out) const {
  // Separated flow: no lift and no side force (their wind axes lose meaning as the flow turns
  // along the span or comes from behind), the pack's drag along the flow, and the pack's
  // moments (weathercock, pitch stiffness, damping), all at the wing-plane incidence: about
  // the head-on values for a tailwind or a crosswind, the edge of the data in a flat fall.
  Outputs separated;
  const double incidence = AeroFlowEnvelope::wing_plane_incidence(in.alpha_rad, in.beta_rad);
  sum_coefficients(in, envelope_.limited_alpha(incidence), envelope_.limited_beta(in.beta_rad),
                   stall_hysteresis, separated);
  const double s = 1.0 - w;
  out.CL *= w;
  out.CY *= w;
  out.CD = w * out.CD + s * separated.CD;
  out.Cl = w * out.Cl + s * separated.Cl;
  out.Cm = w * out.Cm + s * separated.Cm;
  out.Cn = w * out.Cn + s * separated.Cn;
}

Aerodynamics::Outputs Aerodynamics::compute(const Inputs& in, bool stall_hysteresis) const {
  Outputs out;
  out.stall_hysteresis = stall_hysteresis;
  sum_coefficients(in, envelope_.limited_alpha(in.alpha_rad), envelope_.limited_beta(in.beta_rad),
                   stall_hysteresis, out);
  out.attached_weight = envelope_.attached_weight(in.alpha_rad, in.beta_rad);
  if (out.attached_weight < 1.0) {
    blend_separated_flow(in, stall_hysteresis, out.attached_weight, out);
  }

  const double qbar_s = in.qbar_pa * geometry_.wing_area_m2;
  out.lift_n = qbar_s * out.CL;
  out.drag_n = qbar_s * out.CD;
  out.side_force_n = qbar_s * out.CY;
  const Eigen::Vector3d force_w(-out.drag_n, out.side_force_n, -out.lift_n);
  out.force_body = body_from_wind(in.alpha_rad, in.beta_rad) * force_w;
  out.moment_body = qbar_s * Eigen::Vector3d(geometry_.wing_span_m * out.Cl,
                                          geometry_.mean_chord_m * out.Cm,
                                          geometry_.wing_span_m * out.Cn);
  return out;
}

}  // namespace fedsim::flight
