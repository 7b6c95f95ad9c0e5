// Tests of the air-data conversions (TAS, EAS, CAS, Mach).
#include "common/atmosphere/airspeed.hpp"

#include <gtest/gtest.h>

namespace fedsim {
namespace {

TEST(Airspeed, CasEqualsTasAndEasAtSeaLevelStandard) {
  const AirProperties air = Atmosphere{}.at(0.0);
  for (double tas : {10.0, 100.0, 250.0, 340.0, 500.0}) {
    EXPECT_NEAR(cas_from_tas_mps(tas, air), tas, 1e-9 * tas) << tas;
    EXPECT_NEAR(eas_from_tas_mps(tas, air), tas, 1e-4 * tas) << tas;
  }
}

TEST(Airspeed, RoundTripsAtAltitude) {
  const Atmosphere atmosphere({-10.0, 100000.0});
  for (double alt : {0.0, 3000.0, 11000.0, 18000.0}) {
    const AirProperties air = atmosphere.at(alt);
    for (double tas : {30.0, 150.0, 280.0, 450.0, 700.0}) {
      EXPECT_NEAR(tas_from_cas_mps(cas_from_tas_mps(tas, air), air), tas, 1e-9 * tas);
      EXPECT_NEAR(tas_from_eas_mps(eas_from_tas_mps(tas, air), air), tas, 1e-12 * tas);
    }
  }
}

TEST(Airspeed, CasLiesBetweenEasAndTasAndTendsToEasAtLowSpeed) {
  const AirProperties air = Atmosphere{}.at(10000.0);
  // High subsonic: the compressibility correction CAS - EAS is positive at altitude.
  const double tas = 0.8 * air.speed_of_sound_mps;
  EXPECT_GT(cas_from_tas_mps(tas, air), eas_from_tas_mps(tas, air) + 5.0);
  EXPECT_LT(cas_from_tas_mps(tas, air), tas);
  // Low speed: compressibility vanishes and CAS -> EAS (relative difference ~ M^2 / 8).
  EXPECT_NEAR(cas_from_tas_mps(15.0, air) / eas_from_tas_mps(15.0, air), 1.0, 1e-3);
}

TEST(Airspeed, SonicImpactPressureRatio) {
  // At M = 1 the isentropic pitot formula gives qc / p = 1.2^3.5 - 1 = 0.89293.
  EXPECT_NEAR(impact_pressure_pa(1.0, 1.0), 0.89293, 1e-5);
  // Rayleigh pitot formula at M = 2: p02 / p = 5.6404 (NACA 1135 normal-shock tables).
  EXPECT_NEAR(impact_pressure_pa(2.0, 1.0) + 1.0, 5.6404, 1e-3);
}

TEST(Airspeed, ImpactPressureIsContinuousThroughMachOne) {
  const double p = 50000.0;
  EXPECT_NEAR(impact_pressure_pa(1.0 - 1e-9, p), impact_pressure_pa(1.0 + 1e-9, p), 1e-3);
  for (double m : {0.1, 0.7, 0.99, 1.01, 1.5, 2.5}) {
    EXPECT_NEAR(mach_from_impact_pressure(impact_pressure_pa(m, p), p), m, 1e-10) << m;
  }
  // Low speed limit: qc -> rho V^2 / 2.
  const AirProperties air = Atmosphere{}.at(0.0);
  EXPECT_NEAR(impact_pressure_pa(mach_number(10.0, air), air.pressure_pa),
              dynamic_pressure_pa(10.0, air), 0.1);
}

}  // namespace
}  // namespace fedsim
