// Mass, centre of gravity and inertia of the aircraft from its empty mass, point masses and
// fuel tanks, with fuel drawn from the tanks by the engines.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace fedsim::flight {

/// Mass balance (executive step 8): fuel burn and mass properties.
///
/// Frames: positions are body axes (x forward, y right, z down), metres from the pack datum.
/// The inertia matrix is the tensor J such that the angular momentum is H = J omega (body
/// axes): diagonal Ixx, Iyy, Izz; off-diagonal -Ixy, -Ixz, -Iyz with the products defined
/// as Ixz = sum(m x z) (so a typical Ixz > 0 appears as J(0,2) = J(2,0) < 0).
///
/// Inputs:  each engine's fuel mass flow (kg/s), in the order of Params::engine_feeds.
/// Outputs: total mass (kg), CG (m, from datum), inertia about the CG (kg m^2), fuel per
///          tank and in total (kg), and whether each engine's feed tanks ran dry.
///
/// Fuel burn: each engine draws its flow in equal shares from those of its feed tanks that
/// still hold fuel; a tank that runs dry passes its share to the others in the same step.
/// If all its feed tanks are empty the engine is starved (the executive should stop it).
/// Mass properties: empty aircraft (mass, CG, inertia about its CG) plus point masses and
/// tank contents as point masses, combined with the parallel-axis theorem (seed eqs.
/// 3.97-3.99 generalised to the full tensor).
class MassBalance {
 public:
  struct PointMass {
    std::string name;
    double mass_kg = 0.0;
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  };

  struct FuelTank {
    std::string name;
    double capacity_kg = 0.0;
    double initial_contents_kg = 0.0;
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  };

  struct Params {
    double empty_mass_kg = 0.0;
    Eigen::Vector3d empty_cg_m = Eigen::Vector3d::Zero();
    /// Inertia tensor of the empty aircraft about its own CG (see class comment for signs).
    Eigen::Matrix3d empty_inertia_kgm2 = Eigen::Matrix3d::Zero();
    std::vector<PointMass> point_masses;
    std::vector<FuelTank> tanks;
    /// engine_feeds[e] lists the tank indices engine e draws from (at least one).
    std::vector<std::vector<std::size_t>> engine_feeds;

    void validate() const;
  };

  struct Inputs {
    /// One entry per engine (size must equal Params::engine_feeds.size()), kg/s, >= 0.
    std::span<const double> engine_fuel_flow_kgps;
  };

  struct Outputs {
    double mass_kg = 0.0;
    Eigen::Vector3d cg_m = Eigen::Vector3d::Zero();
    Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Zero();  ///< about the CG
    double fuel_kg = 0.0;
    std::vector<double> tank_contents_kg;  ///< sized at construction
    std::vector<bool> engine_starved;      ///< sized at construction
  };

  explicit MassBalance(Params params);

  /// Tanks back to their initial contents, point masses to their pack values.
  void reset();
  /// Burns fuel for dt_s seconds and updates the mass properties. Throws
  /// std::invalid_argument if the number of fuel flows differs from the number of engines.
  void step(double dt_s, const Inputs& in);

  /// Instructor / scenario settings; contents are clamped to [0, capacity].
  void set_tank_contents_kg(std::size_t tank, double contents_kg);
  void set_point_mass_kg(std::size_t index, double mass_kg);

  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

 private:
  /// Takes up to demand_kg from engine e's feed tanks; returns what could not be supplied.
  double draw_fuel(std::size_t engine, double demand_kg);
  bool feeds_empty(std::size_t engine) const;
  void update_mass_properties();

  Params params_;
  std::vector<double> point_mass_kg_;
  Outputs outputs_;
};

}  // namespace fedsim::flight
