// Tests of the US 1976 atmosphere against the published table and of the non-standard day.
#include "common/atmosphere/atmosphere.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fedsim {
namespace {

// Half a unit in the 4th significant figure of the table value.
double four_figures(double table_value) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(table_value))) - 3.0);
}

struct TableRow {
  double z_m, t_k, p_pa, rho_kgpm3, a_mps;
};

// U.S. Standard Atmosphere, 1976 (NOAA-S/T 76-1562), Table I (geometric altitude, SI units),
// values as published to six figures; the model must agree to four significant figures.
constexpr TableRow kUs1976Table[] = {
    {-1000.0, 294.651, 1.13929e5, 1.34700, 344.111},
    {0.0, 288.150, 1.01325e5, 1.22500, 340.294},
    {1000.0, 281.651, 8.98763e4, 1.11166, 336.435},
    {5000.0, 255.676, 5.40482e4, 7.36429e-1, 320.545},
    {11000.0, 216.774, 2.26999e4, 3.64801e-1, 295.154},
    {15000.0, 216.650, 1.21118e4, 1.94755e-1, 295.070},
    {20000.0, 216.650, 5.52929e3, 8.89097e-2, 295.070},
    {32000.0, 228.490, 8.89063e2, 1.35551e-2, 303.025},
    {40000.0, 250.350, 2.87143e2, 3.99566e-3, 317.189},
};

TEST(Atmosphere, MatchesUs1976TableToFourFigures) {
  const Atmosphere atmosphere;
  for (const TableRow& row : kUs1976Table) {
    SCOPED_TRACE(row.z_m);
    const AirProperties air = atmosphere.at(row.z_m);
    EXPECT_NEAR(air.temperature_k, row.t_k, four_figures(row.t_k));
    EXPECT_NEAR(air.pressure_pa, row.p_pa, four_figures(row.p_pa));
    EXPECT_NEAR(air.density_kgpm3, row.rho_kgpm3, four_figures(row.rho_kgpm3));
    EXPECT_NEAR(air.speed_of_sound_mps, row.a_mps, four_figures(row.a_mps));
  }
}

TEST(Atmosphere, SeaLevelStandardValuesAreExact) {
  const AirProperties air = Atmosphere{}.at(0.0);
  EXPECT_DOUBLE_EQ(air.temperature_k, 288.15);
  EXPECT_DOUBLE_EQ(air.pressure_pa, 101325.0);
  EXPECT_NEAR(air.density_kgpm3, 1.2250, 5e-5);
  EXPECT_NEAR(air.speed_of_sound_mps, 340.294, 5e-4);
  EXPECT_NEAR(air.dynamic_viscosity_pas, 1.7894e-5, 5e-9);  // US 1976 Table I
  EXPECT_NEAR(air.density_ratio, 1.0, 1e-4);
}

TEST(Atmosphere, GeopotentialAltitudeFollowsEq31) {
  // Seed 3.2: z = 11,000 m gives h = 10,981 m (r0 = 6,356,766 m).
  EXPECT_NEAR(Atmosphere::geopotential_from_geometric_m(11000.0), 10981.0, 0.5);
  EXPECT_NEAR(Atmosphere::geometric_from_geopotential_m(
                  Atmosphere::geopotential_from_geometric_m(23456.0)),
              23456.0, 1e-8);
}

TEST(Atmosphere, IsContinuousAcrossLayerBoundaries) {
  const Atmosphere atmosphere({15.0, 99000.0});
  for (double base_h : {11000.0, 20000.0, 32000.0, 47000.0, 51000.0, 71000.0}) {
    const double z = Atmosphere::geometric_from_geopotential_m(base_h);
    const AirProperties below = atmosphere.at(z - 1e-6);
    const AirProperties above = atmosphere.at(z + 1e-6);
    EXPECT_NEAR(below.temperature_k, above.temperature_k, 1e-6) << base_h;
    EXPECT_NEAR(below.pressure_pa / above.pressure_pa, 1.0, 1e-9) << base_h;
  }
}

TEST(Atmosphere, HotDayKeepsTropopauseTemperatureAndIsHydrostatic) {
  const Atmosphere hot({20.0, 101325.0});
  EXPECT_DOUBLE_EQ(hot.at(0.0).temperature_k, 308.15);
  const double z11 = Atmosphere::geometric_from_geopotential_m(11000.0);
  EXPECT_NEAR(hot.at(z11).temperature_k, 216.65, 1e-9);
  // Warmer air column is less dense: pressure falls more slowly with height.
  EXPECT_GT(hot.at(5000.0).pressure_pa, Atmosphere{}.at(5000.0).pressure_pa);
  // Hydrostatic balance dp/dH = -rho g0 (geopotential), checked by central difference.
  const double h = 3000.0;
  const double dz = 0.5;
  const double dp_dz = (hot.at(h + dz).pressure_pa - hot.at(h - dz).pressure_pa) / (2.0 * dz);
  const double dh_dz = std::pow(us1976::kEarthRadius / (us1976::kEarthRadius + h), 2.0);
  EXPECT_NEAR(dp_dz, -hot.at(h).density_kgpm3 * us1976::kG0 * dh_dz, 1e-5);
}

TEST(Atmosphere, SeaLevelPressureOffsetScalesTheTroposphere) {
  const Atmosphere low({0.0, 98000.0});
  EXPECT_DOUBLE_EQ(low.at(0.0).pressure_pa, 98000.0);
  EXPECT_NEAR(low.at(4000.0).pressure_pa / Atmosphere{}.at(4000.0).pressure_pa, 98000.0 / 101325.0,
              1e-12);
}

TEST(Atmosphere, ClampsOutOfRangeAltitudesAndRejectsBadOffsets) {
  const Atmosphere atmosphere;
  EXPECT_DOUBLE_EQ(atmosphere.at(1e7).pressure_pa, atmosphere.at(86000.0).pressure_pa);
  EXPECT_DOUBLE_EQ(atmosphere.at(-1e5).pressure_pa, atmosphere.at(-5000.0).pressure_pa);
  EXPECT_TRUE(std::isfinite(atmosphere.at(std::numeric_limits<double>::quiet_NaN()).density_kgpm3));
  EXPECT_THROW(Atmosphere({80.0, 101325.0}), std::invalid_argument);
  EXPECT_THROW(Atmosphere({0.0, 50000.0}), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim
