// The flow angles an aircraft pack's aerodynamic data cover, and how the model leaves them.
#pragma once

#include <numbers>

#include "flight/model/aircraft/aero_variable.hpp"
#include "flight/model/aircraft/pack_aerodynamics.hpp"

namespace fedsim::flight {

/// A pack's coefficient build-up is small-disturbance data: tables over a few degrees of
/// alpha and beta (the C172's run from -10 to +21 deg of alpha and +-20 deg of beta) plus
/// terms linear in alpha or beta. The air data give alpha = atan2(w, u) in (-180, 180] deg and
/// beta = asin(v / V) in [-90, 90] deg, and on the ground any wind direction is possible: a
/// tailwind puts alpha near +-180 deg (where it flips sign as w does), a direct crosswind
/// puts beta near +-90 deg (where alpha is undefined, u and w both ~0). Extrapolating the
/// linear terms there gives nonsense (the C172 at alpha -179 deg: CL -14.6, Cm +5.7).
///
/// The envelope is the range of alpha and of beta that the pack's tables span (taken from
/// their breakpoints, always including 0). Aerodynamics evaluates the pack's coefficients with
/// alpha and beta limited to the envelope and weights them by attached_weight(): 1 inside,
/// falling as cos^2 to 0 over kTransitionRad outside. The rest of the weight goes to separated
/// flow (drag along the air-relative velocity and the pack's moments, both at the wing-plane
/// incidence), so forces and moments stay bounded and continuous for every flow direction.
/// The envelope is capped so that the weight reaches 0 before alpha reaches +-180 deg and,
/// when the pack's coefficients depend on alpha, before beta reaches +-90 deg. A pack without
/// alpha (beta) tables is not limited in alpha (beta): the NASA check-case bodies keep their
/// exact behaviour.
class AeroFlowEnvelope {
 public:
  /// Width of the fade from the pack's data to separated flow beyond the envelope's edges.
  static constexpr double kTransitionRad = 30.0 * std::numbers::pi / 180.0;

  /// Unlimited (no fade, no limits).
  AeroFlowEnvelope() = default;
  /// From the breakpoints of the tables of a pack's terms and factors.
  explicit AeroFlowEnvelope(const AeroModelSpec& model);

  bool limits_alpha() const { return limits_alpha_; }
  bool limits_beta() const { return limits_beta_; }
  double alpha_min_rad() const { return alpha_min_rad_; }
  double alpha_max_rad() const { return alpha_max_rad_; }
  double beta_min_rad() const { return beta_min_rad_; }
  double beta_max_rad() const { return beta_max_rad_; }

  /// alpha and beta held inside the envelope (unchanged inside it).
  double limited_alpha(double alpha_rad) const;
  double limited_beta(double beta_rad) const;
  /// Share of the pack's attached-flow coefficients: 1 inside, 0 from kTransitionRad outside.
  double attached_weight(double alpha_rad, double beta_rad) const;

  /// The incidence of the flow on the wing plane (body x-y), asin(w / V): alpha where the
  /// flow is in the plane of symmetry and ahead of the wing, near 0 for a tailwind or a
  /// crosswind; defined and continuous for every flow direction.
  static double wing_plane_incidence(double alpha_rad, double beta_rad);
  /// alpha of the same flow seen from ahead: alpha within +-90 deg, else 180 deg - alpha
  /// (sign kept), so that a tailwind (alpha near +-180) is not taken for a stall.
  static double forward_equivalent_alpha(double alpha_rad);

 private:
  bool limits_alpha_ = false;
  bool limits_beta_ = false;
  double alpha_min_rad_ = -std::numbers::pi;
  double alpha_max_rad_ = std::numbers::pi;
  double beta_min_rad_ = -std::numbers::pi / 2;
  double beta_max_rad_ = std::numbers::pi / 2;
};

}  // namespace fedsim::flight
