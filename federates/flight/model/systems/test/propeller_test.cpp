// Tests of the propeller coefficient model: the book's CT(J, beta) table, dimensional scaling,
// behaviour with airspeed and at zero rpm.
#include "flight/model/systems/propeller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "flight/model/systems/test/reference_data.hpp"

namespace fedsim::flight {
namespace {

using reference::kDeg;

// Seed Example 2.4 (section 2.9): CT for blade angles 0..40 deg (rows, 5 deg apart) and
// J = 0..2.2 (columns, 0.2 apart).
const std::vector<double> kBookBetaDeg = {0, 5, 10, 15, 20, 25, 30, 35, 40};
const std::vector<double> kBookJ = {0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0, 2.2};
const std::vector<double> kBookCt = {
    0.000, 0.000, 0.000, 0.000, 0.000, 0.000,  0.000,  0.000,  0.000,  0.000,  0.000,  0.000,
    0.000, 0.000, 0.000, 0.000, 0.000, 0.000,  0.000,  0.000,  0.000,  0.000,  0.000,  0.000,
    0.000, 0.000, 0.000, 0.000, 0.000, 0.000,  0.000,  0.000,  0.000,  0.000,  0.000,  0.000,
    0.092, 0.084, 0.065, 0.037, 0.007, -0.022, -0.050, -0.080, -0.108, -0.137, -0.167, -0.196,
    0.099, 0.096, 0.089, 0.064, 0.036, 0.006,  -0.023, -0.054, -0.084, -0.115, -0.144, -0.175,
    0.118, 0.114, 0.110, 0.095, 0.071, 0.043,  0.013,  -0.017, -0.045, -0.073, -0.102, -0.131,
    0.115, 0.110, 0.106, 0.100, 0.101, 0.080,  0.053,  0.024,  -0.007, -0.038, -0.068, -0.098,
    0.139, 0.132, 0.126, 0.119, 0.113, 0.108,  0.089,  0.065,  0.038,  0.010,  -0.020, -0.048,
    0.141, 0.135, 0.128, 0.123, 0.120, 0.114,  0.112,  0.101,  0.080,  0.057,  0.030,  0.005};

// The book's algorithm (Example 2.4), written out independently: interpolate along beta at
// the two bracketing J columns, then along J.
double book_cval(double beta_deg, double j) {
  const int n1 = std::min(static_cast<int>(beta_deg / 5.0), 7);
  const int q1 = std::min(static_cast<int>(j / 0.2), 10);
  const int p1 = n1 * 12;
  const int p2 = p1 + 12;
  const double beta1 = kBookBetaDeg[n1];
  const double x1 = kBookJ[q1];
  const double y1 = kBookCt[p1 + q1], y2 = kBookCt[p2 + q1];
  const double y4 = kBookCt[p1 + q1 + 1], y5 = kBookCt[p2 + q1 + 1];
  const double y3 = y1 + (beta_deg - beta1) * (y2 - y1) / 5.0;
  const double y6 = y4 + (beta_deg - beta1) * (y5 - y4) / 5.0;
  return y3 - (j - x1) * (y3 - y6) / 0.2;
}

// The book's table in the pack layout: rows = J, columns = blade angle (rad).
Propeller::Params book_propeller() {
  std::vector<double> beta_rad;
  for (double b : kBookBetaDeg) beta_rad.push_back(b * kDeg);
  std::vector<double> by_j(kBookCt.size());
  for (std::size_t ib = 0; ib < kBookBetaDeg.size(); ++ib) {
    for (std::size_t ij = 0; ij < kBookJ.size(); ++ij) {
      by_j[ij * kBookBetaDeg.size() + ib] = kBookCt[ib * kBookJ.size() + ij];
    }
  }
  Propeller::Params p;
  p.diameter_m = 2.0;
  p.thrust_coefficient = Table2D(kBookJ, beta_rad, by_j);
  p.power_coefficient = Table2D(kBookJ, beta_rad, std::vector<double>(by_j.size(), 0.05));
  return p;
}

TEST(Propeller, BookExample24ThrustCoefficient) {
  const Propeller prop(book_propeller());
  // Worked by hand: beta 22.5 deg, J 0.5 -> rows 20/25 at J 0.4/0.6: 0.0765 and 0.1025.
  EXPECT_NEAR(prop.thrust_coefficient(0.5, 22.5 * kDeg), 0.0895, 1e-12);
  // beta 17 deg, J 1.1: -0.036 at 15 deg, -0.0085 at 20 deg.
  EXPECT_NEAR(prop.thrust_coefficient(1.1, 17.0 * kDeg), -0.025, 1e-12);
  // Tabulated points are returned exactly.
  EXPECT_NEAR(prop.thrust_coefficient(0.8, 30.0 * kDeg), 0.101, 1e-12);
  // Same as the book's algorithm everywhere inside the table.
  for (double beta = 0.0; beta < 39.99; beta += 1.3) {
    for (double j = 0.0; j < 2.199; j += 0.037) {
      EXPECT_NEAR(prop.thrust_coefficient(j, beta * kDeg), book_cval(beta, j), 1e-12)
          << "beta " << beta << " J " << j;
    }
  }
  // Outside the table the lookup clamps (the book leaves that check out for brevity).
  EXPECT_NEAR(prop.thrust_coefficient(3.0, 50.0 * kDeg), 0.005, 1e-12);
}

TEST(Propeller, ThrustAndTorqueScaleWithDensitySpeedAndDiameter) {
  const Propeller prop(reference::prop_75in2f());
  const double d = prop.params().diameter_m;
  const double rpm = 2400.0, n = rpm / 60.0, rho = 1.0;
  Propeller::Inputs in;
  in.rpm = rpm;
  in.axial_airspeed_mps = 0.5 * n * d;  // J = 0.5: CT 0.066, CP 0.053
  in.density_kgpm3 = rho;
  in.blade_angle_rad = 22.0 * reference::kDeg;
  const Propeller::Outputs out = prop.evaluate(in);
  EXPECT_NEAR(out.advance_ratio, 0.5, 1e-12);
  EXPECT_LT(out.tip_mach, 0.85);  // no tip-Mach correction at this speed
  EXPECT_NEAR(out.thrust_n, 0.066 * rho * n * n * std::pow(d, 4), 1e-9);
  EXPECT_NEAR(out.torque_nm, 0.053 * rho * n * n * std::pow(d, 5) / (2.0 * std::numbers::pi), 1e-9);
  EXPECT_NEAR(out.power_w, 0.053 * rho * n * n * n * std::pow(d, 5), 1e-6);
  EXPECT_NEAR(out.efficiency, 0.5 * 0.066 / 0.053, 1e-12);  // eta = J CT / CP
}

TEST(Propeller, ThrustFallsWithAirspeedAtConstantRpm) {
  const Propeller prop(reference::prop_75in2f());
  Propeller::Inputs in;
  in.rpm = 2400.0;
  in.blade_angle_rad = 22.0 * reference::kDeg;
  double previous = prop.evaluate(in).thrust_n;
  EXPECT_GT(previous, 1000.0);
  for (double v = 5.0; v <= 90.0; v += 5.0) {
    in.axial_airspeed_mps = v;
    const double thrust = prop.evaluate(in).thrust_n;
    EXPECT_LE(thrust, previous) << "at " << v << " m/s";
    previous = thrust;
  }
  EXPECT_LT(previous, 0.0);  // J = 1.18 at 90 m/s: beyond zero-thrust advance ratio
}

TEST(Propeller, StoppedPropellerIsFiniteAndGivesDragInAirflow) {
  const Propeller prop(reference::prop_75in2f());
  Propeller::Inputs in;
  in.blade_angle_rad = 22.0 * reference::kDeg;
  const Propeller::Outputs still = prop.evaluate(in);
  EXPECT_EQ(still.thrust_n, 0.0);
  EXPECT_EQ(still.torque_nm, 0.0);
  EXPECT_EQ(still.advance_ratio, 0.0);

  in.axial_airspeed_mps = 40.0;
  const Propeller::Outputs stopped = prop.evaluate(in);
  const double d = prop.params().diameter_m;
  // Beyond the last tabulated J (5.0), CT(5) / 5^2 rho V^2 D^2 with CT(5) = -0.073.
  EXPECT_NEAR(stopped.thrust_n, -0.073 / 25.0 * 1.225 * 1600.0 * d * d, 1e-9);
  EXPECT_TRUE(std::isfinite(stopped.torque_nm));
  EXPECT_EQ(stopped.power_w, 0.0);

  // The extension joins the table continuously at J = 5.
  const double rpm_at_j5 = 40.0 / (5.0 * d) * 60.0;
  in.rpm = rpm_at_j5 * (1.0 + 1e-9);
  const double inside = prop.evaluate(in).thrust_n;
  in.rpm = rpm_at_j5 * (1.0 - 1e-9);
  const double outside = prop.evaluate(in).thrust_n;
  EXPECT_NEAR(inside, outside, 1e-6);
  EXPECT_NEAR(inside, stopped.thrust_n, 1e-6);
}

TEST(Propeller, HelicalTipMachReducesThrustAndRaisesPower) {
  const Propeller prop(reference::prop_75in2f());
  Propeller::Inputs in;
  in.blade_angle_rad = 22.0 * reference::kDeg;
  in.speed_of_sound_mps = 340.294;
  const double d = prop.params().diameter_m;
  in.rpm = 1.10 * 340.294 / (std::numbers::pi * d) * 60.0;  // static tip Mach 1.10
  const Propeller::Outputs out = prop.evaluate(in);
  EXPECT_NEAR(out.tip_mach, 1.10, 1e-12);
  const double n = in.rpm / 60.0;
  EXPECT_NEAR(out.thrust_n, 0.8 * 0.073 * 1.225 * n * n * std::pow(d, 4), 1e-6);
  // CP factor 1.8 at Mach 1.05 falling to 1.4 at Mach 2: 1.8 - 0.4 * 0.05 / 0.95 at 1.10.
  const double cp_factor = 1.8 - 0.4 * 0.05 / 0.95;
  EXPECT_NEAR(out.torque_nm,
              cp_factor * 0.066 * 1.225 * n * n * std::pow(d, 5) / (2.0 * std::numbers::pi), 1e-6);
}

TEST(Propeller, ConstantFactorsMultiplyTheTablesAsJsbsimsCtAndCpFactors) {
  // JSBSim FGPropeller: ThrustCoeff = C_THRUST(J) * CtFactor, cPReq = C_POWER(J) * CpFactor,
  // ahead of the tip-Mach tables. prop_75in2f at J = 0.5: CT 0.066, CP 0.053; below tip Mach
  // 0.85, where the Mach factors are 1.
  Propeller::Params params = reference::prop_75in2f();
  params.thrust_coefficient_factor = 1.2;
  params.power_coefficient_factor = 0.8;
  const Propeller prop(params);
  const double d = params.diameter_m;
  Propeller::Inputs in;
  in.blade_angle_rad = 22.0 * reference::kDeg;
  in.rpm = 2000.0;
  const double n = in.rpm / 60.0;
  in.axial_airspeed_mps = 0.5 * n * d;
  const Propeller::Outputs out = prop.evaluate(in);
  ASSERT_LT(out.tip_mach, 0.85);
  EXPECT_NEAR(out.thrust_coefficient, 1.2 * 0.066, 1e-12);
  EXPECT_NEAR(out.power_coefficient, 0.8 * 0.053, 1e-12);
  EXPECT_NEAR(out.thrust_n, 1.2 * 0.066 * 1.225 * n * n * std::pow(d, 4), 1e-6);
  EXPECT_NEAR(out.power_w, 0.8 * 0.053 * 1.225 * n * n * n * std::pow(d, 5), 1e-5);
  // Efficiency J CT / CP scales with the ratio of the factors.
  EXPECT_NEAR(out.efficiency, 0.5 * 0.066 / 0.053 * 1.2 / 0.8, 1e-9);
  // A stopped propeller in a wind (beyond the table's last J) is scaled the same way:
  // prop_75in2f ends at J = 5 with CT -0.073, CP 0.0493.
  in.rpm = 0.0;
  in.axial_airspeed_mps = 30.0;
  const Propeller::Outputs stopped = prop.evaluate(in);
  EXPECT_NEAR(stopped.thrust_n, 1.2 * -0.073 / 25.0 * 1.225 * 30.0 * 30.0 * d * d, 1e-6);
  EXPECT_NEAR(stopped.torque_nm,
              0.8 * 0.0493 / 25.0 * 1.225 * 30.0 * 30.0 * std::pow(d, 3) /
                  (2.0 * std::numbers::pi),
              1e-6);
}

TEST(Propeller, ConstantFactorsOutsideTheirRangeAreRefusedByName) {
  for (const double bad : {0.0, -1.0, 0.05, 11.0, std::nan(""), HUGE_VAL}) {
    for (const std::string field : {"thrust_coefficient_factor", "power_coefficient_factor"}) {
      Propeller::Params p = reference::prop_75in2f();
      (field == "thrust_coefficient_factor" ? p.thrust_coefficient_factor
                                            : p.power_coefficient_factor) = bad;
      try {
        p.validate();
        ADD_FAILURE() << field << " = " << bad << " accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
      }
    }
  }
}

TEST(Propeller, FadedFactorsApplyInFullBelowTheBandAndNotAtAllAboveIt) {
  // Factors 1.2 (CT) and 0.8 (CP) faded out between J 0.3 and 0.5: in full at J 0.2 and 0.3,
  // half at J 0.4 (1.1 and 0.9), none at 0.5 and beyond. prop_75in2f: CT 0.072, 0.069, 0.066,
  // 0.062 and CP 0.070, 0.060, 0.053, 0.0501 at J 0.2, 0.4, 0.5, 0.6.
  Propeller::Params params = reference::prop_75in2f();
  params.thrust_coefficient_factor = 1.2;
  params.power_coefficient_factor = 0.8;
  params.factor_fade = Propeller::FactorFade{0.3, 0.5};
  const Propeller prop(params);
  const double d = params.diameter_m;
  Propeller::Inputs in;
  in.blade_angle_rad = 22.0 * reference::kDeg;
  in.rpm = 2000.0;
  const double n = in.rpm / 60.0;
  struct Case {
    double j, ct, cp;
  };
  for (const Case& c : {Case{0.2, 1.2 * 0.072, 0.8 * 0.070}, Case{0.4, 1.1 * 0.069, 0.9 * 0.060},
                        Case{0.5, 0.066, 0.053}, Case{0.6, 0.062, 0.0501}}) {
    in.axial_airspeed_mps = c.j * n * d;
    const Propeller::Outputs out = prop.evaluate(in);
    ASSERT_LT(out.tip_mach, 0.85);
    EXPECT_NEAR(out.thrust_coefficient, c.ct, 1e-12) << "J " << c.j;
    EXPECT_NEAR(out.power_coefficient, c.cp, 1e-12) << "J " << c.j;
    EXPECT_NEAR(out.thrust_n, c.ct * 1.225 * n * n * std::pow(d, 4), 1e-6) << "J " << c.j;
    EXPECT_NEAR(out.power_w, c.cp * 1.225 * n * n * n * std::pow(d, 5), 1e-5) << "J " << c.j;
  }
  // At rest the factors apply in full; a stopped propeller in a wind (J infinite) has none.
  in.axial_airspeed_mps = 0.0;
  EXPECT_NEAR(prop.evaluate(in).thrust_n, 1.2 * 0.073 * 1.225 * n * n * std::pow(d, 4), 1e-6);
  in.rpm = 0.0;
  in.axial_airspeed_mps = 30.0;
  EXPECT_NEAR(prop.evaluate(in).thrust_n, -0.073 / 25.0 * 1.225 * 30.0 * 30.0 * d * d, 1e-6);
  // Without a band the same factors are constant (JSBSim's): at J 0.6 they apply in full.
  params.factor_fade.reset();
  in.rpm = 2000.0;
  in.axial_airspeed_mps = 0.6 * n * d;
  EXPECT_NEAR(Propeller(params).evaluate(in).power_coefficient, 0.8 * 0.0501, 1e-12);
}

TEST(Propeller, FadeBandsOutsideTheirRangeAreRefusedByName) {
  struct Bad {
    double start, end;
    const char* field;
  };
  for (const Bad& b : {Bad{-0.1, 0.5, "factor_fade_start_advance_ratio"},
                       Bad{std::nan(""), 0.5, "factor_fade_start_advance_ratio"},
                       Bad{0.3, HUGE_VAL, "factor_fade_end_advance_ratio"},
                       Bad{0.3, 3.5, "factor_fade_end_advance_ratio"},
                       Bad{0.5, 0.5, "factor_fade_end_advance_ratio"},
                       Bad{0.5, 0.3, "factor_fade_end_advance_ratio"}}) {
    Propeller::Params p = reference::prop_75in2f();
    p.factor_fade = Propeller::FactorFade{b.start, b.end};
    try {
      p.validate();
      ADD_FAILURE() << "band " << b.start << ".." << b.end << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(b.field), std::string::npos) << e.what();
    }
  }
}

TEST(Propeller, NegativeOrNanInputsGiveNoNan) {
  const Propeller prop(reference::prop_75in2f());
  Propeller::Inputs in;
  in.rpm = -100.0;
  in.axial_airspeed_mps = -20.0;
  Propeller::Outputs out = prop.evaluate(in);
  EXPECT_EQ(out.thrust_n, 0.0);
  in.rpm = std::nan("");
  in.axial_airspeed_mps = std::nan("");
  out = prop.evaluate(in);
  EXPECT_TRUE(std::isfinite(out.thrust_n));
  EXPECT_TRUE(std::isfinite(out.torque_nm));
}

TEST(Propeller, ValidateNamesTheBadField) {
  Propeller::Params p = reference::prop_75in2f();
  p.diameter_m = 0.0;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("diameter_m"), std::string::npos);
  }
  p = reference::prop_75in2f();
  p.power_coefficient = Table2D();
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
