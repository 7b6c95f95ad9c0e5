// Tests of the ground reactions: strut forces, friction laws, steering, gear lever, and
// six-degree-of-freedom settling and braking of a light aircraft and a 737 at 50 and 400 Hz.
#include "flight/model/systems/landing_gear.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "flight/model/systems/test/reference_data.hpp"

namespace fedsim::flight {
namespace {

using reference::kDeg;
using reference::kG;

// One contact with a given position / velocity, aircraft level and heading north.
LandingGear::Outputs evaluate_single(const LandingGear::Contact& contact,
                                     const Eigen::Vector3d& position_ned,
                                     const Eigen::Vector3d& velocity_ned, double brake = 0.0,
                                     double steering = 0.0) {
  LandingGear::Params params;
  params.contacts = {contact};
  LandingGear gear(params);
  const LandingGear::ContactKinematics kin{position_ned, velocity_ned};
  LandingGear::Inputs in;
  in.contacts = std::span<const LandingGear::ContactKinematics>(&kin, 1);
  in.brake_left = brake;
  in.steering = steering;
  gear.step(0.0, in);
  return gear.outputs();
}

LandingGear::Contact braked_main() { return reference::c172_gear().contacts[1]; }

TEST(LandingGear, NoForceWhenAirborne) {
  LandingGear gear(reference::c172_gear());
  std::vector<LandingGear::ContactKinematics> kin(3);
  for (auto& k : kin) {
    k.position_ned_m = Eigen::Vector3d(0.0, 0.0, -0.01);  // 1 cm above the runway
    k.velocity_ned_mps = Eigen::Vector3d(30.0, 0.0, 3.0);
  }
  LandingGear::Inputs in;
  in.contacts = kin;
  gear.step(0.02, in);
  EXPECT_EQ(gear.outputs().force_body_n, Eigen::Vector3d::Zero());
  EXPECT_EQ(gear.outputs().moment_datum_body_nm, Eigen::Vector3d::Zero());
  EXPECT_FALSE(gear.outputs().weight_on_wheels);
  // Same with the runway at 500 m and the wheels at 500.5 m.
  for (auto& k : kin) k.position_ned_m.z() = -500.5;
  in.runway_elevation_m = 500.0;
  gear.step(0.02, in);
  EXPECT_FALSE(gear.outputs().weight_on_wheels);
  EXPECT_EQ(gear.outputs().force_body_n, Eigen::Vector3d::Zero());
}

TEST(LandingGear, StaticDeflectionUnderWeightIsMgOverK) {
  const LandingGear::Contact main = braked_main();
  const double supported_kg = 400.0;
  const double deflection = supported_kg * kG / main.spring_npm;
  const LandingGear::Outputs out =
      evaluate_single(main, Eigen::Vector3d(0.0, 0.0, deflection), Eigen::Vector3d::Zero());
  EXPECT_TRUE(out.weight_on_wheels);
  EXPECT_NEAR(out.contacts[0].normal_force_n, supported_kg * kG, 1e-9);
  EXPECT_NEAR(out.force_body_n.z(), -supported_kg * kG, 1e-9);  // up in level body axes
  EXPECT_NEAR(out.force_body_n.head<2>().norm(), 0.0, 1e-12);
}

TEST(LandingGear, DampingActsOnCompressionRateWithSeparateRebound) {
  const LandingGear::Contact main = braked_main();
  const Eigen::Vector3d p(0.0, 0.0, 0.05);
  const double compressing =
      evaluate_single(main, p, Eigen::Vector3d(0, 0, 0.2)).contacts[0].normal_force_n;
  EXPECT_NEAR(compressing, main.spring_npm * 0.05 + main.damping_compression_nspm * 0.2, 1e-9);
  const double extending =
      evaluate_single(main, p, Eigen::Vector3d(0, 0, -0.2)).contacts[0].normal_force_n;
  EXPECT_NEAR(extending, main.spring_npm * 0.05 - main.damping_rebound_nspm * 0.2, 1e-9);
  // A fast rebound cannot pull the aircraft down.
  EXPECT_EQ(evaluate_single(main, p, Eigen::Vector3d(0, 0, -5.0)).contacts[0].normal_force_n, 0.0);
}

TEST(LandingGear, RollingAndBrakingFrictionOpposeMotion) {
  const LandingGear::Contact main = braked_main();
  const Eigen::Vector3d p(0.0, 0.0, 0.05);
  const double n = main.spring_npm * 0.05;
  for (double v : {10.0, -10.0}) {
    const LandingGear::Outputs rolling = evaluate_single(main, p, Eigen::Vector3d(v, 0, 0));
    EXPECT_NEAR(rolling.force_body_n.x(), -std::copysign(main.rolling_friction * n, v), 1e-9);
    EXPECT_NEAR(rolling.force_body_n.y(), 0.0, 1e-9);
    // Full brake: mu_static N (0.8 N); half brake half way between rolling and full.
    const LandingGear::Outputs braked = evaluate_single(main, p, Eigen::Vector3d(v, 0, 0), 1.0);
    EXPECT_NEAR(braked.force_body_n.x(), -std::copysign(main.static_friction * n, v), 1e-9);
    const LandingGear::Outputs half = evaluate_single(main, p, Eigen::Vector3d(v, 0, 0), 0.5);
    EXPECT_NEAR(half.force_body_n.x(),
                -std::copysign(0.5 * (main.rolling_friction + main.static_friction) * n, v), 1e-9);
  }
  // Standing still: no friction at all (inside the blend band it grows with speed).
  EXPECT_NEAR(evaluate_single(main, p, Eigen::Vector3d::Zero(), 1.0).force_body_n.x(), 0.0, 1e-12);
  const double slow = evaluate_single(main, p, Eigen::Vector3d(0.1, 0, 0), 1.0).force_body_n.x();
  EXPECT_NEAR(slow, -main.static_friction * n * 0.1 / 0.25, 1e-9);
}

TEST(LandingGear, CorneringFrictionFollowsTheSlipAngleLaw) {
  const LandingGear::Contact main = braked_main();
  const Eigen::Vector3d p(0.0, 0.0, 0.05);
  const double n = main.spring_npm * 0.05;
  // 20 m/s forward, 0.7 m/s to the right: slip 2.0 deg, linear part of the law.
  const double slip = std::atan2(0.7, 20.0);
  LandingGear::Outputs out = evaluate_single(main, p, Eigen::Vector3d(20.0, 0.7, 0.0));
  EXPECT_NEAR(out.force_body_n.y(),
              -main.dynamic_friction * slip / main.cornering_saturation_slip_rad * n, 1e-9);
  // Sliding sideways at 30 deg: saturated at mu_dynamic, total within the friction circle.
  out = evaluate_single(
      main, p, Eigen::Vector3d(10.0 * std::cos(30 * kDeg), -10.0 * std::sin(30 * kDeg), 0));
  EXPECT_NEAR(out.force_body_n.y(), main.dynamic_friction * n, 1e-9);
  EXPECT_LE(out.force_body_n.head<2>().norm(), main.static_friction * n + 1e-9);
}

// One braked main wheel, level, heading north, with the executive's band floor and damping
// ceiling as given.
LandingGear::Outputs evaluate_with(const LandingGear::Contact& contact,
                                   const Eigen::Vector3d& position_ned,
                                   const Eigen::Vector3d& velocity_ned, double brake,
                                   double band_floor_mps, std::span<const double> max_damping) {
  LandingGear::Params params;
  params.contacts = {contact};
  LandingGear gear(params);
  const LandingGear::ContactKinematics kin{position_ned, velocity_ned};
  LandingGear::Inputs in;
  in.contacts = std::span<const LandingGear::ContactKinematics>(&kin, 1);
  in.brake_left = brake;
  in.min_friction_blend_speed_mps = band_floor_mps;
  in.max_damping_nspm = max_damping;
  gear.step(0.0, in);
  return gear.outputs();
}

TEST(LandingGear, SideFrictionNearAStandstillKeepsTheBandSlope) {
  // Rolling at 1 cm/s with 1 mm/s of side slip the slip angle is 5.7 deg, a third of the way
  // to saturation; the slip-angle law's side force, mu_d N (slip / slip_sat), would grow as
  // 1/v_roll per m/s of side speed (here 5.7 times the band's slope, which chattered with AB2
  // at 50 Hz). Below band / slip_sat = 1.4 m/s of rolling speed the side friction keeps the
  // viscous band's slope instead: mu_d N v_side / band, whatever the rolling speed.
  const LandingGear::Contact main = braked_main();
  const Eigen::Vector3d p(0.0, 0.0, 0.05);
  const double n = main.spring_npm * 0.05;
  const double band = 0.25;
  for (double v_roll : {0.0, 0.01, 0.1, 1.0}) {
    const LandingGear::Outputs out = evaluate_single(main, p, Eigen::Vector3d(v_roll, 1e-3, 0));
    EXPECT_NEAR(out.force_body_n.y(), -main.dynamic_friction * n * 1e-3 / band, 1e-9) << v_roll;
  }
  // Rolling at 20 m/s the slip-angle law governs alone (as in the cornering test above).
  const double slip = std::atan2(0.7, 20.0);
  EXPECT_NEAR(evaluate_single(main, p, Eigen::Vector3d(20.0, 0.7, 0)).force_body_n.y(),
              -main.dynamic_friction * slip / main.cornering_saturation_slip_rad * n, 1e-9);
}

TEST(LandingGear, ExecutiveFloorWidensTheFrictionBand) {
  const LandingGear::Contact main = braked_main();
  const Eigen::Vector3d p(0.0, 0.0, 0.05);
  const Eigen::Vector3d slow(0.1, 0.0, 0.0);
  const double n = main.spring_npm * 0.05;
  // A floor above the gear's own 0.25 m/s band widens it; one below, or NaN, changes nothing.
  EXPECT_NEAR(evaluate_with(main, p, slow, 1.0, 0.5, {}).force_body_n.x(),
              -main.static_friction * n * 0.1 / 0.5, 1e-9);
  for (double floor : {0.0, 0.1, std::nan("")}) {
    EXPECT_NEAR(evaluate_with(main, p, slow, 1.0, floor, {}).force_body_n.x(),
                -main.static_friction * n * 0.1 / 0.25, 1e-9)
        << floor;
  }
}

TEST(LandingGear, DampingCeilingHoldsTheStrutDamper) {
  const LandingGear::Contact main = braked_main();
  const Eigen::Vector3d p(0.0, 0.0, 0.05);
  const double spring = main.spring_npm * 0.05;
  const double ceiling = 1000.0;  // below both of this strut's dampers
  const std::array<double, 1> limit{ceiling};
  EXPECT_NEAR(evaluate_with(main, p, Eigen::Vector3d(0, 0, 0.2), 0.0, 0.0, limit)
                  .contacts[0]
                  .normal_force_n,
              spring + ceiling * 0.2, 1e-9);
  EXPECT_NEAR(evaluate_with(main, p, Eigen::Vector3d(0, 0, -0.2), 0.0, 0.0, limit)
                  .contacts[0]
                  .normal_force_n,
              spring - ceiling * 0.2, 1e-9);
  // A ceiling above the damper, or none, leaves it alone.
  const std::array<double, 1> high{1e9};
  EXPECT_NEAR(evaluate_with(main, p, Eigen::Vector3d(0, 0, -0.2), 0.0, 0.0, high)
                  .contacts[0]
                  .normal_force_n,
              spring - main.damping_rebound_nspm * 0.2, 1e-9);
}

TEST(LandingGear, StructuralContactSlidesAgainstItsVelocity) {
  LandingGear::Contact skid;
  skid.type = LandingGear::ContactType::kStructure;
  skid.spring_npm = 20000.0 * reference::kLbfPerFt;
  skid.static_friction = 0.2;
  skid.dynamic_friction = 0.2;
  const Eigen::Vector3d v(6.0, -8.0, 0.0);
  const LandingGear::Outputs out = evaluate_single(skid, Eigen::Vector3d(0, 0, 0.01), v);
  const double n = skid.spring_npm * 0.01;
  EXPECT_TRUE((out.force_body_n.head<2>() + 0.2 * n * v.head<2>() / 10.0).norm() < 1e-9);
  EXPECT_FALSE(out.weight_on_wheels);  // structure is not a wheel
}

TEST(LandingGear, NoseWheelSteeringYawsTowardTheCommand) {
  LandingGear gear(reference::c172_gear());
  const Eigen::Vector3d cg = reference::from_structural_in(41.0, 0.0, 36.5);
  std::vector<LandingGear::ContactKinematics> kin(3);
  // Rolling north at 5 m/s with each wheel 5 cm into the runway.
  for (std::size_t i = 0; i < 3; ++i) {
    kin[i].position_ned_m = Eigen::Vector3d(0, 0, 0.05);
    kin[i].velocity_ned_mps = Eigen::Vector3d(5.0, 0, 0);
  }
  LandingGear::Inputs in;
  in.contacts = kin;
  in.steering = 1.0;  // 10 deg right
  gear.step(0.0, in);
  EXPECT_NEAR(gear.outputs().contacts[0].steer_angle_rad, 10.0 * kDeg, 1e-12);
  EXPECT_GT(gear.outputs().contacts[0].force_body_n.y(), 0.0);
  const Eigen::Vector3d moment_cg =
      gear.outputs().moment_datum_body_nm - cg.cross(gear.outputs().force_body_n);
  EXPECT_GT(moment_cg.z(), 0.0);  // nose right
  in.steering = -1.0;
  gear.step(0.0, in);
  EXPECT_LT((gear.outputs().moment_datum_body_nm - cg.cross(gear.outputs().force_body_n)).z(), 0.0);
}

TEST(LandingGear, RetractedGearMakesNoContact) {
  LandingGear gear(reference::b737_gear());
  std::vector<LandingGear::ContactKinematics> kin(3);
  for (auto& k : kin) k.position_ned_m = Eigen::Vector3d(0, 0, 0.1);
  LandingGear::Inputs in;
  in.contacts = kin;
  in.gear_down = false;
  gear.step(0.0, in);
  EXPECT_FALSE(gear.outputs().weight_on_wheels);
  EXPECT_EQ(gear.outputs().force_body_n, Eigen::Vector3d::Zero());
  in.gear_down = true;
  gear.step(0.0, in);
  EXPECT_TRUE(gear.outputs().weight_on_wheels);
}

// --- Six-degree-of-freedom harness: a rigid aircraft on its gear, RK4 on a flat earth. ---

struct RigidAircraft {
  LandingGear gear;
  double mass_kg;
  Eigen::Matrix3d inertia_kgm2;
  Eigen::Vector3d cg_m;
  double brakes = 0.0;
  std::vector<LandingGear::ContactKinematics> kin;

  struct State {
    Eigen::Vector3d position_ned, velocity_ned;
    Eigen::Quaterniond ned_from_body;
    Eigen::Vector3d omega_body;
  };
  struct Rates {
    Eigen::Vector3d position, velocity;
    Eigen::Vector4d quaternion;
    Eigen::Vector3d omega;
  };

  RigidAircraft(LandingGear::Params gear_params, double mass, Eigen::Matrix3d inertia,
                Eigen::Vector3d cg)
      : gear(gear_params),
        mass_kg(mass),
        inertia_kgm2(inertia),
        cg_m(cg),
        kin(gear_params.contacts.size()) {}

  Rates rates(const State& s) {
    const Eigen::Matrix3d body_from_ned = s.ned_from_body.toRotationMatrix().transpose();
    LandingGear::contact_kinematics(gear.params(), s.position_ned, s.velocity_ned, body_from_ned,
                                    s.omega_body, cg_m, kin);
    LandingGear::Inputs in;
    in.contacts = kin;
    in.body_from_ned = body_from_ned;
    in.brake_left = in.brake_right = brakes;
    gear.step(0.0, in);
    const Eigen::Vector3d force_body = gear.outputs().force_body_n;
    const Eigen::Vector3d moment_cg = gear.outputs().moment_datum_body_nm - cg_m.cross(force_body);
    Rates r;
    r.position = s.velocity_ned;
    r.velocity = body_from_ned.transpose() * force_body / mass_kg + Eigen::Vector3d(0, 0, kG);
    const Eigen::Quaterniond w(0.0, s.omega_body.x(), s.omega_body.y(), s.omega_body.z());
    r.quaternion = 0.5 * (s.ned_from_body * w).coeffs();
    r.omega = inertia_kgm2.inverse() * (moment_cg - s.omega_body.cross(inertia_kgm2 * s.omega_body));
    return r;
  }

  static State advance(const State& s, const Rates& r, double h) {
    State n;
    n.position_ned = s.position_ned + h * r.position;
    n.velocity_ned = s.velocity_ned + h * r.velocity;
    n.ned_from_body.coeffs() = s.ned_from_body.coeffs() + h * r.quaternion;
    n.ned_from_body.normalize();
    n.omega_body = s.omega_body + h * r.omega;
    return n;
  }

  void rk4(State& s, double h) {
    const Rates k1 = rates(s);
    const Rates k2 = rates(advance(s, k1, h / 2));
    const Rates k3 = rates(advance(s, k2, h / 2));
    const Rates k4 = rates(advance(s, k3, h));
    Rates sum;
    sum.position = (k1.position + 2 * k2.position + 2 * k3.position + k4.position) / 6;
    sum.velocity = (k1.velocity + 2 * k2.velocity + 2 * k3.velocity + k4.velocity) / 6;
    sum.quaternion = (k1.quaternion + 2 * k2.quaternion + 2 * k3.quaternion + k4.quaternion) / 6;
    sum.omega = (k1.omega + 2 * k2.omega + 2 * k3.omega + k4.omega) / 6;
    s = advance(s, sum, h);
    rates(s);  // leave the gear outputs at the new state
  }

  // Level, heading north, lowest wheel `gap_m` above the runway.
  State resting_state(double gap_m) const {
    double lowest = -1e9;
    for (const auto& c : gear.params().contacts)
      lowest = std::max(lowest, c.position_m.z() - cg_m.z());
    State s;
    s.position_ned = Eigen::Vector3d(0, 0, -lowest - gap_m);
    s.velocity_ned.setZero();
    s.ned_from_body.setIdentity();
    s.omega_body.setZero();
    return s;
  }
};

RigidAircraft c172() {
  Eigen::Matrix3d j = Eigen::Vector3d(948.0, 1346.0, 1967.0).asDiagonal();
  return RigidAircraft(reference::c172_gear(), 2400.0 * reference::kLb, j * reference::kSlugFt2,
                       reference::from_structural_in(41.0, 0.0, 36.5));
}

RigidAircraft b737() {
  Eigen::Matrix3d j = Eigen::Vector3d(562000.0, 1.473e6, 1.894e6).asDiagonal();
  j(0, 2) = j(2, 0) = -8000.0;
  return RigidAircraft(reference::b737_gear(), 107000.0 * reference::kLb, j * reference::kSlugFt2,
                       reference::from_structural_in(639.0, 0.0, -40.0));
}

struct AircraftCase {
  const char* name;
  RigidAircraft (*make)();
  double rate_hz;
};

class GearSettling : public ::testing::TestWithParam<AircraftCase> {};

TEST_P(GearSettling, SettlesAtTheStaticDeflectionOfEachGear) {
  RigidAircraft ac = GetParam().make();
  const double dt = 1.0 / GetParam().rate_hz;
  RigidAircraft::State s = ac.resting_state(0.05);  // dropped from 5 cm
  for (int i = 0; i < static_cast<int>(20.0 / dt); ++i) {
    ac.rk4(s, dt);
    ASSERT_TRUE(s.position_ned.allFinite() && s.omega_body.allFinite()) << "diverged at step " << i;
  }
  EXPECT_LT(s.velocity_ned.norm(), 1e-4);
  EXPECT_LT(s.omega_body.norm(), 1e-4);
  const LandingGear::Outputs& out = ac.gear.outputs();
  EXPECT_TRUE(out.weight_on_wheels);

  // Statics with the settled geometry: vertical loads balance the weight and its pitching
  // moment about the CG (lever arms: the ground points' north offsets from the CG).
  const Eigen::Matrix3d ned_from_body = s.ned_from_body.toRotationMatrix();
  auto north_arm = [&](std::size_t i) {
    const Eigen::Vector3d arm_body = ac.gear.params().contacts[i].position_m - ac.cg_m;
    return (ned_from_body * arm_body).x();
  };
  const double weight = ac.mass_kg * kG;
  const double d_nose = north_arm(0), d_main = 0.5 * (north_arm(1) + north_arm(2));
  const double nose_load = -weight * d_main / (d_nose - d_main);
  const double main_load = 0.5 * (weight - nose_load);
  double total = 0.0;
  for (std::size_t i = 0; i < 3; ++i) total += out.contacts[i].normal_force_n;
  EXPECT_NEAR(total / weight, 1.0, 1e-6);
  EXPECT_NEAR(out.contacts[0].normal_force_n / nose_load, 1.0, 0.01);
  const auto& gear = ac.gear.params().contacts;
  EXPECT_NEAR(out.contacts[0].compression_m, nose_load / gear[0].spring_npm,
              0.01 * nose_load / gear[0].spring_npm);
  for (std::size_t i : {1u, 2u}) {
    EXPECT_NEAR(out.contacts[i].compression_m, main_load / gear[i].spring_npm,
                0.01 * main_load / gear[i].spring_npm);
  }
}

INSTANTIATE_TEST_SUITE_P(LightAndTransport, GearSettling,
                         ::testing::Values(AircraftCase{"c172_50Hz", c172, 50.0},
                                           AircraftCase{"c172_400Hz", c172, 400.0},
                                           AircraftCase{"b737_50Hz", b737, 50.0},
                                           AircraftCase{"b737_400Hz", b737, 400.0}),
                         [](const auto& info) { return std::string(info.param.name); });

class GearHardLanding : public ::testing::TestWithParam<AircraftCase> {};

TEST_P(GearHardLanding, HighSinkRateStaysFiniteAndSettles) {
  RigidAircraft ac = GetParam().make();
  const double dt = 1.0 / GetParam().rate_hz;
  RigidAircraft::State s = ac.resting_state(0.0);
  s.velocity_ned = Eigen::Vector3d(60.0, 0.0, 6.0);  // 6 m/s sink (1200 ft/min) while rolling
  double peak_force = 0.0;
  for (int i = 0; i < static_cast<int>(30.0 / dt); ++i) {
    ac.rk4(s, dt);
    ASSERT_TRUE(s.position_ned.allFinite() && s.velocity_ned.allFinite() && s.omega_body.allFinite());
    ASSERT_TRUE(ac.gear.outputs().force_body_n.allFinite());
    peak_force = std::max(peak_force, ac.gear.outputs().force_body_n.norm());
  }
  EXPECT_GT(peak_force, 2.0 * ac.mass_kg * kG);   // a hard landing
  EXPECT_LT(std::abs(s.velocity_ned.z()), 1e-3);  // back at rest vertically
  EXPECT_LT(std::abs(s.velocity_ned.y()), 0.05);
}

INSTANTIATE_TEST_SUITE_P(LightAndTransport, GearHardLanding,
                         ::testing::Values(AircraftCase{"c172_50Hz", c172, 50.0},
                                           AircraftCase{"b737_50Hz", b737, 50.0},
                                           AircraftCase{"b737_400Hz", b737, 400.0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(LandingGear, ExtremePenetrationIsFinite) {
  const LandingGear::Outputs out =
      evaluate_single(reference::b737_gear().contacts[1], Eigen::Vector3d(0, 0, 50.0),
                      Eigen::Vector3d(80, 20, 200), 1.0);
  EXPECT_TRUE(out.force_body_n.allFinite());
  EXPECT_TRUE(out.moment_datum_body_nm.allFinite());
  const LandingGear::Outputs nan_in =
      evaluate_single(reference::b737_gear().contacts[1], Eigen::Vector3d(0, 0, std::nan("")),
                      Eigen::Vector3d::Zero());
  EXPECT_TRUE(nan_in.force_body_n.allFinite());
  EXPECT_FALSE(nan_in.weight_on_wheels);
}

TEST(LandingGear, BrakesDecelerateAtMuTimesTheBrakedWheelLoads) {
  for (double rate_hz : {50.0, 400.0}) {
    RigidAircraft ac = b737();
    const double dt = 1.0 / rate_hz;
    RigidAircraft::State s = ac.resting_state(0.0);
    for (int i = 0; i < static_cast<int>(10.0 / dt); ++i) ac.rk4(s, dt);  // settle
    s.velocity_ned.x() = 20.0;
    ac.brakes = 1.0;
    double t = 0.0, predicted_dv = 0.0;
    const double v0 = s.velocity_ned.x();
    while (s.velocity_ned.x() > 5.0 && t < 20.0) {
      // mu_static on the braked mains, rolling friction on the nose, per the gear's loads.
      const auto& c = ac.gear.outputs().contacts;
      const auto& g = ac.gear.params().contacts;
      predicted_dv += dt *
                      (g[1].static_friction * (c[1].normal_force_n + c[2].normal_force_n) +
                       g[0].rolling_friction * c[0].normal_force_n) /
                      ac.mass_kg;
      ac.rk4(s, dt);
      t += dt;
    }
    const double actual_dv = v0 - s.velocity_ned.x();
    EXPECT_NEAR(actual_dv / predicted_dv, 1.0, 0.02) << rate_hz << " Hz";
    const double mean_decel = actual_dv / t;
    EXPECT_GT(mean_decel, 0.6 * 0.8 * kG);  // most of the weight is on the braked mains
    EXPECT_LT(mean_decel, 0.8 * kG);
    EXPECT_NEAR(s.velocity_ned.y(), 0.0, 1e-6);  // symmetric braking runs straight
  }
}

TEST(LandingGear, ParkedWithBrakesStaysPut) {
  RigidAircraft ac = c172();
  RigidAircraft::State s = ac.resting_state(0.0);
  ac.brakes = 1.0;
  for (int i = 0; i < 50 * 10; ++i) ac.rk4(s, 0.02);  // settle on the struts
  const Eigen::Vector3d parked = s.position_ned;
  for (int i = 0; i < 50 * 60; ++i) ac.rk4(s, 0.02);
  EXPECT_LT((s.position_ned - parked).norm(), 1e-4);  // no creep, no chatter
  EXPECT_LT(s.velocity_ned.norm(), 1e-6);
}

TEST(LandingGear, DampingRatioHelper) {
  // Checked against the free response of a mass on a spring and damper, integrated here
  // (RK4, 0.1 ms steps): the logarithmic decrement delta = ln(x_n / x_n+1) between successive
  // peaks gives zeta = delta / sqrt(4 pi^2 + delta^2) (e.g. Thomson, Theory of Vibration with
  // Applications, section 2.6).
  const double k = 1e5, m = 1000.0;
  for (double c : {2e3, 4e3, 8e3}) {
    auto accel = [&](double x, double v) { return -(k * x + c * v) / m; };
    double x = 0.01, v = 0.0, previous_v = 0.0;
    std::vector<double> peaks;
    const double dt = 1e-4;
    for (int i = 0; i < 40000 && peaks.size() < 2; ++i) {
      const double k1x = v, k1v = accel(x, v);
      const double k2x = v + 0.5 * dt * k1v, k2v = accel(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v);
      const double k3x = v + 0.5 * dt * k2v, k3v = accel(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v);
      const double k4x = v + dt * k3v, k4v = accel(x + dt * k3x, v + dt * k3v);
      x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
      v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
      if (previous_v > 0.0 && v <= 0.0) peaks.push_back(x);  // a positive maximum
      previous_v = v;
    }
    ASSERT_EQ(peaks.size(), 2u) << c;
    const double delta = std::log(peaks[0] / peaks[1]);
    const double zeta = delta / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + delta * delta);
    EXPECT_NEAR(LandingGear::damping_ratio(k, c, m), zeta, 1e-3) << c;
  }
  // Critically damped at c = 2 sqrt(k m) = 20 000 N s/m: zeta = 1.
  EXPECT_NEAR(LandingGear::damping_ratio(k, 2e4, m), 1.0, 1e-12);
}

TEST(LandingGear, ValidateNamesTheBadField) {
  LandingGear::Params p = reference::c172_gear();
  p.contacts[2].spring_npm = 0.0;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("contacts[2].spring_npm"), std::string::npos) << e.what();
  }
  p = reference::c172_gear();
  p.contacts[0].dynamic_friction = 2.0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p = reference::c172_gear();
  p.friction_blend_speed_mps = 0.0;
  EXPECT_THROW(LandingGear{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
