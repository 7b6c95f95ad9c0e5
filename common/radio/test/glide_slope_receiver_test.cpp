// ILS glide slope on the KSFO 28R record: zero on the 3 deg path, full scale at +-0.24 theta
// (DDM 0.175) and DDM 0.0875 at 0.12 theta (ICAO Annex 10 Vol I 3.1.5.6), the coverage sector
// of 3.1.5.3.1, and behind the antenna. Positions are placed with GeographicLib::LocalCartesian.
#include "common/radio/glide_slope_receiver.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::radio::test {
namespace {

GlideSlopeReading read(const IlsApproach& ils, double from_localizer_nm, double offset_deg,
                       double elevation_rad) {
  const GeoPoint where = from_localizer(ils, from_localizer_nm * kNm, offset_deg);
  return GlideSlopeReceiver().read(ils, at_elevation_from_glide_slope(ils, where, elevation_rad));
}

TEST(GlideSlope, ZeroOnThePathFullScaleAtTheStandardAngles) {
  const IlsApproach ils = ksfo_28r();
  const double theta = ils.glide_path_angle_rad;
  for (const double nm : {3.0, 6.0, 11.0}) {  // from the localizer: 0.9 to 8.9 NM from the antenna
    const GlideSlopeReading on = read(ils, nm, 0, theta);
    ASSERT_TRUE(on.valid()) << nm << " " << to_string(on.status);
    EXPECT_NEAR(on.deviation, 0.0, 1e-6) << nm;
    EXPECT_NEAR(on.elevation_angle_rad, theta, 1e-9);
    const GlideSlopeReading half_low = read(ils, nm, 0, theta - 0.12 * theta);
    EXPECT_NEAR(half_low.ddm, -0.0875, 1e-6);  // 150 Hz predominates below
    EXPECT_NEAR(half_low.deviation, 0.5, 1e-6);
    EXPECT_NEAR(read(ils, nm, 0, theta - 0.24 * theta).deviation, 1.0, 1e-6);   // fly up
    EXPECT_NEAR(read(ils, nm, 0, theta + 0.24 * theta).deviation, -1.0, 1e-6);  // fly down
    EXPECT_NEAR(read(ils, nm, 0, theta + 0.24 * theta).ddm, 0.175, 1e-6);
    EXPECT_EQ(read(ils, nm, 0, 0.5 * theta).deviation, 1.0);  // clamped, inside coverage
  }
  // 0.24 theta is the +-0.72 deg of a 3 deg glide path.
  EXPECT_NEAR(0.24 * theta / kDeg, 0.72, 1e-9);
}

TEST(GlideSlope, CoverageSector) {
  const IlsApproach ils = ksfo_28r();
  const double theta = ils.glide_path_angle_rad;
  EXPECT_TRUE(read(ils, 6, 0, 0.46 * theta).valid());
  EXPECT_EQ(read(ils, 6, 0, 0.44 * theta).status, SignalStatus::kOutsideCoverage);
  EXPECT_TRUE(read(ils, 6, 0, 1.74 * theta).valid());
  EXPECT_EQ(read(ils, 6, 0, 1.76 * theta).status, SignalStatus::kOutsideCoverage);
  // 8 deg each side (the localizer is 3.8 km further out than the abeam point, so the offset
  // seen from the localizer is smaller than from the abeam point).
  EXPECT_TRUE(read(ils, 8, 5, theta).valid());
  EXPECT_EQ(read(ils, 8, 8, theta).status, SignalStatus::kOutsideCoverage);
  // 10 NM from the antenna: the abeam point is ~3.5 km from the localizer.
  EXPECT_TRUE(read(ils, 11.5, 0, theta).valid());
  EXPECT_EQ(read(ils, 12.5, 0, theta).status, SignalStatus::kOutsideCoverage);
}

TEST(GlideSlope, BehindTheAntennaAndBadInputs) {
  const IlsApproach ils = ksfo_28r();
  // Over the runway between the abeam point and the localizer, 100 ft up.
  const GeoPoint over_runway = from_localizer(ils, 2000.0, 0);
  const GlideSlopeReading behind =
      GlideSlopeReceiver().read(ils, pose_at(over_runway, ils.threshold.elevation_m + 30));
  EXPECT_EQ(behind.status, SignalStatus::kBehindAntenna);
  EXPECT_EQ(behind.deviation, 0.0);
  AircraftPose pose = at_elevation_from_glide_slope(ils, from_localizer(ils, 6 * kNm, 0), 0.05);
  ASSERT_TRUE(GlideSlopeReceiver().read(ils, pose).valid());
  pose.pitch_rad = 2.0;  // beyond +-90 deg
  EXPECT_EQ(GlideSlopeReceiver().read(ils, pose).status, SignalStatus::kInvalidInput);
}

}  // namespace
}  // namespace fedsim::radio::test
