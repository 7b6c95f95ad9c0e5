// Service volumes against the figures of FAA AIM 1-1-8 Tables 1-1-1 and 1-1-2.
#include "common/radio/service_volume.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

namespace fedsim::radio::test {
namespace {

double range_nm(VhfServiceClass c, double height_ft) {
  return vhf_service_range_m(c, height_ft * kFt) / kNm;
}

TEST(ServiceVolume, VhfTable) {
  EXPECT_NEAR(range_nm(VhfServiceClass::kTerminal, 500), 25, 1e-9);
  EXPECT_NEAR(range_nm(VhfServiceClass::kTerminal, 12000), 25, 1e-9);
  EXPECT_EQ(range_nm(VhfServiceClass::kTerminal, 12100), 0);
  EXPECT_NEAR(range_nm(VhfServiceClass::kLow, 18000), 40, 1e-9);
  EXPECT_EQ(range_nm(VhfServiceClass::kLow, 18100), 0);
  EXPECT_NEAR(range_nm(VhfServiceClass::kHigh, 10000), 40, 1e-9);
  EXPECT_NEAR(range_nm(VhfServiceClass::kHigh, 16000), 100, 1e-9);
  EXPECT_NEAR(range_nm(VhfServiceClass::kHigh, 18000), 130, 1e-9);
  EXPECT_NEAR(range_nm(VhfServiceClass::kHigh, 45000), 130, 1e-9);
  EXPECT_NEAR(range_nm(VhfServiceClass::kHigh, 50000), 100, 1e-9);
  EXPECT_NEAR(range_nm(VhfServiceClass::kHigh, 60000), 100, 1e-9);
  EXPECT_EQ(range_nm(VhfServiceClass::kHigh, 61000), 0);
}

TEST(ServiceVolume, NdbTable) {
  EXPECT_NEAR(ndb_service_range_m(NdbServiceClass::kCompassLocator) / kNm, 15, 1e-9);
  EXPECT_NEAR(ndb_service_range_m(NdbServiceClass::kMediumHigh) / kNm, 25, 1e-9);
  EXPECT_NEAR(ndb_service_range_m(NdbServiceClass::kHigh) / kNm, 50, 1e-9);
  EXPECT_NEAR(ndb_service_range_m(NdbServiceClass::kHighHigh) / kNm, 75, 1e-9);
}

TEST(ServiceVolume, ClassesFromOurAirportsFields) {
  EXPECT_EQ(vhf_service_class(sfo_vor_dme()), VhfServiceClass::kHigh);  // BOTH
  EXPECT_EQ(vhf_service_class(sjc_vor_dme()), VhfServiceClass::kLow);   // LO
  Navaid terminal = sjc_vor_dme();
  terminal.usage = UsageType::kTerminal;
  EXPECT_EQ(vhf_service_class(terminal), VhfServiceClass::kTerminal);
  Navaid unknown = sjc_vor_dme();
  unknown.usage = UsageType::kUnknown;
  unknown.power = PowerClass::kHigh;
  EXPECT_EQ(vhf_service_class(unknown), VhfServiceClass::kHigh);
  unknown.power = PowerClass::kLow;
  EXPECT_EQ(vhf_service_class(unknown), VhfServiceClass::kTerminal);
  unknown.power = PowerClass::kUnknown;
  EXPECT_EQ(vhf_service_class(unknown), VhfServiceClass::kLow);

  EXPECT_EQ(ndb_service_class(brijj_ndb()), NdbServiceClass::kCompassLocator);  // TERMINAL LOW
  EXPECT_EQ(ndb_service_class(reiga_ndb()), NdbServiceClass::kMediumHigh);      // LO LOW
  Navaid ndb = reiga_ndb();
  ndb.power = PowerClass::kMedium;
  EXPECT_EQ(ndb_service_class(ndb), NdbServiceClass::kHigh);
  ndb.power = PowerClass::kHigh;
  EXPECT_EQ(ndb_service_class(ndb), NdbServiceClass::kHighHigh);
}

TEST(ServiceVolume, ReceptionNeedsBothVolumeAndLineOfSight) {
  const GeoPoint station = sfo_vor_dme().position;
  const auto status = [&](double distance_nm, double altitude_ft) {
    const GeoPoint aircraft = direct(station, 270.0, distance_nm * kNm, 0.0);
    const LinkGeometry link =
        link_geometry(station, aircraft.lat_rad, aircraft.lon_rad, altitude_ft * kFt);
    return vhf_reception(VhfServiceClass::kHigh, link, station.elevation_m, altitude_ft * kFt);
  };
  EXPECT_EQ(status(35, 3000), SignalStatus::kValid);
  EXPECT_EQ(status(35, 300), SignalStatus::kBelowRadioHorizon);  // 1.23 (sqrt 13 + sqrt 300) = 25.7 NM
  EXPECT_EQ(status(60, 10000), SignalStatus::kOutOfServiceVolume);  // H: 40 NM below 14,500 ft
  EXPECT_EQ(status(60, 20000), SignalStatus::kValid);               // 130 NM from 18,000 ft
}

}  // namespace
}  // namespace fedsim::radio::test
