// Tests of the aerodynamic build-up: c172 coefficients against the JSBSim table numbers,
// stability-derivative signs, force directions, NASA brick damping moments, hysteresis, CL^2,
// and the flow beyond the packs' data (tailwind, crosswind, flat fall).
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "common/util/allocation_counter.hpp"
#include "flight/model/aircraft/aerodynamics.hpp"


namespace fedsim::flight {
namespace {

constexpr double kPi = units::kPi;
constexpr double kDeg = kPi / 180.0;

AircraftPack pack(const std::string& name) {
  return load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/" + name);
}

// Cruise-like air data; everything else zero (flaps up, controls neutral, out of ground effect).
Aerodynamics::Inputs cruise(double alpha_rad, double tas_mps = 50.0) {
  Aerodynamics::Inputs in;
  in.alpha_rad = alpha_rad;
  in.tas_mps = tas_mps;
  in.mach = tas_mps / 340.294;
  in.qbar_pa = 0.5 * 1.225 * tas_mps * tas_mps;
  return in;
}

// Linear interpolation in a JSBSim 1-D breakpoint list (independent of fedsim's tables).
double interp(const std::vector<double>& x, const std::vector<double>& y, double at) {
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    if (at <= x[i + 1]) return y[i] + (y[i + 1] - y[i]) * (at - x[i]) / (x[i + 1] - x[i]);
  }
  return y.back();
}

// c172x.xml, CLwbh (alpha-rad, stall-hyst-norm = 0 column) and CLalpha (alpha-deg rows,
// beta-deg 0 column, flap-pos-deg 0 page) copied from the JSBSim file.
const std::vector<double> kClwbhAlpha = {-0.09, 0.0, 0.09, 0.1, 0.12, 0.14, 0.16, 0.17, 0.19};
const std::vector<double> kClwbhValue = {-0.22, 0.25, 0.73, 0.83, 0.92, 1.02, 1.08, 1.13, 1.19};
double jsbsim_clalpha_at_beta0_flap0(double alpha_deg) {
  if (alpha_deg == 0.0) return 4.657724;
  if (alpha_deg == 5.0) return 4.501400;
  return 4.271521;  // 10 deg
}

TEST(Aerodynamics, C172LiftMatchesTheJsbsimTermsFlapsUp) {
  Aerodynamics aero(pack("c172.yaml"));
  for (double alpha_deg : {0.0, 5.0, 10.0}) {
    SCOPED_TRACE(alpha_deg);
    const double alpha = alpha_deg * kDeg;
    // CL = CLwbh(alpha) * ground effect (1.0 out of it) + CLalpha(alpha, 0, 0) * alpha.
    const double expected = interp(kClwbhAlpha, kClwbhValue, alpha) +
                            jsbsim_clalpha_at_beta0_flap0(alpha_deg) * alpha;
    EXPECT_NEAR(aero.evaluate(cruise(alpha)).CL, expected, 1e-9);
  }
  EXPECT_NEAR(aero.evaluate(cruise(5.0 * kDeg)).CL, 1.108243, 1e-6);  // hand sum
}

TEST(Aerodynamics, C172StaticAndDynamicStability) {
  Aerodynamics aero(pack("c172.yaml"));
  const double h = 1e-4;
  auto coefficients = [&](auto change) {
    Aerodynamics::Inputs in = cruise(2.0 * kDeg);
    change(in);
    return aero.compute(in, false);
  };
  const auto base = coefficients([](auto&) {});
  const auto alpha = coefficients([&](auto& in) { in.alpha_rad += h; });
  const auto de = coefficients([&](auto& in) { in.elevator_rad = h; });
  const auto beta = coefficients([&](auto& in) { in.beta_rad = h; });
  const double b_2v = 36.0 * units::kFtToM / (2.0 * 50.0);
  const auto p = coefficients([&](auto& in) { in.omega_air_body.x() = h / b_2v; });
  const auto r = coefficients([&](auto& in) { in.omega_air_body.z() = h / b_2v; });

  const double cm_alpha = (alpha.Cm - base.Cm) / h;
  EXPECT_LT(cm_alpha, 0.0);
  EXPECT_NEAR(cm_alpha, -1.8, 1e-6);                     // Cmalpha of c172x.xml
  EXPECT_NEAR((de.Cm - base.Cm) / h, -1.28, 1e-6);        // Cm_de < 0
  EXPECT_NEAR((p.Cl - base.Cl) / h, -0.47, 1e-6);         // Cl_p < 0 (roll damping)
  const double cn_r = (r.Cn - base.Cn) / h;
  EXPECT_NEAR(cn_r, -0.099, 1e-6);                        // Cn_r < 0 (yaw damping)
  const double cn_beta = (beta.Cn - base.Cn) / h;
  EXPECT_NEAR(cn_beta, 0.0227 / 0.349, 1e-6);             // Cn_beta > 0 (weathercock)
  EXPECT_GT(cn_beta, 0.0);
  EXPECT_LT((beta.Cl - base.Cl) / h, 0.0);                // dihedral effect Cl_beta < 0
}

TEST(Aerodynamics, ControlCommandsMatchDesignSignConventions) {
  // DESIGN.md: +1 elevator = nose down, +1 aileron = right wing down, +1 rudder = nose right.
  for (const char* name : {"c172.yaml", "b737.yaml"}) {
    SCOPED_TRACE(name);
    const AircraftPack p = pack(name);
    Aerodynamics aero(p);
    const auto base = aero.compute(cruise(0.0), false);
    auto with = [&](auto set) {
      Aerodynamics::Inputs in = cruise(0.0);
      set(in);
      return aero.compute(in, false);
    };
    const auto& fc = p.flight_controls;
    const double de = fc.elevator->demanded_deflection_rad(1.0);
    const double da = fc.aileron->demanded_deflection_rad(1.0);
    const double dr = fc.rudder->demanded_deflection_rad(1.0);
    EXPECT_LT(with([&](auto& in) { in.elevator_rad = de; }).moment_body.y(), base.moment_body.y());
    EXPECT_GT(with([&](auto& in) { in.aileron_rad = da; }).moment_body.x(), base.moment_body.x());
    EXPECT_GT(with([&](auto& in) { in.rudder_rad = dr; }).moment_body.z(), base.moment_body.z());
  }
}

TEST(Aerodynamics, LiftActsUpAndDragOpposesTheAirVelocity) {
  Aerodynamics aero(pack("c172.yaml"));
  const double alpha = 3.0 * kDeg, beta = 2.0 * kDeg;
  Aerodynamics::Inputs in = cruise(alpha);
  in.beta_rad = beta;
  const auto out = aero.compute(in, false);
  ASSERT_GT(out.CL, 0.0);
  ASSERT_GT(out.CD, 0.0);
  EXPECT_LT(out.force_body.z(), -0.9 * out.lift_n);  // lift is up: body -z at small alpha
  // Air-relative velocity direction in body axes; drag is the force component against it.
  const Eigen::Vector3d v_hat(std::cos(alpha) * std::cos(beta), std::sin(beta),
                              std::sin(alpha) * std::cos(beta));
  EXPECT_NEAR(out.force_body.dot(v_hat), -out.drag_n, 1e-9 * out.lift_n);
  // Lift is perpendicular to the velocity, in the plane of symmetry.
  const Eigen::Vector3d lift_dir(std::sin(alpha), 0.0, -std::cos(alpha));
  EXPECT_NEAR(out.force_body.dot(lift_dir), out.lift_n, 1e-9 * out.lift_n);
  EXPECT_NEAR(out.lift_n, in.qbar_pa * 174.0 * units::kFtToM * units::kFtToM * out.CL, 1e-6);
}

TEST(Aerodynamics, SphereDragIsExactlyAgainstTheVelocity) {
  Aerodynamics aero(pack("nasa_sphere_drag.yaml"));
  const double alpha = 0.7, beta = -0.4;
  Aerodynamics::Inputs in = cruise(alpha, 120.0);
  in.beta_rad = beta;
  const auto out = aero.evaluate(in);
  const Eigen::Vector3d v_hat(std::cos(alpha) * std::cos(beta), std::sin(beta),
                              std::sin(alpha) * std::cos(beta));
  const double drag = in.qbar_pa * 0.1963495 * units::kFtToM * units::kFtToM * 0.1;
  EXPECT_NEAR((out.force_body + drag * v_hat).norm(), 0.0, 1e-9 * drag);
  EXPECT_DOUBLE_EQ(out.moment_body.norm(), 0.0);
}

TEST(Aerodynamics, NasaBrickDampingMomentsFollowTheReportFormula) {
  Aerodynamics aero(pack("nasa_brick_damped.yaml"));
  Aerodynamics::Inputs in;
  in.tas_mps = 30.0;
  const double rho = 0.458;  // near 30,000 ft
  in.qbar_pa = 0.5 * rho * in.tas_mps * in.tas_mps;
  in.omega_air_body = Eigen::Vector3d(10.0, 20.0, 30.0) * kDeg;
  const auto out = aero.evaluate(in);
  // NASA TM-2015-218675 brick: L = 1/4 rho V S b^2 Clp p (seed eq. 3.19), with S = 8 x 4 in,
  // b = 4 in, c = 8 in and Clp = Cmq = Cnr = -1.
  const double in_m = 0.0254, s = 32.0 * in_m * in_m, b = 4.0 * in_m, c = 8.0 * in_m;
  const double k = 0.25 * rho * in.tas_mps * s;
  EXPECT_NEAR(out.moment_body.x(), -k * b * b * in.omega_air_body.x(), 1e-12);
  EXPECT_NEAR(out.moment_body.y(), -k * c * c * in.omega_air_body.y(), 1e-12);
  EXPECT_NEAR(out.moment_body.z(), -k * b * b * in.omega_air_body.z(), 1e-12);
  EXPECT_DOUBLE_EQ(out.force_body.norm(), 0.0);
  // At rest the rate terms vanish instead of dividing by zero.
  in.tas_mps = 0.0;
  in.qbar_pa = 0.0;
  EXPECT_DOUBLE_EQ(aero.evaluate(in).moment_body.norm(), 0.0);
}

TEST(Aerodynamics, UndampedBrickAndDraglessSphereProduceNothing) {
  for (const char* name : {"nasa_brick.yaml", "nasa_sphere.yaml"}) {
    Aerodynamics aero(pack(name));
    Aerodynamics::Inputs in = cruise(0.3, 100.0);
    in.omega_air_body = Eigen::Vector3d(1.0, 2.0, 3.0);
    const auto out = aero.evaluate(in);
    EXPECT_DOUBLE_EQ(out.force_body.norm(), 0.0) << name;
    EXPECT_DOUBLE_EQ(out.moment_body.norm(), 0.0) << name;
  }
}

TEST(Aerodynamics, C172StallHysteresisFollowsJsbsimLimits) {
  Aerodynamics aero(pack("c172.yaml"));
  const double alpha = 0.2;
  const double unstalled = aero.evaluate(cruise(alpha)).CL;
  EXPECT_FALSE(aero.stall_hysteresis_active());
  aero.evaluate(cruise(0.37));  // above 0.36 rad: stalled
  EXPECT_TRUE(aero.stall_hysteresis_active());
  const double stalled = aero.evaluate(cruise(alpha)).CL;  // still stalled above 0.09 rad
  // CLwbh at 0.2 rad: 1.22 unstalled, 0.855 stalled (c172x.xml table columns 0 and 1).
  EXPECT_NEAR(unstalled - stalled, 1.22 - 0.855, 1e-9);
  aero.evaluate(cruise(0.05));  // below 0.09 rad: recovered
  EXPECT_FALSE(aero.stall_hysteresis_active());
  aero.evaluate(cruise(0.37));
  aero.reset();
  EXPECT_FALSE(aero.stall_hysteresis_active());
}

TEST(Aerodynamics, C172GroundEffectScalesTheLiftTerms) {
  Aerodynamics aero(pack("c172.yaml"));
  Aerodynamics::Inputs in = cruise(0.0);  // CLalpha term is zero at alpha 0
  const double free_air = aero.compute(in, false).CL;
  in.aero_rp_height_agl_m = 0.1 * 36.0 * units::kFtToM;  // h/b = 0.1: factor 1.127
  EXPECT_NEAR(aero.compute(in, false).CL, 1.127 * free_air, 1e-12);
}

TEST(Aerodynamics, B737InducedDragUsesThisEvaluationsLift) {
  Aerodynamics aero(pack("b737.yaml"));
  Aerodynamics::Inputs in = cruise(0.1, 200.0);
  const auto out = aero.compute(in, false);
  // CL = table(0.1) = 0.2 + 1.0 * 0.1 / 0.23; CD = CD0(alpha) + 0.043 CL^2 + CDmach(0.588).
  const double cl = 0.2 + 0.1 / 0.23;
  EXPECT_NEAR(out.CL, cl, 1e-12);
  const double cd0 = 0.021 + 0.021 * 0.1 / 0.26;
  EXPECT_NEAR(out.CD, cd0 + 0.043 * cl * cl, 1e-12);
}

TEST(Aerodynamics, FlapDegreesComeFromTheNormalisedPosition) {
  Aerodynamics aero(pack("c172.yaml"));
  Aerodynamics::Inputs in = cruise(0.0);
  const double up = aero.compute(in, false).CL;
  in.flap_norm = 1.0 / 3.0;  // 10 deg of 30: CLDf 0.25, and CLalpha's page moves (alpha 0)
  EXPECT_NEAR(aero.compute(in, false).CL - up, 0.25, 1e-9);
}

TEST(Aerodynamics, EvaluationDoesNotAllocate) {
  Aerodynamics aero(pack("c172.yaml"));
  Aerodynamics::Inputs in = cruise(0.1);
  in.omega_air_body = Eigen::Vector3d(0.1, 0.2, 0.3);
  in.flap_norm = 0.5;
  {
    const util::AllocationScope probe_scope;
    { std::vector<double> probe(3); }  // the counter itself must see this one
    ASSERT_EQ(probe_scope.allocations(), 1u);
  }
  const util::AllocationScope scope;
  double sink = 0.0;
  for (int i = 0; i < 100; ++i) sink += aero.evaluate(in).CL;
  EXPECT_EQ(scope.allocations(), 0u);
  EXPECT_GT(sink, 0.0);
}

// ---- Flow beyond the pack's data -------------------------------------------------------------

// Any flow direction at 10 m/s near sea level (a parked aircraft in a 20 kt wind).
Aerodynamics::Inputs wind_from(double alpha_rad, double beta_rad) {
  Aerodynamics::Inputs in = cruise(alpha_rad, 10.0);
  in.beta_rad = beta_rad;
  return in;
}

double qbar_s(const AircraftPack& p, const Aerodynamics::Inputs& in) {
  return in.qbar_pa * p.geometry.wing_area_m2;
}

TEST(AeroFlowEnvelope, SpansThePacksTablesAndCapsWhereAlphaIsLost) {
  // C172: alpha from CLalpha's -10 deg row to CLwbh's 0.36 rad, beta +-0.349 rad (CYb, Clb,
  // Cnb). 737: alpha and beta +-1.57 rad (CD0, CDbeta), beta capped at 60 deg so that the
  // weight is 0 in a sideways flow, where alpha is undefined.
  const AeroFlowEnvelope c172 = Aerodynamics(pack("c172.yaml")).envelope();
  ASSERT_TRUE(c172.limits_alpha() && c172.limits_beta());
  EXPECT_DOUBLE_EQ(c172.alpha_min_rad(), -0.1745329252);
  EXPECT_DOUBLE_EQ(c172.alpha_max_rad(), 0.36);
  EXPECT_DOUBLE_EQ(c172.beta_min_rad(), -0.349);
  EXPECT_DOUBLE_EQ(c172.beta_max_rad(), 0.349);
  const AeroFlowEnvelope b737 = Aerodynamics(pack("b737.yaml")).envelope();
  EXPECT_DOUBLE_EQ(b737.alpha_min_rad(), -1.57);
  EXPECT_DOUBLE_EQ(b737.alpha_max_rad(), 1.57);
  EXPECT_NEAR(b737.beta_max_rad(), 60.0 * kDeg, 1e-12);
  EXPECT_NEAR(b737.beta_min_rad(), -60.0 * kDeg, 1e-12);
  // The NASA bodies' coefficients depend on no flow angle: nothing is limited.
  for (const char* name : {"nasa_sphere_drag.yaml", "nasa_brick_damped.yaml"}) {
    const AeroFlowEnvelope none = Aerodynamics(pack(name)).envelope();
    EXPECT_FALSE(none.limits_alpha() || none.limits_beta()) << name;
    EXPECT_EQ(none.attached_weight(kPi, 1.5), 1.0) << name;
  }
  // The weight: 1 inside, cos^2 over 30 deg outside.
  EXPECT_EQ(c172.attached_weight(0.36, 0.349), 1.0);
  EXPECT_NEAR(c172.attached_weight(0.36 + 15.0 * kDeg, 0.0), 0.5, 1e-12);
  EXPECT_NEAR(c172.attached_weight(0.0, -0.349 - 15.0 * kDeg), 0.5, 1e-12);
  EXPECT_EQ(c172.attached_weight(0.36 + 30.0 * kDeg, 0.0), 0.0);
}

TEST(AeroFlowEnvelope, InsideTheDataTheBuildUpIsUntouched) {
  // The limits and the weight are the identity inside the envelope, so every in-envelope
  // number (the JSBSim checks above) is the pack's own.
  Aerodynamics aero(pack("c172.yaml"));
  for (double alpha : {-0.17, 0.0, 0.2, 0.36}) {
    for (double beta : {-0.349, 0.0, 0.3}) {
      const auto out = aero.compute(wind_from(alpha, beta), false);
      EXPECT_EQ(out.attached_weight, 1.0);
      EXPECT_EQ(aero.envelope().limited_alpha(alpha), alpha);
      EXPECT_EQ(aero.envelope().limited_beta(beta), beta);
    }
  }
}

TEST(AeroFlowEnvelope, TailwindGivesTheHeadOnDragAndNoLift) {
  // The report's case: a C172 parked in a tailwind, alpha -179.2 deg. The terms linear in
  // alpha, extrapolated, gave CL = -14.6 (14 kN of lift at 61 Pa, 1.35 times the weight) and
  // Cm = +5.7; now the flow from behind is separated flow with the head-on coefficients.
  const AircraftPack p = pack("c172.yaml");
  Aerodynamics aero(p);
  const auto head_on = aero.compute(wind_from(0.0, 0.0), false);
  for (double alpha : {kPi, -179.2 * kDeg, 179.9 * kDeg}) {
    SCOPED_TRACE(alpha);
    const Aerodynamics::Inputs in = wind_from(alpha, 0.0);
    const auto out = aero.compute(in, false);
    EXPECT_EQ(out.attached_weight, 0.0);
    EXPECT_DOUBLE_EQ(out.CL, 0.0);
    EXPECT_DOUBLE_EQ(out.CY, 0.0);
    // Drag along the flow, from behind: it pushes the aircraft forward.
    const Eigen::Vector3d v_hat(std::cos(alpha), 0.0, std::sin(alpha));
    EXPECT_NEAR((out.force_body + out.drag_n * v_hat).norm(), 0.0, 1e-9 * out.drag_n);
    EXPECT_GT(out.force_body.x(), 0.0);
    // About the head-on drag and pitching moment (the wing-plane incidence is under 1 deg).
    EXPECT_NEAR(out.CD, head_on.CD, 0.01);
    EXPECT_NEAR(out.Cm, head_on.Cm, 0.05);
    EXPECT_LT(out.force_body.norm(), 0.1 * qbar_s(p, in));
  }
}

TEST(AeroFlowEnvelope, CrosswindLiftsNothingAndWeathercocksIntoTheWind) {
  // Air from the right (beta +90 deg): alpha is undefined (u = w = 0), and whatever it reads
  // the result is the same: no lift, drag pushing the aircraft left, and the pack's
  // weathercock yawing moment (Cn_beta > 0) turning the nose right, into the wind.
  const AircraftPack p = pack("c172.yaml");
  Aerodynamics aero(p);
  const auto reference = aero.compute(wind_from(0.0, 0.5 * kPi), false);
  EXPECT_DOUBLE_EQ(reference.CL, 0.0);
  EXPECT_LT(reference.force_body.y(), 0.0);
  EXPECT_NEAR(reference.force_body.y(), -reference.drag_n, 1e-9 * reference.drag_n);
  EXPECT_GT(reference.Cn, 0.0);
  for (double alpha : {-3.0, -1.0, 0.4, 2.0, 3.1}) {
    const auto out = aero.compute(wind_from(alpha, 0.5 * kPi), false);
    EXPECT_NEAR((out.force_body - reference.force_body).norm(), 0.0, 1e-9 * reference.drag_n) << alpha;
    EXPECT_NEAR((out.moment_body - reference.moment_body).norm(), 0.0, 1e-9) << alpha;
  }
}

TEST(AeroFlowEnvelope, FlatFallKeepsThePitchStiffness) {
  // Falling flat (air from below, alpha +90 deg) the pack's Cm at the edge of its data holds
  // the nose-down moment that brings the aircraft back into flight; rising flat, nose up.
  Aerodynamics aero(pack("c172.yaml"));
  const auto falling = aero.compute(wind_from(0.5 * kPi, 0.0), false);
  const auto edge = aero.compute(wind_from(0.36, 0.0), false);
  EXPECT_DOUBLE_EQ(falling.CL, 0.0);
  EXPECT_NEAR(falling.Cm, edge.Cm, 1e-12);
  EXPECT_LT(falling.Cm, 0.0);
  EXPECT_GT(aero.compute(wind_from(-0.5 * kPi, 0.0), false).Cm, 0.0);
}

TEST(AeroFlowEnvelope, EveryFlowDirectionIsBoundedByTheDataAndContinuous) {
  // Over the whole sphere of flow directions the coefficients never exceed what the pack's
  // own data reach inside the envelope, and the forces and moments are continuous, through
  // alpha = +-180 deg (where alpha jumps) and beta = +-90 deg (where alpha is undefined).
  for (const char* name : {"c172.yaml", "b737.yaml"}) {
    SCOPED_TRACE(name);
    const AircraftPack p = pack(name);
    Aerodynamics aero(p);
    const AeroFlowEnvelope& env = aero.envelope();
    std::array<double, 6> data_max{};
    auto coefficients = [](const Aerodynamics::Outputs& o) {
      return std::array<double, 6>{o.CL, o.CD, o.CY, o.Cl, o.Cm, o.Cn};
    };
    // The data's extremes inside the envelope (a fine grid: 0.5 % allowed for what it misses
    // between its points, e.g. CDwbh's peak at 0.279 rad).
    for (int i = 0; i <= 400; ++i) {
      for (int j = 0; j <= 40; ++j) {
        const double a = env.alpha_min_rad() + (env.alpha_max_rad() - env.alpha_min_rad()) * i / 400;
        const double b = env.beta_min_rad() + (env.beta_max_rad() - env.beta_min_rad()) * j / 40;
        const auto c = coefficients(aero.compute(wind_from(a, b), false));
        for (std::size_t k = 0; k < 6; ++k) data_max[k] = std::max(data_max[k], std::abs(c[k]));
      }
    }
    for (int i = -180; i <= 180; i += 3) {
      for (int j = -90; j <= 90; j += 3) {
        const auto c = coefficients(aero.compute(wind_from(i * kDeg, j * kDeg), false));
        for (std::size_t k = 0; k < 6; ++k) {
          EXPECT_LE(std::abs(c[k]), 1.005 * data_max[k] + 1e-9) << i << " " << j << " axis " << k;
        }
      }
    }
    // Continuity: 0.01 deg either side of the two singular lines.
    const double e = 0.01 * kDeg;
    for (double beta : {0.0, 0.3, -1.0}) {
      const auto l = aero.compute(wind_from(kPi - e, beta), false);
      const auto r = aero.compute(wind_from(-kPi + e, beta), false);
      const double scale = qbar_s(p, wind_from(0.0, 0.0));
      EXPECT_LT((l.force_body - r.force_body).norm(), 1e-3 * scale) << beta;
      EXPECT_LT((l.moment_body - r.moment_body).norm(), 1e-3 * scale * p.geometry.wing_span_m) << beta;
    }
    for (double alpha : {-2.0, 0.1, 1.0}) {
      const auto l = aero.compute(wind_from(alpha, 0.5 * kPi - e), false);
      const auto r = aero.compute(wind_from(alpha + kPi, 0.5 * kPi - e), false);
      const double scale = qbar_s(p, wind_from(0.0, 0.0));
      EXPECT_LT((l.force_body - r.force_body).norm(), 1e-3 * scale) << alpha;
      EXPECT_LT((l.moment_body - r.moment_body).norm(), 1e-3 * scale * p.geometry.wing_span_m) << alpha;
    }
  }
}

TEST(AeroFlowEnvelope, AFlowFromBehindIsNotAStall) {
  // The stall flag reads the forward-equivalent alpha: a tailwind (alpha +-179 deg, which
  // flips sign with w) neither sets nor clears it in turn.
  Aerodynamics aero(pack("c172.yaml"));
  for (double alpha : {179.0 * kDeg, -179.0 * kDeg, 179.5 * kDeg}) {
    aero.evaluate(wind_from(alpha, 0.0));
    EXPECT_FALSE(aero.stall_hysteresis_active()) << alpha;
  }
  aero.evaluate(wind_from(0.37, 0.0));
  EXPECT_TRUE(aero.stall_hysteresis_active());
  EXPECT_NEAR(AeroFlowEnvelope::forward_equivalent_alpha(170.0 * kDeg), 10.0 * kDeg, 1e-12);
  EXPECT_NEAR(AeroFlowEnvelope::forward_equivalent_alpha(-170.0 * kDeg), -10.0 * kDeg, 1e-12);
  EXPECT_EQ(AeroFlowEnvelope::forward_equivalent_alpha(0.3), 0.3);
}

TEST(Aerodynamics, WindToBodyIsARotation) {
  const Eigen::Matrix3d m = Aerodynamics::body_from_wind(0.3, -0.2);
  EXPECT_NEAR((m * m.transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(m.determinant(), 1.0, 1e-15);
}

}  // namespace
}  // namespace fedsim::flight
