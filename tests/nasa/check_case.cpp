// NASA atmospheric check cases on fedsim's rigid-body dynamics.
#include "check_case.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <stdexcept>

#include "common/atmosphere/atmosphere.hpp"

namespace fedsim::flight::nasa {

namespace {
constexpr double kFt = units::kFtToM;
constexpr double kSlug = 14.593902937206;         // kg
constexpr double kSlugFt2 = kSlug * kFt * kFt;    // kg m^2
constexpr double kDeg = units::kDegToRad;

// Vehicle data of NASA TM-2015-218675 (section B.1 and table 4).
constexpr double kSphereDiameterM = 0.5 * kFt;
constexpr double kBrickSpanM = 4.0 * 0.0254;      // b: reference span (y extent)
constexpr double kBrickChordM = 8.0 * 0.0254;     // cbar: reference chord (x extent)
constexpr double kBrickAreaM2 = kBrickSpanM * kBrickChordM;
constexpr double kBrickDampingDerivative = -1.0;  // Clp = Cmq = Cnr, per radian

/// Drag of a sphere (force along the air-relative velocity), wind constant in NED.
class SphereDrag : public ForceSource {
 public:
  SphereDrag(const RigidBodyDynamics& dynamics, double drag_coefficient,
             const Eigen::Vector3d& wind_ned_mps)
      : dynamics_(dynamics), cd_s_m2_(drag_coefficient * 0.25 * units::kPi *
                                      kSphereDiameterM * kSphereDiameterM),
        wind_ned_mps_(wind_ned_mps) {}

  Wrench forces(const RigidBodyState& state, double) override {
    Wrench wrench;
    if (cd_s_m2_ == 0.0) return wrench;
    const EarthModel& earth = dynamics_.earth();
    const GeodeticPosition where = earth.geodetic(state.position_m);
    const AirProperties air = atmosphere_.at(where.alt_m);
    const Eigen::Vector3d wind_ref = earth.ned_from_reference(where).transpose() * wind_ned_mps_;
    const Eigen::Vector3d air_velocity_body = state.attitude.conjugate() * (state.velocity_mps - wind_ref);
    const double speed = air_velocity_body.norm();
    // F = -qbar S CD v/|v| = -(rho/2) S CD |v| v
    wrench.force_body_n = -0.5 * air.density_kgpm3 * cd_s_m2_ * speed * air_velocity_body;
    return wrench;
  }

 private:
  const RigidBodyDynamics& dynamics_;
  Atmosphere atmosphere_;
  double cd_s_m2_;
  Eigen::Vector3d wind_ned_mps_;
};

/// Aerodynamic rate damping of the brick: L = qbar S b Clp (p b / 2V) and likewise for M (with
/// cbar) and N; qbar b / (2V) = rho V b / 4, so the moments vanish smoothly at V = 0.
class BrickDamping : public ForceSource {
 public:
  BrickDamping(const RigidBodyDynamics& dynamics, bool enabled)
      : dynamics_(dynamics), enabled_(enabled) {}

  Wrench forces(const RigidBodyState& state, double) override {
    Wrench wrench;
    if (!enabled_) return wrench;
    const GeodeticPosition where = dynamics_.earth().geodetic(state.position_m);
    const double rho = atmosphere_.at(where.alt_m).density_kgpm3;
    const double speed = state.velocity_mps.norm();  // no wind in the brick cases
    const double k = 0.25 * rho * speed * kBrickAreaM2 * kBrickDampingDerivative;
    const Eigen::Vector3d& w = state.omega_body_radps;
    wrench.moment_body_nm = {k * kBrickSpanM * kBrickSpanM * w.x(),
                          k * kBrickChordM * kBrickChordM * w.y(),
                          k * kBrickSpanM * kBrickSpanM * w.z()};
    return wrench;
  }

 private:
  const RigidBodyDynamics& dynamics_;
  Atmosphere atmosphere_;
  bool enabled_;
};

InitialConditions dropped_at_30000_ft() {
  InitialConditions ic;
  ic.position = {0.0, 0.0, 30000.0 * kFt};
  return ic;  // at rest relative to the earth, level, heading north, no inertial rotation
}

InitialConditions cannonball(double heading_rad, const Eigen::Vector3d& velocity_ned_fps) {
  InitialConditions ic;
  ic.position = {0.0, 0.0, 0.0};
  ic.velocity_ned_mps = velocity_ned_fps * kFt;
  ic.attitude.psi_rad = heading_rad;
  ic.omega_relative_to_earth = true;  // not rotating relative to the earth
  return ic;
}
}  // namespace

std::vector<CheckCase> atmospheric_check_cases() {
  std::vector<CheckCase> cases;
  CheckCase c;
  c.id = "Atmos_01";
  c.title = "dropped sphere, no drag";
  c.initial = dropped_at_30000_ft();
  cases.push_back(c);

  c = CheckCase{};
  c.id = "Atmos_02";
  c.title = "tumbling brick, no damping";
  c.body = CheckBody::kBrick;
  c.initial = dropped_at_30000_ft();
  c.initial.omega_body_radps = Eigen::Vector3d(10.0, 20.0, 30.0) * kDeg;  // relative to inertial
  cases.push_back(c);

  c.id = "Atmos_03";
  c.title = "tumbling brick with damping";
  c.brick_damping = true;
  cases.push_back(c);

  c = CheckCase{};
  c.id = "Atmos_06";
  c.title = "sphere with drag";
  c.drag_coefficient = 0.1;
  c.initial = dropped_at_30000_ft();
  cases.push_back(c);

  c.id = "Atmos_07";
  c.title = "dropped sphere in a steady 20 ft/s wind from the west";
  c.wind_ned_mps = Eigen::Vector3d(0.0, 20.0 * kFt, 0.0);
  cases.push_back(c);

  c = CheckCase{};
  c.id = "Atmos_09";
  c.title = "cannonball fired eastward";
  c.drag_coefficient = 0.1;
  c.initial = cannonball(90.0 * kDeg, {0.0, 1000.0, -1000.0});
  cases.push_back(c);

  c.id = "Atmos_10";
  c.title = "cannonball fired northward";
  c.initial = cannonball(0.0, {1000.0, 0.0, -1000.0});
  cases.push_back(c);
  return cases;
}

MassProperties mass_properties_of(CheckBody body) {
  if (body == CheckBody::kSphere) {
    return MassProperties::from_moments(1.0 * kSlug, 3.6 * kSlugFt2, 3.6 * kSlugFt2, 3.6 * kSlugFt2);
  }
  return MassProperties::from_moments(0.155404754 * kSlug, 0.001894220 * kSlugFt2,
                                      0.006211019 * kSlugFt2, 0.007194665 * kSlugFt2);
}

TimeHistory simulate(const CheckCase& check_case, IntegrationMethod method, double step_s,
                     double output_period_s) {
  RigidBodyConfig config;
  config.earth.kind = EarthModelKind::kWgs84;
  config.method = method;
  RigidBody body(config, mass_properties_of(check_case.body));
  body.reset(check_case.initial);
  SphereDrag drag(body.dynamics(), check_case.drag_coefficient, check_case.wind_ned_mps);
  BrickDamping damping(body.dynamics(), check_case.brick_damping);
  ForceSource& forces = check_case.body == CheckBody::kSphere ? static_cast<ForceSource&>(drag)
                                                              : static_cast<ForceSource&>(damping);
  const int substeps = static_cast<int>(std::lround(output_period_s / step_s));
  if (substeps < 1 || std::abs(substeps * step_s - output_period_s) > 1e-12) {
    throw std::invalid_argument("the output period must be a whole number of steps");
  }
  TimeHistory history({"altitude_m", "north_m", "east_m", "v_north_mps", "v_east_mps",
                       "v_down_mps", "phi_rad", "theta_rad", "psi_rad", "p_radps", "q_radps",
                       "r_radps", "lat_rad", "lon_rad"});
  const double cos_lat0 = std::cos(check_case.initial.position.lat_rad);
  const int frames = static_cast<int>(std::lround(check_case.duration_s / output_period_s));
  for (int frame = 0; frame <= frames; ++frame) {
    const RigidBodyOutputs out = body.outputs();
    const GeodeticPosition& g = out.geodetic;
    history.append(frame * output_period_s,
                   {g.alt_m, g.lat_rad * wgs84::kSemiMajorAxisM,
                    g.lon_rad * wgs84::kSemiMajorAxisM * cos_lat0, out.velocity_ned_mps.x(),
                    out.velocity_ned_mps.y(), out.velocity_ned_mps.z(), out.euler.phi_rad,
                    out.euler.theta_rad, out.euler.psi_rad, out.omega_body_radps.x(),
                    out.omega_body_radps.y(), out.omega_body_radps.z(), g.lat_rad, g.lon_rad});
    if (frame < frames) body.step(output_period_s, substeps, forces);
  }
  return history;
}

}  // namespace fedsim::flight::nasa
