// Tests of the steady wind profile: meteorological direction to NED, interpolation across
// layers and across north, clamping and validation.
#include "flight/model/weather/wind_profile.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fedsim::flight {
namespace {

constexpr double kDeg = units::kDegToRad;

TEST(WindProfile, FromDirectionBlowsTheOtherWay) {
  // From the west (270 deg): the air moves east.
  Eigen::Vector3d w = WindProfile::ned_from(10.0, 270.0 * kDeg);
  EXPECT_NEAR(w.x(), 0.0, 1e-12);
  EXPECT_NEAR(w.y(), 10.0, 1e-12);
  EXPECT_EQ(w.z(), 0.0);
  // From the north: the air moves south. From 045: toward the south-west.
  w = WindProfile::ned_from(10.0, 0.0);
  EXPECT_NEAR(w.x(), -10.0, 1e-12);
  w = WindProfile::ned_from(10.0, 45.0 * kDeg);
  EXPECT_NEAR(w.x(), -10.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(w.y(), -10.0 / std::sqrt(2.0), 1e-12);
}

TEST(WindProfile, InterpolatesSpeedAndDirectionBetweenLayers) {
  WindProfile::Params p;
  p.altitude_m = {0.0, 1000.0, 3000.0};
  p.speed_mps = {5.0, 15.0, 25.0};
  p.from_direction_rad = {200.0 * kDeg, 240.0 * kDeg, 300.0 * kDeg};
  const WindProfile profile(p);
  const WindProfile::Outputs mid = profile.at(500.0);
  EXPECT_NEAR(mid.speed_mps, 10.0, 1e-12);
  EXPECT_NEAR(mid.from_direction_rad, 220.0 * kDeg, 1e-12);
  EXPECT_TRUE(mid.wind_ned_mps.isApprox(WindProfile::ned_from(10.0, 220.0 * kDeg), 1e-12));
  const WindProfile::Outputs upper = profile.at(2500.0);
  EXPECT_NEAR(upper.speed_mps, 22.5, 1e-12);
  EXPECT_NEAR(upper.from_direction_rad, 285.0 * kDeg, 1e-12);
  // Clamped outside the table.
  EXPECT_NEAR(profile.at(-50.0).speed_mps, 5.0, 1e-12);
  EXPECT_NEAR(profile.at(10000.0).from_direction_rad, 300.0 * kDeg, 1e-12);
}

TEST(WindProfile, TurnsTheShortWayThroughNorth) {
  WindProfile::Params p;
  p.altitude_m = {0.0, 1000.0, 2000.0};
  p.speed_mps = {10.0, 10.0, 10.0};
  p.from_direction_rad = {350.0 * kDeg, 10.0 * kDeg, 340.0 * kDeg};
  const WindProfile profile(p);
  EXPECT_NEAR(profile.at(500.0).from_direction_rad, 0.0, 1e-12);  // not 180
  EXPECT_NEAR(profile.at(250.0).from_direction_rad, 355.0 * kDeg, 1e-12);
  EXPECT_NEAR(profile.at(1500.0).from_direction_rad, 355.0 * kDeg, 1e-12);
  EXPECT_NEAR(profile.at(500.0).wind_ned_mps.x(), -10.0, 1e-12);
}

TEST(WindProfile, LinearShearLayerGivesConstantShear) {
  // 0 to 20 m/s from 270 deg over the lowest 500 m: a shear of 0.04 /s.
  WindProfile::Params p;
  p.altitude_m = {0.0, 500.0};
  p.speed_mps = {0.0, 20.0};
  p.from_direction_rad = {270.0 * kDeg, 270.0 * kDeg};
  const WindProfile profile(p);
  for (double h = 10.0; h < 490.0; h += 40.0) {
    const double shear =
        (profile.at(h + 10.0).wind_ned_mps.y() - profile.at(h).wind_ned_mps.y()) / 10.0;
    EXPECT_NEAR(shear, 0.04, 1e-12);
  }
}

TEST(WindProfile, CalmByDefaultAndNanSafe) {
  const WindProfile calm;
  EXPECT_EQ(calm.at(1000.0).wind_ned_mps, Eigen::Vector3d::Zero());
  WindProfile::Params p;
  p.altitude_m = {0.0, 1000.0};
  p.speed_mps = {3.0, 6.0};
  p.from_direction_rad = {0.0, 0.0};
  EXPECT_TRUE(WindProfile(p).at(std::nan("")).wind_ned_mps.allFinite());
}

TEST(WindProfile, ValidateNamesTheBadField) {
  WindProfile::Params p;
  p.altitude_m = {0.0, 1000.0};
  p.speed_mps = {3.0, -1.0};
  p.from_direction_rad = {0.0, 0.0};
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("speed_mps[1]"), std::string::npos) << e.what();
  }
  p.speed_mps = {3.0};
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.speed_mps = {3.0, 4.0};
  p.altitude_m = {1000.0, 0.0};
  EXPECT_THROW(WindProfile{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
