// The aircraft executive: initial conditions, air data, moments moved to the CG, gust rates in
// the aerodynamics, weather, failures, gear, fuel, repositioning, substeps and determinism.
#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <cmath>

#include "flight/model/scenario/test/flight_test_support.hpp"
#include "flight/model/scenario/reposition.hpp"
#include "common/atmosphere/airspeed.hpp"

namespace fedsim::flight {
namespace {

using namespace testing;

AircraftInitialConditions flying(double lat_deg, double lon_deg, double alt_m, double speed_mps,
                                 double heading_deg) {
  AircraftInitialConditions ic;
  ic.position = {lat_deg * kDeg, lon_deg * kDeg, alt_m};
  ic.attitude.psi_rad = heading_deg * kDeg;
  ic.velocity_mps =
      speed_mps * Eigen::Vector3d(std::cos(heading_deg * kDeg), std::sin(heading_deg * kDeg), 0.0);
  return ic;
}

TEST(AircraftModel, ResetPutsTheAircraftWhereTheInitialConditionsSay) {
  for (const EarthModelKind earth : {EarthModelKind::kFlat, EarthModelKind::kWgs84}) {
    AircraftModel::Options options;
    options.earth = earth;
    auto model = make_model("c172.yaml", options);
    AircraftInitialConditions ic = flying(47.5, 8.5, 1500.0, 50.0, 30.0);
    ic.attitude.theta_rad = 3.0 * kDeg;
    ic.attitude.phi_rad = -10.0 * kDeg;
    model->reset(ic);
    const AircraftOutputs& o = model->outputs();
    EXPECT_NEAR(o.geodetic.lat_rad, ic.position.lat_rad, 1e-12);
    EXPECT_NEAR(o.geodetic.lon_rad, ic.position.lon_rad, 1e-12);
    EXPECT_NEAR(o.geodetic.alt_m, 1500.0, 1e-6);
    EXPECT_NEAR(o.height_agl_m, 1500.0, 1e-6);  // runway plane at MSL
    EXPECT_LT((o.velocity_ned_mps - ic.velocity_mps).norm(), 1e-9);
    EXPECT_NEAR(o.euler.phi_rad, ic.attitude.phi_rad, 1e-12);
    EXPECT_NEAR(o.euler.theta_rad, ic.attitude.theta_rad, 1e-12);
    EXPECT_NEAR(o.euler.psi_rad, ic.attitude.psi_rad, 1e-12);
    EXPECT_NEAR(o.tas_mps, 50.0, 1e-9);  // calm air
    EXPECT_NEAR(o.q_ned_from_body.norm(), 1.0, 1e-12);
    EXPECT_NEAR(o.time_s, 0.0, 0.0);
    // The ECEF position is the WGS-84 point of the geodetic one on either earth.
    EXPECT_LT((o.position_ecef_m - Wgs84::ecef_from_geodetic(o.geodetic)).norm(), 1e-6);
    // Air data agree with the atmosphere model at that height.
    const AirProperties air = Atmosphere().at(1500.0);
    EXPECT_NEAR(o.static_pressure_pa, air.pressure_pa, 1e-6);
    EXPECT_NEAR(o.cas_mps, cas_from_tas_mps(50.0, air), 1e-9);
    EXPECT_NEAR(o.qbar_pa, 0.5 * air.density_kgpm3 * 2500.0, 1e-9);
  }
}

TEST(AircraftModel, BodyVelocityInitialConditions) {
  auto model = make_model("c172.yaml");
  AircraftInitialConditions ic = flying(0.0, 0.0, 1000.0, 0.0, 90.0);
  ic.velocity_frame = AircraftInitialConditions::VelocityFrame::kBody;
  ic.velocity_mps = Eigen::Vector3d(50.0, 0.0, 5.0);
  ic.attitude.theta_rad = 0.1;
  model->reset(ic);
  const AircraftOutputs& o = model->outputs();
  EXPECT_LT((o.velocity_body_mps - ic.velocity_mps).norm(), 1e-9);
  EXPECT_NEAR(o.alpha_rad, std::atan2(5.0, 50.0), 1e-12);
  EXPECT_NEAR(o.velocity_ned_mps.x(), 0.0, 1e-9);  // heading east
}

TEST(AircraftModel, AlphaAndBetaAreDefinedAtZeroAirspeed) {
  auto model = make_model("c172.yaml");
  AircraftInitialConditions ic = flying(0.0, 0.0, 1000.0, 0.0, 0.0);
  model->reset(ic);
  const AircraftOutputs& o = model->outputs();
  EXPECT_EQ(o.tas_mps, 0.0);
  EXPECT_EQ(o.alpha_rad, 0.0);
  EXPECT_EQ(o.beta_rad, 0.0);
  EXPECT_EQ(o.qbar_pa, 0.0);
  EXPECT_TRUE(o.total_force_body_n.allFinite());
  model->step(0.01);
  EXPECT_TRUE(std::isfinite(model->outputs().alpha_rad));
  EXPECT_GT(model->outputs().velocity_ned_mps.z(), 0.0);  // falling
}

TEST(AircraftModel, TheWindAddsToTheAirspeed) {
  // 10 m/s from the north on an aircraft flying north at 50 m/s over the ground: 60 m/s of
  // airspeed; flying west, 10 m/s of sideslip wind from the right.
  auto model = make_model("c172.yaml");
  WeatherSettings weather;
  weather.wind.altitude_m = {0.0};
  weather.wind.speed_mps = {10.0};
  weather.wind.from_direction_rad = {0.0};
  model->set_weather(weather);
  model->reset(flying(0.0, 0.0, 1000.0, 50.0, 0.0));
  EXPECT_NEAR(model->outputs().tas_mps, 60.0, 1e-9);
  EXPECT_LT((model->outputs().wind_ned_mps - Eigen::Vector3d(-10.0, 0.0, 0.0)).norm(), 1e-12);
  model->reset(flying(0.0, 0.0, 1000.0, 50.0, 270.0));
  EXPECT_NEAR(model->outputs().beta_rad, std::atan2(10.0, 50.0), 1e-12);
}

TEST(AircraftModel, IsaOffsetsChangeTheAir) {
  auto model = make_model("c172.yaml");
  WeatherSettings weather;
  weather.atmosphere.sea_level_temperature_offset_k = 20.0;
  weather.atmosphere.sea_level_pressure_pa = 99000.0;
  model->set_weather(weather);
  model->reset(flying(0.0, 0.0, 0.0, 50.0, 0.0));
  EXPECT_NEAR(model->outputs().temperature_k, 308.15, 1e-9);
  EXPECT_NEAR(model->outputs().static_pressure_pa, 99000.0, 1e-6);
  WeatherSettings bad;
  bad.wind.altitude_m = {0.0, 0.0};  // not increasing
  bad.wind.speed_mps = {1.0, 2.0};
  bad.wind.from_direction_rad = {0.0, 0.0};
  EXPECT_THROW(model->set_weather(bad), std::invalid_argument);
}

TEST(AircraftModel, AerodynamicMomentsAreMovedFromTheReferencePointToTheCg) {
  // The drag sphere with its aerodynamic reference point 0.1 m below the CG: its drag (along
  // the air-relative velocity) then turns it. Falling at rest-attitude with a 30 m/s wind from
  // the north the drag points south, giving a moment r x F about the CG and nothing else.
  AircraftPack pack = load_pack("nasa_sphere_drag.yaml");
  const Eigen::Vector3d arm(0.0, 0.0, 0.1);
  pack.geometry.aero_reference_point_m = arm;
  AircraftModel model(pack, {});
  WeatherSettings weather;
  weather.wind.altitude_m = {0.0};
  weather.wind.speed_mps = {30.0};
  weather.wind.from_direction_rad = {0.0};
  model.set_weather(weather);
  model.reset(flying(0.0, 0.0, 1000.0, 0.0, 0.0));
  const AircraftOutputs& o = model.outputs();
  const Eigen::Vector3d drag = o.aero_force_body_n;
  EXPECT_LT(drag.x(),
            -0.5);  // 0.9 N: the air blows toward the south: drag on the body points south
  EXPECT_LT((o.total_moment_body_nm - arm.cross(drag)).norm(), 1e-12);
  // Euler's equation at rest: omega' = J^-1 M.
  EXPECT_LT((o.omega_dot_body_radps2 - o.inertia_kgm2.inverse() * arm.cross(drag)).norm(), 1e-12);
}

TEST(AircraftModel, EngineAndGearMomentsAreAboutTheCgAndTheTotalsAddUp) {
  auto model = make_model("c172.yaml");
  ASSERT_TRUE(Trim(*model).solve(cruise("c172.yaml")).converged);
  const AircraftOutputs& o = model->outputs();
  EXPECT_LT(
      (o.total_force_body_n - o.aero_force_body_n - o.propulsion_force_body_n - o.gear_force_body_n).norm(),
      1e-9);
  EXPECT_LT(
      (o.total_moment_body_nm - o.aero_moment_body_nm - o.propulsion_moment_body_nm - o.gear_moment_body_nm)
          .norm(),
      1e-9);
  // The aero moment about the CG: the coefficients' moment about the reference point plus the
  // force at its arm.
  const Eigen::Vector3d arm = model->pack().geometry.aero_reference_point_m - o.cg_m;
  EXPECT_LT((o.aero_moment_body_nm - (o.aero.moment_body + arm.cross(o.aero.force_body))).norm(), 1e-9);
  // The thrust acts on the engine's line (the datum-relative position less the CG) and the
  // propeller's torque rolls the airframe the other way round from its spin (spin_sense -1:
  // anticlockwise seen from behind, so the reaction rolls right, +x).
  const EngineSpec& engine = model->pack().engines.front();
  const Eigen::Vector3d thrust(o.engines[0].thrust_n, 0.0, 0.0);
  const Eigen::Vector3d thrust_moment = (engine.position_m - o.cg_m).cross(thrust);
  EXPECT_NEAR(o.propulsion_moment_body_nm.y(), thrust_moment.y(), 1e-9);
  EXPECT_GT(o.propulsion_moment_body_nm.x(), 0.0);
  // In trim the aileron holds the propeller's torque (aileron command into its rolling moment).
  EXPECT_LT(model->controls().aileron, 0.0);
}

TEST(AircraftModel, GustRatesSubtractFromTheBodyRatesInTheAerodynamics) {
  // Etkin: the aerodynamic rates are the body rates relative to the air less the gust rates
  // p_g, q_g, r_g. Recompute the rolling-moment coefficient (Clb, Clp, Clr, Clda, Cldr: no
  // alpha-dot term) from the outputs both ways; only the Etkin form matches.
  auto model = make_model("c172.yaml");
  WeatherSettings weather;
  weather.turbulence = Turbulence::Severity::kSevere;
  weather.turbulence_seed = 7;
  model->set_weather(weather);
  ASSERT_TRUE(Trim(*model).solve(cruise("c172.yaml")).converged);
  for (int i = 0; i < 100; ++i) model->step(0.02);
  const AircraftOutputs& o = model->outputs();
  ASSERT_GT(o.gust_rates_body_radps.norm(), 1e-4);
  Aerodynamics aero(model->pack());
  Aerodynamics::Inputs in;
  in.alpha_rad = o.alpha_rad;
  in.beta_rad = o.beta_rad;
  in.tas_mps = o.tas_mps;
  in.mach = o.mach;
  in.qbar_pa = o.qbar_pa;
  in.elevator_rad = o.elevator_rad;
  in.aileron_rad = o.aileron_rad;
  in.rudder_rad = o.rudder_rad;
  in.flap_norm = o.flap_norm;
  in.gear_norm = o.gear_norm;
  in.aero_rp_height_agl_m = 1e6;
  in.omega_air_body = o.omega_body_wrt_earth_radps - o.gust_rates_body_radps;
  EXPECT_NEAR(aero.compute(in, false).Cl, o.aero.Cl, 1e-12);
  in.omega_air_body = o.omega_body_wrt_earth_radps;
  EXPECT_GT(std::abs(aero.compute(in, false).Cl - o.aero.Cl), 1e-6);
}

TEST(AircraftModel, AFailedEngineStopsPushing) {
  // The 737 loses its left engine in cruise: that engine's thrust and fuel flow go (it spools
  // down), the right engine's thrust yaws the nose left.
  auto model = make_model("b737.yaml");
  ASSERT_TRUE(Trim(*model).solve(cruise("b737.yaml")).converged);
  const double thrust_before = model->outputs().engines[0].thrust_n;
  model->set_engine_failed(0, true);
  EXPECT_TRUE(model->engine_failed(0));
  for (int i = 0; i < 500; ++i) model->step(0.02);
  const AircraftOutputs& o = model->outputs();
  EXPECT_TRUE(o.engines[0].failed);
  EXPECT_FALSE(o.engines[0].running);
  EXPECT_EQ(o.engines[0].fuel_flow_kgps, 0.0);
  EXPECT_LT(o.engines[0].thrust_n, 0.05 * thrust_before);
  EXPECT_GT(o.engines[1].thrust_n, 0.9 * thrust_before);
  EXPECT_LT(wrap_pi(o.euler.psi_rad - 90.0 * kDeg), -1.0 * kDeg);  // yawed left
  model->set_engine_failed(0, false);
  for (int i = 0; i < 1000; ++i) model->step(0.02);
  EXPECT_GT(model->outputs().engines[0].thrust_n, 0.5 * thrust_before);  // relit, spooled up
  model->set_engine_failed(7, true);                                     // out of range: ignored
}

TEST(AircraftModel, RetractableGearTakesItsTransitTime) {
  auto model = make_model("b737.yaml");
  ASSERT_TRUE(Trim(*model).solve(cruise("b737.yaml")).converged);
  EXPECT_EQ(model->outputs().gear_norm, 0.0);
  AircraftControls c = model->controls();
  c.gear_down = true;
  model->set_controls(c);
  for (int i = 0; i < 125; ++i) model->step(0.02);  // 2.5 s of the 5 s transit
  EXPECT_NEAR(model->outputs().gear_norm, 0.5, 1e-9);
  EXPECT_GT(model->outputs().aero.CD, 0.0);
  for (int i = 0; i < 150; ++i) model->step(0.02);
  EXPECT_EQ(model->outputs().gear_norm, 1.0);
  // The C172's fixed gear is always down.
  auto c172 = make_model("c172.yaml");
  EXPECT_EQ(c172->outputs().gear_norm, 1.0);
}

TEST(AircraftModel, FuelFreezeKeepsTheMass) {
  auto model = make_model("b737.yaml");
  ASSERT_TRUE(Trim(*model).solve(cruise("b737.yaml")).converged);
  const double mass = model->outputs().mass_kg;
  model->set_fuel_frozen(true);
  for (int i = 0; i < 500; ++i) model->step(0.02);
  EXPECT_EQ(model->outputs().mass_kg, mass);
  EXPECT_GT(model->outputs().engines[0].fuel_flow_kgps, 0.1);
  model->set_fuel_frozen(false);
  for (int i = 0; i < 500; ++i) model->step(0.02);
  EXPECT_LT(model->outputs().mass_kg, mass - 5.0);
}

TEST(AircraftModel, TheRunwayPlaneCanBeMoved) {
  auto model = make_model("c172.yaml");
  model->set_runway_elevation_m(300.0);
  TrimRequest r;
  r.kind = TrimKind::kGround;
  ASSERT_TRUE(Trim(*model).solve(r).converged);
  EXPECT_NEAR(model->outputs().geodetic.alt_m - 300.0, model->outputs().height_agl_m, 1e-9);
  EXPECT_GT(model->outputs().height_agl_m, 0.5);
  EXPECT_LT(model->outputs().height_agl_m, 2.0);
}

TEST(AircraftModel, RepositionToAPointTrimsStraightAndLevel) {
  auto model = make_model("c172.yaml");
  const GeodeticPosition where{51.0 * kDeg, -1.0 * kDeg, 2000.0};
  const TrimResult t = reposition_to_point(*model, where, 200.0 * kDeg, 95.0 * kKt);
  ASSERT_TRUE(t.converged) << t.reason;
  EXPECT_NEAR(model->outputs().geodetic.lat_rad, where.lat_rad, 1e-12);
  EXPECT_NEAR(model->outputs().tas_mps, 95.0 * kKt, 1e-9);
  EXPECT_EQ(model->origin().lat_rad, where.lat_rad);  // the flat earth is pinned there
}

TEST(AircraftModel, RepositionToTheRunwayIsAtRestOnTheCentreline) {
  auto model = make_model("b737.yaml");
  const Runway runway{{37.6 * kDeg, -122.4 * kDeg, 4.0}, 280.0 * kDeg};
  const TrimResult t = reposition_to_runway(*model, runway);
  ASSERT_TRUE(t.converged) << t.reason;
  const AircraftOutputs& o = model->outputs();
  EXPECT_EQ(model->runway_elevation_m(), 4.0);
  EXPECT_TRUE(o.weight_on_wheels);
  EXPECT_EQ(o.gear_norm, 1.0);
  EXPECT_NEAR(o.euler.psi_rad, wrap_pi(280.0 * kDeg), 1e-12);
  EXPECT_NEAR(o.geodetic.lat_rad, runway.threshold.lat_rad, 1e-12);
  EXPECT_EQ(o.ground_speed_mps, 0.0);
}

TEST(AircraftModel, RepositionToTheApproachGateIsOnTheGlidePath) {
  auto model = make_model("c172.yaml");
  AircraftControls c = model->controls();
  c.flaps = 1.0 / 3.0;
  model->set_controls(c);
  const Runway runway{{47.0 * kDeg, 8.0 * kDeg, 400.0}, 90.0 * kDeg};
  const double gate_m = 3.0 * 1852.0;
  const TrimResult t = reposition_to_approach_gate(*model, runway, gate_m, 70.0 * kKt);
  ASSERT_TRUE(t.converged) << t.reason;
  const AircraftOutputs& o = model->outputs();
  // 50 ft over the threshold plus 3 nm at 3 deg: 1023 ft above the runway, 3 nm west of it.
  EXPECT_NEAR(o.height_agl_m, 50.0 * kFt + gate_m * std::tan(3.0 * kDeg), 1e-6);
  EXPECT_NEAR(std::asin(o.climb_rate_mps / o.tas_mps), -3.0 * kDeg, 1e-9);
  EXPECT_NEAR(o.euler.psi_rad, 90.0 * kDeg, 1e-9);
  EXPECT_NEAR(o.flap_norm, 1.0 / 3.0, 1e-12);
  const Eigen::Vector3d gate = Wgs84::ecef_from_geodetic(o.geodetic);
  const Eigen::Vector3d threshold = Wgs84::ecef_from_geodetic(runway.threshold);
  EXPECT_NEAR((gate - threshold).norm(), std::hypot(gate_m, o.height_agl_m), 5.0);
  EXPECT_LT(o.geodetic.lon_rad, runway.threshold.lon_rad);  // west of a runway heading east
  // Hands off it stays on the 3 deg path.
  for (int i = 0; i < 1000; ++i) model->step(0.02);
  EXPECT_NEAR(model->outputs().climb_rate_mps, -70.0 * kKt * std::sin(3.0 * kDeg), 0.3);
}

TEST(AircraftModel, InterceptStartLiesBesideTheCentrelineHeadingTowardsIt) {
  auto model = make_model("b737.yaml");
  AircraftControls c = model->controls();
  c.flaps = 0.875;
  c.gear_down = true;
  model->set_controls(c);
  const Runway runway{{47.0 * kDeg, 8.0 * kDeg, 400.0}, 90.0 * kDeg};  // landing east
  InterceptStart s;
  s.distance_m = 12.0 * 1852.0;
  s.left_m = 2.0 * 1852.0;  // left of an eastbound landing: north of the centreline
  s.intercept_rad = 30.0 * kDeg;
  s.altitude_msl_m = 400.0 + 2500.0 * kFt;
  s.airspeed_mps = 150.0 * kKt;
  s.airspeed_is_cas = true;
  const TrimResult t = reposition_to_intercept(*model, runway, s);
  ASSERT_TRUE(t.converged) << t.reason;
  const AircraftOutputs& o = model->outputs();
  // Seen from the threshold (GeographicLib's geodesic): hypot(12 NM, 2 NM) away, on the bearing
  // of the reciprocal runway heading (west) turned north, to the left of the landing, by atan(2 / 12).
  double range_m = 0.0, bearing_deg = 0.0, back_deg = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(47.0, 8.0, o.geodetic.lat_rad / kDeg, o.geodetic.lon_rad / kDeg, range_m,
                                           bearing_deg, back_deg);
  // (0.1 %: the flat-earth model reports its position through its tangent-plane mapping.)
  EXPECT_NEAR(range_m, std::hypot(s.distance_m, s.left_m), 1e-3 * range_m);
  EXPECT_NEAR(bearing_deg + (bearing_deg < 0 ? 360.0 : 0.0), 270.0 + std::atan2(s.left_m, s.distance_m) / kDeg, 0.01);
  EXPECT_NEAR(o.euler.psi_rad, 120.0 * kDeg, 1e-6);  // towards the centreline, south of east
  EXPECT_NEAR(o.cas_mps, 150.0 * kKt, 0.05);
  EXPECT_NEAR(o.climb_rate_mps, 0.0, 1e-6);
  EXPECT_NEAR(o.flap_norm, 0.875, 1e-12);
  // From the right the heading turns the other way; a bad field is refused by name.
  s.left_m = -s.left_m;
  ASSERT_TRUE(reposition_to_intercept(*model, runway, s).converged);
  EXPECT_NEAR(model->outputs().euler.psi_rad, 60.0 * kDeg, 1e-6);
  s.intercept_rad = std::nan("");
  try {
    reposition_to_intercept(*model, runway, s);
    ADD_FAILURE() << "a NaN intercept angle was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("intercept_rad"), std::string::npos) << e.what();
  }
  s.intercept_rad = 30.0 * kDeg;
  s.altitude_msl_m = 410.0;  // 10 m above the runway
  EXPECT_THROW(reposition_to_intercept(*model, runway, s), std::invalid_argument);
}

TEST(AircraftModel, SubstepsEqualShorterFrames) {
  // A 50 Hz frame in two substeps is exactly two 100 Hz frames (same steps, same order).
  AircraftModel::Options two;
  two.substeps = 2;
  auto a = make_model("c172.yaml", two);
  auto b = make_model("c172.yaml");
  ASSERT_TRUE(Trim(*a).solve(cruise("c172.yaml")).converged);
  ASSERT_TRUE(Trim(*b).solve(cruise("c172.yaml")).converged);
  AircraftControls c = a->controls();
  c.elevator -= 0.1;
  a->set_controls(c);
  b->set_controls(c);
  for (int i = 0; i < 200; ++i) {
    a->step(0.02);
    b->step(0.01);
    b->step(0.01);
  }
  EXPECT_EQ(a->outputs().geodetic.alt_m, b->outputs().geodetic.alt_m);
  EXPECT_EQ(a->outputs().omega_body_radps, b->outputs().omega_body_radps);
  EXPECT_NEAR(a->time_s(), 4.0, 1e-12);
}

TEST(AircraftModel, TurbulenceIsRepeatableForASeed) {
  auto run = [](std::uint64_t seed) {
    AircraftModel::Options options;
    options.turbulence_seed = seed;
    auto model = make_model("c172.yaml", options);
    WeatherSettings weather;
    weather.turbulence = Turbulence::Severity::kModerate;
    model->set_weather(weather);
    EXPECT_TRUE(Trim(*model).solve(cruise("c172.yaml")).converged);
    for (int i = 0; i < 1000; ++i) model->step(0.02);
    return model->outputs();
  };
  const AircraftOutputs a = run(11), b = run(11), c = run(12);
  EXPECT_EQ(a.geodetic.alt_m, b.geodetic.alt_m);
  EXPECT_EQ(a.omega_body_radps, b.omega_body_radps);
  EXPECT_EQ(a.gust_ned_mps, b.gust_ned_mps);
  EXPECT_NE(a.geodetic.alt_m, c.geodetic.alt_m);
  EXPECT_GT(a.gust_ned_mps.norm(), 0.0);
}

TEST(AircraftModel, BadConstructionAndInitialConditionsAreRefused) {
  AircraftModel::Options bad;
  bad.substeps = 0;
  EXPECT_THROW(AircraftModel(load_pack("c172.yaml"), bad), std::invalid_argument);
  auto model = make_model("c172.yaml");
  AircraftInitialConditions ic = flying(0.0, 0.0, 1000.0, 50.0, 0.0);
  ic.position.lat_rad = 2.0;
  EXPECT_THROW(model->reset(ic), std::invalid_argument);
  ic = flying(0.0, 0.0, 1000.0, 50.0, 0.0);
  ic.fuel_kg = {10.0};  // the C172 has two tanks
  EXPECT_THROW(model->reset(ic), std::invalid_argument);
  ic.velocity_mps.x() = NAN;
  ic.fuel_kg.clear();
  EXPECT_THROW(model->reset(ic), std::invalid_argument);
}

TEST(AircraftModel, InitialFuelLoadSetsTheMass) {
  auto model = make_model("c172.yaml");
  AircraftInitialConditions ic = flying(0.0, 0.0, 1000.0, 50.0, 0.0);
  const double full = model->outputs().mass_kg;
  ic.fuel_kg = {10.0, 20.0};
  model->reset(ic);
  EXPECT_NEAR(model->outputs().fuel_kg, 30.0, 1e-9);
  EXPECT_NEAR(model->outputs().mass_kg, full - (2.0 * 58.9670081 - 30.0), 1e-6);
}

TEST(AircraftModel, ControlsAreClampedAndNaNSafe) {
  auto model = make_model("c172.yaml");
  AircraftControls c;
  c.elevator = 3.0;
  c.aileron = NAN;
  c.set_throttle(-1.0);
  model->set_controls(c);
  EXPECT_EQ(model->controls().elevator, 1.0);
  EXPECT_EQ(model->controls().aileron, 0.0);
  EXPECT_EQ(model->controls().throttle[0], 0.0);
}

}  // namespace
}  // namespace fedsim::flight
