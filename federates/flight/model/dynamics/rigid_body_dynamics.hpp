// Six-degree-of-freedom rigid-body equations of motion (seed 3.6-3.7 and 3.11) on an EarthModel.
#pragma once

#include <Eigen/Core>

#include "common/math/integration_method.hpp"
#include "flight/model/dynamics/earth_model.hpp"
#include "flight/model/dynamics/mass_properties.hpp"
#include "flight/model/dynamics/rigid_body_state.hpp"
#include "common/math/rotation.hpp"

namespace fedsim::flight {

/// How a run starts: position, earth-relative velocity and attitude in local NED terms.
struct InitialConditions {
  GeodeticPosition position;                                    // flat earth: about its origin
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();   // relative to the earth
  EulerAngles attitude;                                         // body relative to local NED
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();        // body rates, body axes
  bool omega_relative_to_earth = false;  // true: omega_body_radps is relative to the (rotating)
                                         // earth; the earth's rate is added to it
};

/// Kinematic outputs of a state (no forces needed).
struct RigidBodyOutputs {
  GeodeticPosition geodetic;                        // lat, lon, height above the ellipsoid
  Eigen::Vector3d position_ecef_m;
  Eigen::Vector3d velocity_ned_mps;                 // relative to the earth
  Eigen::Vector3d velocity_body_mps;                   // u, v, w relative to the earth
  EulerAngles euler;                                // phi, theta, psi relative to local NED
  Eigen::Matrix3d ned_from_body;
  Eigen::Vector3d omega_body_radps;                      // p, q, r relative to inertial space
  Eigen::Vector3d omega_body_wrt_earth_radps;            // p, q, r relative to the earth
  Eigen::Vector3d gravitation_ned_mps2;             // gravitational attraction, local NED
};

/// Accelerations of a state under a wrench.
struct RigidBodyAccelerations {
  Eigen::Vector3d specific_force_body_mps2;  // non-gravitational force / mass: what an
                                          // accelerometer at the CG reads (n_z = -f_z / g)
  Eigen::Vector3d acceleration_body_mps2;    // rate of change of the earth-relative velocity
                                          // (reference frame), body axes
  Eigen::Vector3d omega_dot_body_radps2;       // angular acceleration, body axes
};

/// The equations. State vector layout (13 doubles): position (3), velocity (3), attitude
/// quaternion e0..e3 (4), omega_body (3), all as in RigidBodyState.
///   r'     = v
///   v'     = C_ref_body F / m + free-fall acceleration (gravity [- 2 W x v - W x (W x r)])
///   q'     = 1/2 q (x) (omega_body - C_body_ref W) + k lambda q                 (eqs 3.59-3.70)
///   omega' = J^-1 (M - omega x (J omega + h_rotor))                      (eqs 3.104-3.112)
/// The flat-earth translational equation is the book's body-axis eqs 3.101-3.103 written in the
/// NED frame, where the transport terms (r v - q w, ...) vanish. The inertia may change between
/// steps (fuel burn); its rate of change within a step is neglected.
/// The constraint term k lambda q (lambda = 1 - |q|^2) is passed in as the number k lambda,
/// evaluated once per integration step from the state at the start of the step: evaluated at
/// the intermediate stages of RK4 it would react to their O(h^2) excursions off the unit sphere
/// and bias the norm by ~(omega h)^2 whatever the gain.
class RigidBodyDynamics {
 public:
  static constexpr int kStateSize = 13;
  using StateVector = Eigen::Matrix<double, kStateSize, 1>;

  RigidBodyDynamics(EarthModel earth, const MassProperties& mass);

  const EarthModel& earth() const { return earth_; }
  const MassProperties& mass_properties() const { return mass_; }
  /// Validates and stores new mass properties (precomputes the inverse inertia).
  void set_mass_properties(const MassProperties& mass);

  StateVector derivative(const StateVector& x, const Wrench& wrench,
                         double quaternion_correction_per_s) const;
  /// k lambda for the state at the start of a step of length h (seed: k h <= 1).
  /// The largest stable quaternion-constraint gain k h for an integration method. The
  /// correction k (1 - |q|^2) q pulls the norm back at the rate 2k, an eigenvalue -2 k h per
  /// step, which must lie inside the method's stability interval on the negative real axis:
  /// (-2, 0) for Euler, (-2.79, 0) for RK4, but only (-1, 0), (-6/11, 0) and (-3/10, 0) for
  /// Adams-Bashforth 2, 3 and 4; with k h = 0.5 an AB4 run diverges within a second.
  static double stable_quaternion_constraint_kh(IntegrationMethod method);

  static double quaternion_correction_per_s(const StateVector& x, double constraint_kh,
                                            double step_s);

  static StateVector pack(const RigidBodyState& state);
  static RigidBodyState unpack(const StateVector& x);

  RigidBodyState initial_state(const InitialConditions& initial) const;
  RigidBodyOutputs outputs(const RigidBodyState& state) const;
  RigidBodyAccelerations accelerations(const RigidBodyState& state, const Wrench& wrench) const;

  /// Specific force at a point fixed in the body (e.g. the pilot's eye), body axes, given the
  /// CG specific force and the body's angular motion: f_P = f_cg + w' x r + w x (w x r).
  static Eigen::Vector3d specific_force_at_body(const RigidBodyAccelerations& accelerations,
                                             const Eigen::Vector3d& omega_body_radps,
                                             const Eigen::Vector3d& point_from_cg_body_m);

 private:
  Eigen::Vector3d angular_acceleration(const Eigen::Vector3d& omega_body,
                                       const Wrench& wrench) const;

  EarthModel earth_;
  MassProperties mass_;
  Eigen::Matrix3d inverse_inertia_;
};

}  // namespace fedsim::flight
