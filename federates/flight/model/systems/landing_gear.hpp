// Landing gear and other ground contacts: spring-damper struts on a level runway plane with
// rolling, braking and cornering friction.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

namespace fedsim::flight {

/// Ground reactions (seed 3.9; executive step 7).
///
/// Stateless: the forces are a function of the contact points' positions and velocities, so
/// an integrator may evaluate it at any sub-stage (RK4 stages included).
///
/// Inputs:  per contact, its position and velocity in NED relative to the ground
///          (ContactKinematics; contact_kinematics() computes them from the rigid-body state),
///          the NED-to-body direction cosine matrix, the runway elevation (the ground is the
///          level plane at that altitude, normal up), nose-wheel steering (-1..1, + = nose
///          right), left / right brakes (0..1), gear lever (down / up).
/// Outputs: total force_body_n (body axes) and moment_datum_body_nm (about the pack datum, body
///          axes), weight-on-wheels, and per contact its compression, normal force and force.
///
/// Per contact (a wheel, or a structural point such as a tail skid or a wing tip):
///  - compression d = runway elevation - altitude of the undeflected contact point; in
///    contact while d > 0 (retractable wheels only with the gear down);
///  - normal force N = max(0, k d + c d'), with c the compression damping while d' >= 0 and
///    the rebound damping otherwise (either held to Inputs::max_damping_nspm, the ceiling an
///    executive sets for its integrator); the ground can push, never pull; N acts along the
///    ground normal (up) at the tyre's ground point;
///  - a wheel rolls along its heading (body x turned by the steering angle) projected on the
///    ground. Along it: rolling / braking friction mu_x N opposing the rolling speed, with
///    mu_x = mu_roll (1 - b) + mu_static b for brake b (the JSBSim FGLGear law). Across it:
///    cornering friction opposing the side speed,
///    mu_side = mu_dynamic * min(|slip| / slip_sat, |v_side| / band, 1)
///    with slip = atan2(v_side, |v_roll|): linear in the slip angle up to the saturation slip
///    angle while the wheel rolls (faster than band / slip_sat), the viscous band below;
///  - a structural contact slides: mu_dynamic N opposing the ground-plane velocity;
///  - the total ground-plane friction never exceeds mu_static N (friction circle);
///  - below the band speed the Coulomb friction blends linearly to zero with speed (a viscous
///    band): a discontinuous sign(v) would chatter at a standstill. The band is the larger of
///    Params::friction_blend_speed_mps and Inputs::min_friction_blend_speed_mps, the floor an
///    executive sets so that its integrator stays stable: inside the band each contact's
///    friction is a damper of rate mu N / band on a contact point of effective mass m_eff, and
///    an explicit step h needs h * sum(mu N / (band m_eff)) within the method's real-axis
///    stability limit (Euler 2, RK4 2.79, AB2 1). Inside the band a braked aircraft creeps at
///    v = band * applied force / (mu N).
/// Damping guidance: zeta = c / (2 sqrt(k m)) with m the mass the strut carries;
/// damping_ratio() computes it. Light aircraft and transport packs (JSBSim c172x, 737) have
/// zeta of about 0.2-1.3 in compression, more in rebound.
class LandingGear {
 public:
  enum class ContactType { kWheel, kStructure };
  enum class BrakeGroup { kNone, kLeft, kRight };

  struct Contact {
    std::string name;
    ContactType type = ContactType::kWheel;
    /// Lowest point of the tyre (or the structure) with the strut fully extended: body axes,
    /// metres from the pack datum.
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
    double spring_npm = 0.0;                ///< strut stiffness, N/m
    double damping_compression_nspm = 0.0;  ///< N/(m/s) while compressing
    double damping_rebound_nspm = 0.0;      ///< N/(m/s) while extending
    double static_friction = 0.8;           ///< friction circle limit and full-brake coefficient
    double dynamic_friction = 0.5;   ///< peak cornering (wheel) or sliding (structure) coefficient
    double rolling_friction = 0.02;  ///< unbraked rolling resistance coefficient
    double max_steer_rad = 0.0;      ///< steering angle at command 1 (0: not steerable)
    BrakeGroup brake_group = BrakeGroup::kNone;
    bool retractable = false;
    /// Slip angle at which cornering friction reaches dynamic_friction.
    double cornering_saturation_slip_rad = 0.175;
  };

  struct Params {
    std::vector<Contact> contacts;
    double friction_blend_speed_mps = 0.25;

    /// Throws std::invalid_argument naming the field, e.g. "contacts[1].spring_npm ...".
    void validate() const;
  };

  struct ContactKinematics {
    /// Undeflected contact point in NED; its altitude is -z, on the same reference as
    /// Inputs::runway_elevation_m (flat earth: NED origin at sea level).
    Eigen::Vector3d position_ned_m = Eigen::Vector3d::Zero();
    /// Velocity of that point relative to the ground, NED.
    Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();
  };

  struct Inputs {
    std::span<const ContactKinematics> contacts;  ///< one per Params::contacts, same order
    Eigen::Matrix3d body_from_ned = Eigen::Matrix3d::Identity();  ///< v_body = C v_ned
    double runway_elevation_m = 0.0;
    double steering = 0.0;     ///< -1..1, + = nose right
    double brake_left = 0.0;   ///< 0..1
    double brake_right = 0.0;  ///< 0..1
    bool gear_down = true;
    /// Floor on the friction band (m/s), set by the executive for its integrator and step;
    /// 0: Params::friction_blend_speed_mps alone.
    double min_friction_blend_speed_mps = 0.0;
    /// Per contact (same order as Params::contacts), a ceiling on the strut damping (N s/m)
    /// that the executive's integrator carries at its step; empty: none.
    std::span<const double> max_damping_nspm;
  };

  struct ContactOutput {
    bool in_contact = false;
    double compression_m = 0.0;
    double compression_rate_mps = 0.0;
    double normal_force_n = 0.0;
    double steer_angle_rad = 0.0;
    Eigen::Vector3d force_body_n = Eigen::Vector3d::Zero();
  };

  struct Outputs {
    Eigen::Vector3d force_body_n = Eigen::Vector3d::Zero();
    Eigen::Vector3d moment_datum_body_nm = Eigen::Vector3d::Zero();
    bool weight_on_wheels = false;        ///< any wheel (not structure) in contact
    std::vector<ContactOutput> contacts;  ///< sized at construction
  };

  explicit LandingGear(Params params);

  void reset();
  /// Evaluates the ground reactions (dt_s is unused: the model has no state). Throws
  /// std::invalid_argument if the number of contact kinematics does not match the pack.
  void step(double dt_s, const Inputs& in);

  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

  /// Contact point positions and velocities from the rigid-body state: cg_ned_m and
  /// cg_velocity_ned_mps of the CG over the ground, attitude, body rates relative to the
  /// ground (rad/s, body axes) and the CG's position from the pack datum (m, body axes).
  /// Writes one entry per contact into `out` (size must match; no allocation).
  static void contact_kinematics(const Params& params, const Eigen::Vector3d& cg_ned_m,
                                 const Eigen::Vector3d& cg_velocity_ned_mps,
                                 const Eigen::Matrix3d& body_from_ned,
                                 const Eigen::Vector3d& omega_body_radps, const Eigen::Vector3d& cg_m,
                                 std::span<ContactKinematics> out);

  /// c / (2 sqrt(k m)) for a strut of stiffness k carrying mass m.
  static double damping_ratio(double spring_npm, double damping_nspm, double supported_mass_kg);

 private:
  ContactOutput evaluate_contact(std::size_t index, const ContactKinematics& kin,
                                 const Inputs& in) const;
  Eigen::Vector3d wheel_friction_ned(const Contact& contact, const Eigen::Vector3d& velocity_ned,
                                     const Eigen::Matrix3d& body_from_ned, double steer_rad,
                                     double brake, double normal_n, double band_mps) const;
  Eigen::Vector3d sliding_friction_ned(const Contact& contact, const Eigen::Vector3d& velocity_ned,
                                       double normal_n, double band_mps) const;
  double blend_speed_mps(const Inputs& in) const;
  double brake_for(const Contact& contact, const Inputs& in) const;

  Params params_;
  Outputs outputs_;
};

}  // namespace fedsim::flight
