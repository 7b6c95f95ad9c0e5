// The eye point carried to the display time: a straight flight moves by v dt over the WGS-84
// radii (checked against GeographicLib's direct geodesic), a steady turn turns by the Euler
// heading rate r / cos(theta) for a level turn (seed eq. 3.48), spans are clamped, and a
// non-finite input is refused by name.
#include "visual/model/eye_extrapolation.hpp"

#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::visual {
namespace {

using units::kDegToRad;

MovingPose cruise() {
  MovingPose m;
  m.pose.lat_rad = 37.6 * kDegToRad;
  m.pose.lon_rad = -122.3 * kDegToRad;
  m.pose.alt_msl_m = 1219.2;
  m.pose.psi_rad = 40.0 * kDegToRad;
  m.velocity_ned_mps = {51.4 * std::cos(40.0 * kDegToRad), 51.4 * std::sin(40.0 * kDegToRad), -2.0};
  return m;
}

TEST(EyeExtrapolation, StraightFlightMovesAlongTheGeodesic) {
  const MovingPose m = cruise();
  const EyePose e = extrapolate(m, 0.2, "test");
  double lat2 = 0, lon2 = 0;
  GeographicLib::Geodesic::WGS84().Direct(37.6, -122.3, 40.0, 51.4 * 0.2, lat2, lon2);
  // GeographicLib at the ellipsoid; the eye at 1219 m moves the same ground track: the angular
  // rates differ by h/R = 2e-4 of 10 m, 2 mm.
  const double north_m = (e.lat_rad - lat2 * kDegToRad) * 6.36e6;
  const double east_m = (e.lon_rad - lon2 * kDegToRad) * 6.38e6 * std::cos(m.pose.lat_rad);
  EXPECT_LT(std::hypot(north_m, east_m), 0.01);
  EXPECT_NEAR(e.alt_msl_m, 1219.2 + 0.4, 1e-9);  // climbing 2 m/s for 0.2 s
  EXPECT_DOUBLE_EQ(e.psi_rad, m.pose.psi_rad);
  // Negative control: no span, no motion.
  const EyePose same = extrapolate(m, 0.0, "test");
  EXPECT_DOUBLE_EQ(same.lat_rad, m.pose.lat_rad);
  EXPECT_DOUBLE_EQ(same.lon_rad, m.pose.lon_rad);
}

TEST(EyeExtrapolation, ALevelTurnTurnsByTheEulerHeadingRate) {
  MovingPose m = cruise();
  m.pose.phi_rad = 20.0 * kDegToRad;
  m.pose.theta_rad = 2.0 * kDegToRad;
  const double psi_dot = 3.0 * kDegToRad;  // rate-one turn
  // Body rates of a steady turn: q = psi' sin(phi) cos(theta), r = psi' cos(phi) cos(theta),
  // p = -psi' sin(theta).
  m.omega_body_radps = {-psi_dot * std::sin(m.pose.theta_rad),
                        psi_dot * std::sin(m.pose.phi_rad) * std::cos(m.pose.theta_rad),
                        psi_dot * std::cos(m.pose.phi_rad) * std::cos(m.pose.theta_rad)};
  const EyePose e = extrapolate(m, 0.1, "test");
  EXPECT_NEAR(e.psi_rad - m.pose.psi_rad, psi_dot * 0.1, 1e-12);
  EXPECT_NEAR(e.phi_rad, m.pose.phi_rad, 1e-12);
  EXPECT_NEAR(e.theta_rad, m.pose.theta_rad, 1e-12);
}

TEST(EyeExtrapolation, LongSpansAreClampedAndNegativeOnesIgnored) {
  const MovingPose m = cruise();
  const EyePose far = extrapolate(m, 10.0, "test");
  const EyePose clamp = extrapolate(m, kMaxExtrapolationS, "test");
  EXPECT_DOUBLE_EQ(far.lat_rad, clamp.lat_rad);
  EXPECT_DOUBLE_EQ(extrapolate(m, -1.0, "test").lat_rad, m.pose.lat_rad);
}

TEST(EyeExtrapolation, NonFiniteInputsAreRefusedByName) {
  MovingPose m = cruise();
  m.velocity_ned_mps[1] = std::nan("");
  try {
    extrapolate(m, 0.1, "fedsim/aircraft_state");
    FAIL() << "accepted a NaN velocity";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "fedsim/aircraft_state: field 'velocity_ned_mps': not a finite number");
  }
  m = cruise();
  EXPECT_THROW(extrapolate(m, std::nan(""), "x"), std::invalid_argument);
  m.pose.theta_rad = INFINITY;
  EXPECT_THROW(extrapolate(m, 0.1, "x"), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::visual
