// Trim: convergence for both packs in cruise, climb and a 30 deg turn, the equilibrium holding
// when flown hands-off, ground trim load sharing, and clear failures for trims out of reach.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flight/model/scenario/test/flight_test_support.hpp"
#include "flight/model/scenario/reposition.hpp"

namespace fedsim::flight {
namespace {

using namespace testing;

struct TrimCase {
  std::string name;
  std::string pack;
  TrimRequest request;
};

TrimRequest climb(const std::string& pack) {
  // C172: 75 KTAS (near Vy) climbing at 3 deg (about 400 ft/min) from 4000 ft, POH climb power
  // available; 737: 280 KTAS at 10,000 ft climbing at 3 deg, gear up.
  TrimRequest r = cruise(pack);
  r.kind = TrimKind::kClimb;
  r.flight_path_rad = 3.0 * kDeg;
  r.airspeed_mps = (pack == "c172.yaml" ? 75.0 : 280.0) * kKt;
  if (pack == "b737.yaml") r.position.alt_m = 10000.0 * kFt;
  return r;
}

TrimRequest turn(const std::string& pack) {
  TrimRequest r = cruise(pack);
  r.kind = TrimKind::kTurn;
  r.bank_rad = 30.0 * kDeg;
  return r;
}

std::vector<TrimCase> trim_cases() {
  std::vector<TrimCase> cases;
  for (const std::string pack : {"c172.yaml", "b737.yaml"}) {
    const std::string stem = pack.substr(0, pack.find('.'));
    cases.push_back({stem + "_cruise", pack, cruise(pack)});
    cases.push_back({stem + "_climb", pack, climb(pack)});
    cases.push_back({stem + "_turn30", pack, turn(pack)});
  }
  return cases;
}

class TrimConverges : public ::testing::TestWithParam<TrimCase> {};

TEST_P(TrimConverges, EveryResidualWithinItsTolerance) {
  const TrimCase& c = GetParam();
  auto model = make_model(c.pack);
  const TrimResult t = Trim(*model).solve(c.request);
  ASSERT_TRUE(t.converged) << c.name << ": " << t.reason;
  EXPECT_TRUE(t.reason.empty());
  EXPECT_LE(t.iterations, 20);
  // The equilibrium checked from the forces and moments on the trimmed aircraft, not from the
  // trim's own residuals: Newton's and Euler's laws on the flat earth (NED inertial),
  //   F / m + g_body - omega x v = 0,   I^-1 (M - omega x (I omega + h_rotor)) = 0,
  // with the weight, the aerodynamic, propulsive and gear forces, the centripetal term of a
  // turn and the gyroscopic term of the spinning propeller, h_rotor = sense I_prop Omega x_body.
  {
    const AircraftOutputs& o = model->outputs();
    const Eigen::Vector3d g_body = o.ned_from_body.transpose() * Eigen::Vector3d(0.0, 0.0, kG0);
    const Eigen::Vector3d linear =
        o.total_force_body_n / o.mass_kg + g_body - o.omega_body_radps.cross(o.velocity_body_mps);
    Eigen::Vector3d h_rotor = Eigen::Vector3d::Zero();
    for (std::size_t e = 0; e < model->pack().engines.size(); ++e) {
      const EngineSpec& spec = model->pack().engines[e];
      if (spec.type != EngineType::piston_propeller) continue;
      ASSERT_EQ(spec.orientation_rad.norm(), 0.0);  // thrust axis along body x
      h_rotor.x() += spec.propeller.spin_sense * spec.propeller.inertia_kgm2 *
                     o.engines[e].propeller_rpm * 2.0 * kPi / 60.0;
    }
    const Eigen::Vector3d angular =
        o.inertia_kgm2.inverse() *
        (o.total_moment_body_nm - o.omega_body_radps.cross(o.inertia_kgm2 * o.omega_body_radps + h_rotor));
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::abs(linear[k]), 1e-4) << c.name << " force balance, axis " << k;
      EXPECT_LE(std::abs(angular[k]), 1e-5) << c.name << " moment balance, axis " << k;
    }
  }
  // The tolerances themselves: 1e-4 m/s^2 on forces, 1e-5 rad/s^2 on moments.
  EXPECT_EQ(t.tolerances[kUDot], 1e-4);
  EXPECT_EQ(t.tolerances[kQDot], 1e-5);

  // The model is left in the trimmed state, flying the requested condition.
  const AircraftOutputs& o = model->outputs();
  EXPECT_NEAR(o.tas_mps, c.request.airspeed_mps, 1e-9);
  EXPECT_NEAR(o.geodetic.alt_m, c.request.position.alt_m, 1e-6);
  EXPECT_EQ(model->controls(), t.controls);
  EXPECT_GT(t.controls.throttle[0], 0.0);
  EXPECT_LT(t.controls.throttle[0], 1.0);
  const double gamma = std::asin(o.climb_rate_mps / o.tas_mps);
  EXPECT_NEAR(gamma, c.request.flight_path_rad, 1e-9);
  EXPECT_NEAR(o.euler.psi_rad, c.request.heading_rad, 1e-9);
  if (c.request.kind == TrimKind::kTurn) {
    // Coordinated level turn: heading rate g tan(phi) / V, load factor 1 / cos(phi), ball
    // centred (the lateral specific force is one of the trim's equations).
    EXPECT_NEAR(o.euler.phi_rad, c.request.bank_rad, 1e-9);
    EXPECT_NEAR(t.turn_rate_radps, kG0 * std::tan(c.request.bank_rad) / o.tas_mps,
                0.01 * t.turn_rate_radps);
    EXPECT_NEAR(o.load_factor_z, 1.0 / std::cos(c.request.bank_rad), 0.01);
    EXPECT_LE(std::abs(o.specific_force_cg_body_mps2.y()), 1e-4);
  } else {
    EXPECT_NEAR(o.euler.phi_rad, 0.0, 1e-12);
    EXPECT_NEAR(o.omega_body_radps.norm(), 0.0, 1e-12);  // flat earth: straight flight, no rotation
    EXPECT_NEAR(t.theta_rad, t.alpha_rad + c.request.flight_path_rad, 1e-3);
  }
  // Within the pack's angle-of-attack limits and not stalled.
  EXPECT_FALSE(o.stalled);
  if (model->pack().limits.alpha_max_rad) {
    EXPECT_LT(t.alpha_rad, *model->pack().limits.alpha_max_rad);
  }
}

INSTANTIATE_TEST_SUITE_P(BothPacks, TrimConverges, ::testing::ValuesIn(trim_cases()),
                         [](const auto& info) { return info.param.name; });

/// Flies a trimmed model hands-off and returns the largest altitude and heading excursions.
struct Excursions {
  double altitude_m = 0.0;
  double heading_rad = 0.0;
  double airspeed_mps = 0.0;
};

Excursions fly_hands_off(AircraftModel& model, double duration_s, double rate_hz) {
  const AircraftOutputs start = model.outputs();
  Excursions e;
  const int frames = static_cast<int>(std::lround(duration_s * rate_hz));
  for (int i = 0; i < frames; ++i) {
    model.step(1.0 / rate_hz);
    const AircraftOutputs& o = model.outputs();
    e.altitude_m = std::max(e.altitude_m, std::abs(o.geodetic.alt_m - start.geodetic.alt_m));
    e.heading_rad =
        std::max(e.heading_rad, std::abs(wrap_pi(o.euler.psi_rad - start.euler.psi_rad)));
    e.airspeed_mps = std::max(e.airspeed_mps, std::abs(o.tas_mps - start.tas_mps));
  }
  return e;
}

TEST(TrimHolds, HandsOffCruiseHoldsAltitudeForAMinute) {
  // The trimmed state is an equilibrium of the model that flies it: hands off for 60 s with the
  // fuel frozen, the aircraft stays within 1 m of its altitude, 0.1 deg of its heading and
  // 0.1 m/s of its airspeed (what remains is integration error).
  for (const std::string pack : {"c172.yaml", "b737.yaml"}) {
    for (const IntegrationMethod method : {IntegrationMethod::kRk4, IntegrationMethod::kAb2}) {
      AircraftModel::Options options;
      options.integrator = method;
      auto model = make_model(pack, options);
      ASSERT_TRUE(Trim(*model).solve(cruise(pack)).converged);
      model->set_fuel_frozen(true);
      const Excursions e = fly_hands_off(*model, 60.0, 60.0);
      EXPECT_LT(e.altitude_m, 1.0) << pack << " " << to_string(method);
      EXPECT_LT(e.heading_rad, 0.1 * kDeg) << pack << " " << to_string(method);
      EXPECT_LT(e.airspeed_mps, 0.1) << pack << " " << to_string(method);
    }
  }
}

TEST(TrimHolds, BurningFuelTheAircraftClimbsAsItLightens) {
  // With the fuel burning the aircraft gets lighter at m' / m per second: the lift surplus
  // g (m'/m) t accelerates it upward, about g (m'/m) t^3 / 6 of climb after t seconds before
  // the phugoid turns it round (the 737 burns 1.2 kg/s of 48.5 t: about 9 m in a minute).
  for (const std::string pack : {"c172.yaml", "b737.yaml"}) {
    auto model = make_model(pack);
    ASSERT_TRUE(Trim(*model).solve(cruise(pack)).converged);
    const double mass0 = model->outputs().mass_kg;
    double flow = 0.0;
    for (const EngineOutputs& e : model->outputs().engines) flow += e.fuel_flow_kgps;
    const Excursions e = fly_hands_off(*model, 60.0, 60.0);
    EXPECT_NEAR(mass0 - model->outputs().mass_kg, flow * 60.0, 0.02 * flow * 60.0) << pack;
    const double climb_estimate = kG0 * flow / mass0 * std::pow(60.0, 3) / 6.0;
    EXPECT_LT(e.altitude_m, 1.0 + 1.5 * climb_estimate) << pack;
    EXPECT_GT(model->outputs().geodetic.alt_m, cruise(pack).position.alt_m) << pack;
  }
}

TEST(TrimHolds, TrimmedOnTheRotatingEarth) {
  // On the WGS-84 earth the trim adds the transport and earth rates: level flight eastward
  // at 28 N still trims to the tolerances and holds its altitude (above the ellipsoid).
  AircraftModel::Options options;
  options.earth = EarthModelKind::kWgs84;
  options.integrator = IntegrationMethod::kRk4;
  auto model = make_model("c172.yaml", options);
  const TrimResult t = Trim(*model).solve(cruise("c172.yaml"));
  ASSERT_TRUE(t.converged) << t.reason;
  EXPECT_LT(fly_hands_off(*model, 60.0, 50.0).altitude_m, 3.0);
}

TEST(TrimHolds, CalibratedAirspeedRequest) {
  auto model = make_model("c172.yaml");
  TrimRequest r = cruise("c172.yaml");
  r.position.alt_m = 8000.0 * kFt;
  r.airspeed_mps = 90.0 * kKt;
  r.airspeed_is_cas = true;
  const TrimResult t = Trim(*model).solve(r);
  ASSERT_TRUE(t.converged) << t.reason;
  EXPECT_NEAR(model->outputs().cas_mps, 90.0 * kKt, 1e-6);
  EXPECT_GT(model->outputs().tas_mps, 100.0 * kKt);  // about 11 % more at 8000 ft
}

TEST(TrimFails, ThrottleSaturatedSaysWhyAndByHowMuch) {
  // 160 KTAS is beyond the C172's maximum level speed (about 125 KTAS): the trim must fail
  // and say so, not return a state that is not an equilibrium.
  auto model = make_model("c172.yaml");
  TrimRequest r = cruise("c172.yaml");
  r.airspeed_mps = 160.0 * kKt;
  const TrimResult t = Trim(*model).solve(r);
  EXPECT_FALSE(t.converged);
  EXPECT_EQ(
      t.reason.rfind("throttle saturated at 1.0: the aircraft cannot hold 4000 ft at 160 KTAS", 0),
      0u)
      << t.reason;
  EXPECT_NE(t.reason.find("u_dot_mps2 -"), std::string::npos) << t.reason;  // decelerating
  EXPECT_LT(t.residuals[kUDot], -0.1);
  EXPECT_DOUBLE_EQ(t.controls.throttle[0], 1.0);
}

TEST(TrimFails, BelowTheStallSpeed) {
  // 35 KTAS clean is far below the C172's 48 KCAS clean stall: the wing cannot lift it.
  auto model = make_model("c172.yaml");
  TrimRequest r = cruise("c172.yaml");
  r.airspeed_mps = 35.0 * kKt;
  const TrimResult t = Trim(*model).solve(r);
  EXPECT_FALSE(t.converged);
  const bool says_why = t.reason.find("angle of attack at its limit") != std::string::npos ||
                        t.reason.find("elevator saturated") != std::string::npos;
  EXPECT_TRUE(says_why) << t.reason;
  EXPECT_NE(t.reason.find("35 KTAS"), std::string::npos) << t.reason;
}

TEST(TrimFails, DescentTooSteepForIdle) {
  // At 280 KTAS the clean 737's drag less its idle thrust holds a descent of a few degrees;
  // 10 deg would need more drag than that (speedbrake), so the throttle sits at idle.
  auto model = make_model("b737.yaml");
  TrimRequest r = climb("b737.yaml");
  r.flight_path_rad = -10.0 * kDeg;
  const TrimResult t = Trim(*model).solve(r);
  EXPECT_FALSE(t.converged);
  EXPECT_EQ(
      t.reason.rfind("throttle saturated at idle: the aircraft cannot descend at 10.0 deg", 0), 0u)
      << t.reason;
}

TEST(TrimFails, MalformedRequestThrows) {
  auto model = make_model("c172.yaml");
  TrimRequest r = cruise("c172.yaml");
  r.airspeed_mps = 0.0;
  EXPECT_THROW(Trim(*model).solve(r), std::invalid_argument);
  EXPECT_THROW(trim_kind_from_name("loop"), std::invalid_argument);
}

TEST(TrimFails, ABodyWithoutWheelsCannotRestOnTheGround) {
  auto model = make_model("nasa_sphere.yaml");
  TrimRequest r;
  r.kind = TrimKind::kGround;
  const TrimResult t = Trim(*model).solve(r);
  EXPECT_FALSE(t.converged);
  EXPECT_EQ(t.reason, "the aircraft has no wheels to rest on");
}

class GroundTrim : public ::testing::TestWithParam<std::string> {};

TEST_P(GroundTrim, RestsOnItsWheelsWithTheStaticLoadSplit) {
  auto model = make_model(GetParam());
  model->set_runway_elevation_m(120.0);
  TrimRequest r;
  r.kind = TrimKind::kGround;
  r.position = {0.7, -1.2, 0.0};
  r.heading_rad = 280.0 * kDeg;
  const TrimResult t = Trim(*model).solve(r);
  ASSERT_TRUE(t.converged) << t.reason;
  const AircraftOutputs& o = model->outputs();
  EXPECT_TRUE(o.weight_on_wheels);
  EXPECT_EQ(t.controls.throttle[0], 0.0);
  EXPECT_EQ(t.controls.brake_left, 1.0);
  EXPECT_NEAR(o.ground_speed_mps, 0.0, 1e-12);
  EXPECT_GT(o.height_agl_m, 0.0);
  // The struts carry the weight (no lift at rest)...
  EXPECT_NEAR(o.gear_normal_force_n, o.mass_kg * kG0, 1e-3 * o.mass_kg * kG0);
  // ...shared between nose and main wheels as their lever arms about the CG say (statics:
  // N_nose / W = -a_main / (a_nose - a_main), a the horizontal distance ahead of the CG along
  // the heading, taken with the attitude the aircraft sits at).
  const auto& contacts = model->pack().landing_gear.contacts;
  const Eigen::Vector3d heading(std::cos(r.heading_rad), std::sin(r.heading_rad), 0.0);
  auto ahead_of_cg = [&](std::size_t i) {
    return heading.dot(o.ned_from_body * (contacts[i].position_m - o.cg_m));
  };
  const double a_nose = ahead_of_cg(0), a_main = 0.5 * (ahead_of_cg(1) + ahead_of_cg(2));
  const double expected_share = -a_main / (a_nose - a_main);
  EXPECT_NEAR(o.contacts[0].normal_force_n / o.gear_normal_force_n, expected_share, 0.005);
  // The mains differ only by the lateral CG offset and the propeller torque: within 2 %.
  EXPECT_NEAR(o.contacts[1].normal_force_n, o.contacts[2].normal_force_n,
              0.02 * o.gear_normal_force_n);
  // Left there with the brakes on, it stays put.
  for (int i = 0; i < 500; ++i) model->step(0.02);
  EXPECT_LT(std::hypot(model->outputs().north_m, model->outputs().east_m), 0.5);
  EXPECT_TRUE(model->outputs().weight_on_wheels);
}

TEST(GroundTrimThrottle, HoldsAFullThrottleRunUpOnTheBrakes) {
  // A take-off start: the C172 parked with the engine settled at full throttle.
  auto model = make_model("c172.yaml");
  TrimRequest r;
  r.kind = TrimKind::kGround;
  r.position = {0.7, -1.2, 0.0};
  r.ground_throttle = 1.0;
  const TrimResult t = Trim(*model).solve(r);
  ASSERT_TRUE(t.converged) << t.reason;
  EXPECT_EQ(t.controls.throttle[0], 1.0);
  EXPECT_EQ(t.controls.brake_left, 1.0);
  const EngineOutputs& engine = model->outputs().engines[0];
  EXPECT_GT(engine.rpm, 2000.0);  // settled at the static full-throttle rpm, not at idle
  EXPECT_GT(engine.thrust_n, 1000.0);
  // Settled: the shaft neither speeds up nor slows down over the next seconds.
  const double rpm = engine.rpm;
  for (int i = 0; i < 100; ++i) model->step(0.02);
  EXPECT_NEAR(model->outputs().engines[0].rpm, rpm, 1e-3 * rpm);
  // The brakes hold: the gear's friction stays inside its viscous band (0.25 m/s), where a
  // braked wheel under a steady push creeps at a steady speed instead of sliding away
  // (data/aircraft/README.md, landing_gear).
  const double creep_mps = model->outputs().ground_speed_mps;
  for (int i = 0; i < 50; ++i) model->step(0.02);
  EXPECT_LT(model->outputs().ground_speed_mps, 0.25);
  EXPECT_NEAR(model->outputs().ground_speed_mps, creep_mps, 0.01);

  for (double bad : {-0.01, 1.01, std::nan(""), double{INFINITY}}) {
    r.ground_throttle = bad;
    EXPECT_THROW(Trim(*model).solve(r), std::invalid_argument) << bad;
    EXPECT_THROW(reposition_to_runway(*model, {{0.7, -1.2, 0.0}, 0.0}, bad),
                 std::invalid_argument)
        << bad;
  }
}

INSTANTIATE_TEST_SUITE_P(BothPacks, GroundTrim, ::testing::Values("c172.yaml", "b737.yaml"),
                         [](const auto& info) { return info.param.substr(0, 4); });

}  // namespace
}  // namespace fedsim::flight
