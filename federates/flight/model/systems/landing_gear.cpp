// Landing gear and other ground contacts: spring-damper struts on a level runway plane with
// rolling, braking and cornering friction.
#include "flight/model/systems/landing_gear.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

namespace {
const Eigen::Vector3d kUpNed(0.0, 0.0, -1.0);

double clamp_or_zero(double x, double lo, double hi) {
  return std::isnan(x) ? 0.0 : std::clamp(x, lo, hi);
}

// Linear blend of Coulomb friction to zero inside the viscous band around standstill.
double blend(double speed_mps, double band_mps) {
  return std::min(std::abs(speed_mps) / band_mps, 1.0);
}

// Unit ground-plane (horizontal) vectors along and to the right of a wheel's heading.
struct GroundAxes {
  Eigen::Vector3d along;
  Eigen::Vector3d right;
};

GroundAxes wheel_ground_axes(const Eigen::Matrix3d& body_from_ned, double steer_rad) {
  const Eigen::Vector3d heading_body(std::cos(steer_rad), std::sin(steer_rad), 0.0);
  const Eigen::Vector3d heading_ned = body_from_ned.transpose() * heading_body;
  Eigen::Vector3d along(heading_ned.x(), heading_ned.y(), 0.0);
  const double n = along.norm();
  // A wheel pointing straight up or down has no ground heading; pick north (no rolling
  // contact exists in that attitude anyway).
  along = n > 1e-9 ? Eigen::Vector3d(along / n) : Eigen::Vector3d::UnitX();
  return {along, Eigen::Vector3d(-along.y(), along.x(), 0.0)};
}

std::string field(std::size_t i, const char* name) {
  return "contacts[" + std::to_string(i) + "]." + name;
}
}  // namespace

void LandingGear::Params::validate() const {
  namespace pc = param_checks;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    pc::finite(c.position_m, field(i, "position_m"));
    pc::positive(c.spring_npm, field(i, "spring_npm"));
    pc::non_negative(c.damping_compression_nspm, field(i, "damping_compression_nspm"));
    pc::non_negative(c.damping_rebound_nspm, field(i, "damping_rebound_nspm"));
    pc::non_negative(c.static_friction, field(i, "static_friction"));
    pc::in_range(c.dynamic_friction, 0.0, c.static_friction, field(i, "dynamic_friction"));
    pc::in_range(c.rolling_friction, 0.0, c.static_friction, field(i, "rolling_friction"));
    pc::in_range(c.max_steer_rad, 0.0, std::numbers::pi / 2, field(i, "max_steer_rad"));
    pc::positive(c.cornering_saturation_slip_rad, field(i, "cornering_saturation_slip_rad"));
  }
  pc::positive(friction_blend_speed_mps, "friction_blend_speed_mps");
}

LandingGear::LandingGear(Params params) : params_((params.validate(), std::move(params))) {
  outputs_.contacts.resize(params_.contacts.size());
  reset();
}

void LandingGear::reset() {
  outputs_.force_body_n.setZero();
  outputs_.moment_datum_body_nm.setZero();
  outputs_.weight_on_wheels = false;
  std::fill(outputs_.contacts.begin(), outputs_.contacts.end(), ContactOutput{});
}

double LandingGear::damping_ratio(double spring_npm, double damping_nspm,
                                  double supported_mass_kg) {
  return damping_nspm / (2.0 * std::sqrt(spring_npm * supported_mass_kg));
}

void LandingGear::contact_kinematics(const Params& params, const Eigen::Vector3d& cg_ned_m,
                                     const Eigen::Vector3d& cg_velocity_ned_mps,
                                     const Eigen::Matrix3d& body_from_ned,
                                     const Eigen::Vector3d& omega_body_radps,
                                     const Eigen::Vector3d& cg_m,
                                     std::span<ContactKinematics> out) {
  if (out.size() != params.contacts.size()) {
    throw std::invalid_argument("LandingGear::contact_kinematics: output size mismatch");
  }
  const Eigen::Matrix3d ned_from_body = body_from_ned.transpose();
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Eigen::Vector3d arm_body = params.contacts[i].position_m - cg_m;
    out[i].position_ned_m = cg_ned_m + ned_from_body * arm_body;
    out[i].velocity_ned_mps = cg_velocity_ned_mps + ned_from_body * omega_body_radps.cross(arm_body);
  }
}

double LandingGear::brake_for(const Contact& contact, const Inputs& in) const {
  switch (contact.brake_group) {
    case BrakeGroup::kLeft:
      return clamp_or_zero(in.brake_left, 0.0, 1.0);
    case BrakeGroup::kRight:
      return clamp_or_zero(in.brake_right, 0.0, 1.0);
    case BrakeGroup::kNone:
      break;
  }
  return 0.0;
}

double LandingGear::blend_speed_mps(const Inputs& in) const {
  const double floor = std::isfinite(in.min_friction_blend_speed_mps)
                           ? in.min_friction_blend_speed_mps
                           : 0.0;
  return std::max(params_.friction_blend_speed_mps, floor);
}

Eigen::Vector3d LandingGear::wheel_friction_ned(const Contact& contact,
                                                const Eigen::Vector3d& velocity_ned,
                                                const Eigen::Matrix3d& body_from_ned,
                                                double steer_rad, double brake, double normal_n,
                                                double band_mps) const {
  const GroundAxes axes = wheel_ground_axes(body_from_ned, steer_rad);
  const double v_roll = velocity_ned.dot(axes.along);
  const double v_side = velocity_ned.dot(axes.right);

  const double mu_roll = contact.rolling_friction * (1.0 - brake) + contact.static_friction * brake;
  const double f_roll = -std::copysign(mu_roll * normal_n * blend(v_roll, band_mps), v_roll);

  // The slip-angle law's slope, mu N / (slip_sat |v_roll|) per m/s of side speed, grows without
  // bound as the wheel stops rolling; near a standstill the side friction is held to the
  // viscous band instead (the same slope as along the wheel), which an explicit integrator
  // carries. Above |v_roll| = band / slip_sat (1.4 m/s) the slip-angle law governs alone.
  const double slip_rad = std::atan2(v_side, std::abs(v_roll));
  const double side_fraction = std::min(
      std::abs(slip_rad) / contact.cornering_saturation_slip_rad, blend(v_side, band_mps));
  const double f_side = -std::copysign(contact.dynamic_friction * side_fraction * normal_n, v_side);

  return f_roll * axes.along + f_side * axes.right;
}

Eigen::Vector3d LandingGear::sliding_friction_ned(const Contact& contact,
                                                  const Eigen::Vector3d& velocity_ned,
                                                  double normal_n, double band_mps) const {
  const Eigen::Vector3d v_ground(velocity_ned.x(), velocity_ned.y(), 0.0);
  const double speed = v_ground.norm();
  // mu N v / max(|v|, band): Coulomb outside the band, viscous inside.
  return -contact.dynamic_friction * normal_n * v_ground / std::max(speed, band_mps);
}

LandingGear::ContactOutput LandingGear::evaluate_contact(std::size_t index,
                                                         const ContactKinematics& kin,
                                                         const Inputs& in) const {
  const Contact& contact = params_.contacts[index];
  ContactOutput out;
  const bool wheel = contact.type == ContactType::kWheel;
  const bool deployed = !wheel || !contact.retractable || in.gear_down;
  out.compression_m = kin.position_ned_m.z() + in.runway_elevation_m;
  out.compression_rate_mps = kin.velocity_ned_mps.z();
  if (!deployed || !(out.compression_m > 0.0) || !std::isfinite(out.compression_rate_mps)) {
    out.compression_m = std::max(out.compression_m, 0.0);
    if (std::isnan(out.compression_m)) out.compression_m = 0.0;
    return out;
  }
  out.in_contact = true;
  double damping = out.compression_rate_mps >= 0.0 ? contact.damping_compression_nspm
                                                   : contact.damping_rebound_nspm;
  if (index < in.max_damping_nspm.size() && in.max_damping_nspm[index] >= 0.0) {
    damping = std::min(damping, in.max_damping_nspm[index]);
  }
  out.normal_force_n =
      std::max(contact.spring_npm * out.compression_m + damping * out.compression_rate_mps, 0.0);
  out.steer_angle_rad = wheel ? clamp_or_zero(in.steering, -1.0, 1.0) * contact.max_steer_rad : 0.0;

  const double band = blend_speed_mps(in);
  Eigen::Vector3d friction_ned =
      wheel ? wheel_friction_ned(contact, kin.velocity_ned_mps, in.body_from_ned,
                                 out.steer_angle_rad, brake_for(contact, in), out.normal_force_n,
                                 band)
            : sliding_friction_ned(contact, kin.velocity_ned_mps, out.normal_force_n, band);
  const double limit = contact.static_friction * out.normal_force_n;
  const double magnitude = friction_ned.norm();
  if (magnitude > limit) friction_ned *= limit / magnitude;  // friction circle

  out.force_body_n = in.body_from_ned * (out.normal_force_n * kUpNed + friction_ned);
  return out;
}

void LandingGear::step(double /*dt_s*/, const Inputs& in) {
  if (in.contacts.size() != params_.contacts.size()) {
    throw std::invalid_argument("LandingGear::step: " + std::to_string(in.contacts.size()) +
                                " contact states for " + std::to_string(params_.contacts.size()) +
                                " contacts");
  }
  Outputs& out = outputs_;
  out.force_body_n.setZero();
  out.moment_datum_body_nm.setZero();
  out.weight_on_wheels = false;
  for (std::size_t i = 0; i < params_.contacts.size(); ++i) {
    const Contact& contact = params_.contacts[i];
    ContactOutput& c = out.contacts[i];
    c = evaluate_contact(i, in.contacts[i], in);
    if (!c.in_contact) continue;
    // The force acts where the tyre meets the ground: the undeflected point moved up by the
    // compression along the ground normal.
    const Eigen::Vector3d ground_point_body =
        contact.position_m + in.body_from_ned * (c.compression_m * kUpNed);
    out.force_body_n += c.force_body_n;
    out.moment_datum_body_nm += ground_point_body.cross(c.force_body_n);
    if (contact.type == ContactType::kWheel) out.weight_on_wheels = true;
  }
}

}  // namespace fedsim::flight
