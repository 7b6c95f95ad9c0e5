// Tests of pressure altitude, altimeter reading, QNH and QFE.
#include "common/atmosphere/altimetry.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

namespace fedsim {
namespace {

TEST(Altimetry, PressureAltitudeInvertsTheStandardAtmosphere) {
  for (double h : {-500.0, 0.0, 1500.0, 10999.0, 11000.0, 15000.0, 25000.0, 40000.0, 60000.0}) {
    EXPECT_NEAR(pressure_altitude_m(standard_pressure_at_m(h)), h, 1e-6) << h;
  }
  // FL350 = 35,000 ft: 238.4 hPa in the ICAO standard atmosphere table.
  EXPECT_NEAR(standard_pressure_at_m(35000.0 * units::kFtToM) / 100.0, 238.4, 0.05);
}

TEST(Altimetry, QfeReadsZeroAndQnhReadsElevationOnTheField) {
  const Atmosphere day({12.0, 99500.0});
  const double field_m = 450.0;
  const double station_pa = day.at(field_m).pressure_pa;
  EXPECT_NEAR(altimeter_reading_m(station_pa, qfe_pa(day, field_m)), 0.0, 1e-6);
  EXPECT_NEAR(altimeter_reading_m(station_pa, qnh_pa(day, field_m)), field_m, 1e-6);
  // On a standard day QNH is 1013.25 hPa and the altimeter reads the geopotential altitude.
  const Atmosphere standard;
  EXPECT_NEAR(qnh_pa(standard, 0.0), 101325.0, 1e-6);
  EXPECT_NEAR(altimeter_reading_m(standard.at(3000.0).pressure_pa, 101325.0),
              Atmosphere::geopotential_from_geometric_m(3000.0), 1e-6);
}

TEST(Altimetry, LowPressureMakesTheAltimeterOverRead) {
  // "High to low, look out below": flying into lower MSL pressure with an unchanged setting,
  // the altimeter reads higher than the true altitude (about 8.4 m per hPa near sea level).
  const Atmosphere low({0.0, 100325.0});
  const double reading = altimeter_reading_m(low.at(300.0).pressure_pa, 101325.0);
  EXPECT_NEAR(reading - Atmosphere::geopotential_from_geometric_m(300.0), 84.0, 2.0);
}

}  // namespace
}  // namespace fedsim
