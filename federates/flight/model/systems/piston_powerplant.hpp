// Piston engine driving a propeller: shaft-speed dynamics, blade-angle control and the
// resulting force and moment on the airframe.
#pragma once

#include <Eigen/Core>

#include "flight/model/systems/piston_engine.hpp"
#include "flight/model/systems/propeller.hpp"
#include "flight/model/systems/propeller_governor.hpp"
#include "flight/model/systems/thrust_line.hpp"

namespace fedsim::flight {

/// One piston engine + propeller installation (seed 3.8.1).
///
/// State:   propeller shaft speed omega (rad/s, >= 0) and the blade angle.
/// Inputs:  throttle, mixture, propeller lever (0..1), feather, running and failure flags;
///          ambient pressure (Pa), temperature (K), density (kg/m^3), speed of sound (m/s);
///          air_velocity_body_mps, the aircraft's velocity relative to the air in body axes.
/// Outputs: force_body_n (body axes) and moment_datum_body_nm (about the pack datum, body axes),
///          engine and propeller figures, fuel flow (kg/s), and the rotor's angular momentum
///          (body axes) for the gyroscopic term if the equations of motion carry it.
///
/// Shaft dynamics (propeller shaft, gear ratio g = engine rpm / propeller rpm):
///   I d(omega)/dt = g Q_combustion - Q_propeller - g Q_loss,
/// integrated explicitly with the torques at the start of the step. The loss torque
/// (engine pumping + friction) only ever brakes the shaft toward zero, never reverses it,
/// so a stopped engine stays stopped unless something drives it.
/// Force: thrust along ThrustLine::axis_body() at ThrustLine::position_m. Moment: r x F plus
/// the air's torque on the propeller, -sense Q_propeller along the axis (a clockwise-from-
/// behind propeller, sense +1, rolls the aircraft left).
/// Not modelled: P-factor, slipstream effects on the airframe (aerodynamics' job).
class PistonPowerplant {
 public:
  struct Params {
    PistonEngine::Params engine;
    Propeller::Params propeller;
    PropellerGovernor::Params governor;
    ThrustLine thrust_line;
    double gear_ratio = 1.0;  ///< engine rpm / propeller rpm
    /// Rotating inertia (propeller + engine, referred to the propeller shaft), kg m^2.
    double shaft_inertia_kgm2 = 0.0;
    /// +1: the propeller turns clockwise seen from behind (right-handed about the thrust
    /// axis, usual for US engines); -1: anticlockwise.
    int rotation_sense = 1;

    /// Throws std::invalid_argument naming the field, e.g. "engine.rated_rpm ...".
    void validate() const;
  };

  struct Inputs {
    double throttle = 0.0;
    double mixture = 1.0;
    double propeller_lever = 1.0;
    bool feather = false;
    bool running = true;
    bool failed = false;
    double pressure_pa = 101325.0;
    double temperature_k = 288.15;
    double density_kgpm3 = 1.225;
    double speed_of_sound_mps = 340.294;
    Eigen::Vector3d air_velocity_body_mps = Eigen::Vector3d::Zero();
  };

  struct Outputs {
    Eigen::Vector3d force_body_n = Eigen::Vector3d::Zero();
    Eigen::Vector3d moment_datum_body_nm = Eigen::Vector3d::Zero();
    Eigen::Vector3d rotor_angular_momentum_body_kgm2ps = Eigen::Vector3d::Zero();
    double thrust_n = 0.0;
    double engine_rpm = 0.0;
    double propeller_rpm = 0.0;
    double blade_angle_rad = 0.0;
    double selected_rpm = 0.0;
    double advance_ratio = 0.0;
    double propeller_torque_nm = 0.0;
    double propeller_efficiency = 0.0;
    double manifold_pressure_pa = 0.0;
    double brake_power_w = 0.0;
    double fuel_flow_kgps = 0.0;
    double exhaust_gas_temperature_k = 0.0;  ///< EGT (PistonEngine); ambient when not burning
  };

  explicit PistonPowerplant(Params params);

  /// Shaft at `engine_rpm`, blades at the fine stop; outputs for still sea-level air.
  void reset(double engine_rpm = 0.0);
  void step(double dt_s, const Inputs& in);

  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

 private:
  struct Snapshot {
    PistonEngine::Outputs engine;
    Propeller::Outputs propeller;
  };
  Snapshot evaluate(const Inputs& in) const;
  void integrate_shaft(double dt_s, const Snapshot& now);
  void fill_outputs(const Inputs& in, const Snapshot& now);
  double propeller_rpm() const;

  Params params_;
  PistonEngine engine_;
  Propeller propeller_;
  PropellerGovernor governor_;
  Eigen::Vector3d axis_b_;
  double omega_radps_ = 0.0;
  Outputs outputs_;
};

}  // namespace fedsim::flight
