// The least-squares fix and its DOPs: exact without noise, DOPs of a hand-computed geometry,
// errors scaling with the DOPs under seeded noise, invalid fixes, atmospheric biases.
#include "federates/nav/model/gps/dilution_of_precision.hpp"
#include "federates/nav/model/gps/gps_receiver.hpp"
#include "federates/nav/model/gps/least_squares_fix.hpp"
#include "federates/nav/model/gps/satellite_geometry.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace fedsim::nav {
namespace {

constexpr double kDeg = units::kDegToRad;

GpsReceiverConfig noiseless() {
  GpsReceiverConfig config;
  config.pseudoranges.noise_sigma_m = 0.0;
  return config;
}

TEST(GpsFix, WithoutNoiseTheFixIsTheTruthToTheMillimetre) {
  GpsReceiver receiver(GpsConstellation::baseline_24(), noiseless());
  const GeodeticPosition places[] = {{51.47 * kDeg, -0.45 * kDeg, 25.0},
                                     {-33.9 * kDeg, 151.2 * kDeg, 10000.0},
                                     {1.0 * kDeg, -80.0 * kDeg, 300.0},
                                     {70.0 * kDeg, 20.0 * kDeg, 3000.0}};
  double t = 3600.0;
  for (const GeodeticPosition& place : places) {
    const Eigen::Vector3d truth = Wgs84::ecef_from_geodetic(place);
    for (int epoch = 0; epoch < 3; ++epoch, t += 617.0) {
      const GpsFix fix = receiver.update(t, truth);  // first from the last fix far away
      ASSERT_TRUE(fix.valid) << to_string(fix.status);
      EXPECT_LT((fix.position_ecef_m - truth).norm(), 1e-3);
      EXPECT_NEAR(fix.position.alt_m, place.alt_m, 1e-3);
      EXPECT_NEAR(fix.clock_bias_s, receiver.true_clock_bias_s(t), 1e-12);  // 0.3 mm
      EXPECT_GE(fix.satellites_used, 4);
      EXPECT_EQ(fix.satellites_used, fix.satellites_visible);
      EXPECT_LT(fix.residual_rms_m, 1e-3);
      EXPECT_GT(fix.dop.pdop, 1.0);
      EXPECT_LT(fix.dop.pdop, 6.0);
    }
  }
}

TEST(GpsFix, ConvergesFromTheEarthsCentre) {
  PseudorangeModel model(PseudorangeConfig{kDefaultMaskAngleRad, 0.0});
  const GpsConstellation c = GpsConstellation::baseline_24();
  const Eigen::Vector3d truth = Wgs84::ecef_from_geodetic({45.0 * kDeg, 7.0 * kDeg, 500.0});
  const std::vector<Pseudorange> rho = model.measure(c, 1000.0, truth, 2e-3);  // 600 km of clock
  const LeastSquaresFix fix = solve_least_squares(rho, Eigen::Vector3d::Zero(), 0.0);
  ASSERT_EQ(fix.status, FixStatus::kValid);
  EXPECT_LT((fix.position_ecef_m - truth).norm(), 1e-3);
  EXPECT_NEAR(fix.clock_bias_m, 2e-3 * 299792458.0, 1e-3);
  EXPECT_LE(fix.iterations, 10);
}

// Satellites placed by azimuth and elevation around a receiver (20,200 km away).
std::vector<Eigen::Vector3d> satellites_at(const Eigen::Vector3d& receiver,
                                           const std::vector<std::pair<double, double>>& az_el) {
  const Eigen::Matrix3d ecef_from_enu = enu_from_ecef(receiver).transpose();
  std::vector<Eigen::Vector3d> out;
  for (const auto& [az, el] : az_el) {
    const Eigen::Vector3d enu(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el));
    out.push_back(receiver + 20200e3 * (ecef_from_enu * enu));
  }
  return out;
}

TEST(GpsDop, MatchesTheHandComputedGeometry) {
  // One satellite at the zenith, three at elevation E, azimuths 0, 120, 240 deg. With
  // u_k = (cos E sin A_k, cos E cos A_k, sin E) and rows [-u_k, 1]:
  //   H^T H = [[3/2 c^2, 0, 0, 0], [0, 3/2 c^2, 0, 0], [0, 0, 1 + 3 s^2, -(1 + 3 s)],
  //            [0, 0, -(1 + 3 s), 4]],  c = cos E, s = sin E,
  // whose inverse gives Q_EE = Q_NN = 2 / (3 c^2), and from the 2 x 2 block (determinant
  // 3 (1 - s)^2) Q_UU = 4 / (3 (1 - s)^2), Q_tt = (1 + 3 s^2) / (3 (1 - s)^2).
  const Eigen::Vector3d receiver = Wgs84::ecef_from_geodetic({40.0 * kDeg, -105.0 * kDeg, 1600.0});
  for (double e_deg : {0.0, 10.0, 30.0, 45.0}) {
    const double e = e_deg * kDeg;
    const double c = std::cos(e);
    const double s = std::sin(e);
    const auto sats = satellites_at(receiver, {{0.0, 90.0 * kDeg}, {0.0, e}, {120.0 * kDeg, e},
                                               {240.0 * kDeg, e}});
    const std::optional<DilutionOfPrecision> dop = dilution_of_precision(receiver, sats);
    ASSERT_TRUE(dop.has_value());
    const double q_horizontal = 2.0 / (3.0 * c * c);
    const double q_up = 4.0 / (3.0 * (1.0 - s) * (1.0 - s));
    const double q_clock = (1.0 + 3.0 * s * s) / (3.0 * (1.0 - s) * (1.0 - s));
    EXPECT_NEAR(dop->hdop, std::sqrt(2.0 * q_horizontal), 1e-9) << e_deg;
    EXPECT_NEAR(dop->vdop, std::sqrt(q_up), 1e-9) << e_deg;
    EXPECT_NEAR(dop->tdop, std::sqrt(q_clock), 1e-9) << e_deg;
    EXPECT_NEAR(dop->pdop, std::sqrt(2.0 * q_horizontal + q_up), 1e-9) << e_deg;
    EXPECT_NEAR(dop->gdop, std::sqrt(2.0 * q_horizontal + q_up + q_clock), 1e-9) << e_deg;
  }
  // E = 0: HDOP = VDOP = 2 / sqrt(3) = 1.1547, TDOP = 1 / sqrt(3).
  const auto flat = satellites_at(receiver, {{0.0, 90.0 * kDeg}, {0.0, 0.0}, {120.0 * kDeg, 0.0},
                                             {240.0 * kDeg, 0.0}});
  EXPECT_NEAR(dilution_of_precision(receiver, flat)->hdop, 1.1547005, 1e-6);
  // Three satellites are not enough; four in one direction are singular, and so are four on
  // one cone about the receiver (all at 30 deg elevation: u . up = const makes the up and clock
  // columns of H dependent), the classic degenerate geometry.
  EXPECT_FALSE(dilution_of_precision(receiver, {flat[0], flat[1], flat[2]}).has_value());
  EXPECT_FALSE(dilution_of_precision(receiver, {flat[1], flat[1], flat[1], flat[1]}).has_value());
  const auto cone = satellites_at(receiver, {{0.0, 30.0 * kDeg}, {70.0 * kDeg, 30.0 * kDeg},
                                             {160.0 * kDeg, 30.0 * kDeg}, {250.0 * kDeg, 30.0 * kDeg}});
  EXPECT_FALSE(dilution_of_precision(receiver, cone).has_value());
  // Negative control: lift one of them to 60 deg and the geometry is solvable.
  auto lifted = cone;
  lifted[3] = satellites_at(receiver, {{250.0 * kDeg, 60.0 * kDeg}})[0];
  EXPECT_TRUE(dilution_of_precision(receiver, lifted).has_value());
}

TEST(GpsFix, NoiseScalesThePositionErrorByTheDop) {
  // 2000 seeded epochs at one geometry: RMS horizontal error = HDOP sigma, vertical = VDOP
  // sigma, clock = TDOP sigma (each within 6 %: the RMS of 2000 samples scatters by ~2 %).
  const GpsConstellation c = GpsConstellation::baseline_24();
  const Eigen::Vector3d truth = Wgs84::ecef_from_geodetic({45.0 * kDeg, 7.0 * kDeg, 0.0});
  const double t = 20000.0;
  const double sigma_m = 3.0;
  PseudorangeConfig config;
  config.noise_sigma_m = sigma_m;
  config.seed = 2024;
  PseudorangeModel model(config);
  const Eigen::Matrix3d enu = enu_from_ecef(truth);
  double sum_h = 0.0;
  double sum_v = 0.0;
  double sum_t = 0.0;
  DilutionOfPrecision dop;
  const int epochs = 2000;
  for (int k = 0; k < epochs; ++k) {
    const LeastSquaresFix fix =
        solve_least_squares(model.measure(c, t, truth, 0.0), truth, 0.0);
    ASSERT_EQ(fix.status, FixStatus::kValid);
    const Eigen::Vector3d e = enu * (fix.position_ecef_m - truth);
    sum_h += e.head<2>().squaredNorm();
    sum_v += e.z() * e.z();
    sum_t += fix.clock_bias_m * fix.clock_bias_m;
    dop = fix.dop;
  }
  EXPECT_NEAR(std::sqrt(sum_h / epochs) / (dop.hdop * sigma_m), 1.0, 0.06);
  EXPECT_NEAR(std::sqrt(sum_v / epochs) / (dop.vdop * sigma_m), 1.0, 0.06);
  EXPECT_NEAR(std::sqrt(sum_t / epochs) / (dop.tdop * sigma_m), 1.0, 0.06);
  // Negative control: twice the noise, twice the error.
  PseudorangeConfig louder = config;
  louder.noise_sigma_m = 2.0 * sigma_m;
  PseudorangeModel loud(louder);
  double sum_loud = 0.0;
  for (int k = 0; k < epochs; ++k) {
    const LeastSquaresFix fix = solve_least_squares(loud.measure(c, t, truth, 0.0), truth, 0.0);
    sum_loud += (enu * (fix.position_ecef_m - truth)).head<2>().squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(sum_loud / sum_h), 2.0, 0.01);  // same seed: exactly the same draws x2
}

TEST(GpsFix, SameSeedSameFixDifferentSeedDifferentFix) {
  const Eigen::Vector3d truth = Wgs84::ecef_from_geodetic({10.0 * kDeg, 20.0 * kDeg, 100.0});
  GpsReceiverConfig config;
  config.pseudoranges.seed = 5;
  GpsReceiver a(GpsConstellation::baseline_24(), config);
  GpsReceiver b(GpsConstellation::baseline_24(), config);
  config.pseudoranges.seed = 6;
  GpsReceiver other(GpsConstellation::baseline_24(), config);
  const GpsFix fa = a.update(100.0, truth);
  const GpsFix fb = b.update(100.0, truth);
  const GpsFix fo = other.update(100.0, truth);
  EXPECT_EQ(fa.position_ecef_m, fb.position_ecef_m);
  EXPECT_GT((fa.position_ecef_m - fo.position_ecef_m).norm(), 1e-3);
}

TEST(GpsFix, FewerThanFourSatellitesOrDeniedGiveNoFix) {
  const Eigen::Vector3d truth = Wgs84::ecef_from_geodetic({45.0 * kDeg, 7.0 * kDeg, 0.0});
  GpsReceiverConfig config = noiseless();
  GpsReceiver receiver(GpsConstellation::baseline_24(), config);
  ASSERT_TRUE(receiver.update(0.0, truth).valid);
  // Denied after a valid fix: invalid, no stale values.
  const GpsFix denied = receiver.update(1.0, truth, /*denied=*/true);
  EXPECT_FALSE(denied.valid);
  EXPECT_EQ(denied.status, FixStatus::kDenied);
  EXPECT_TRUE(std::isnan(denied.position_ecef_m.x()));
  EXPECT_TRUE(std::isnan(denied.position.lat_rad));
  EXPECT_TRUE(std::isnan(denied.dop.pdop));
  EXPECT_EQ(denied.satellites_used, 0);
  // And it recovers when GPS returns.
  EXPECT_TRUE(receiver.update(2.0, truth).valid);

  // A 60 deg mask leaves fewer than 4 satellites at some time of the day: never a fix then.
  config.pseudoranges.mask_angle_rad = 60.0 * kDeg;
  GpsReceiver masked(GpsConstellation::baseline_24(), config);
  int too_few = 0;
  for (double t = 0.0; t < 86400.0; t += 600.0) {
    const GpsFix fix = masked.update(t, truth);
    if (fix.satellites_visible < 4) {
      ++too_few;
      EXPECT_FALSE(fix.valid);
      EXPECT_EQ(fix.status, FixStatus::kTooFewSatellites);
      EXPECT_TRUE(std::isnan(fix.position_ecef_m.norm()));
    } else if (fix.valid) {
      EXPECT_LT((fix.position_ecef_m - truth).norm(), 1e-3);
    }
  }
  EXPECT_GT(too_few, 0);
  EXPECT_TRUE(solve_least_squares({}, truth, 0.0).status == FixStatus::kTooFewSatellites);
}

TEST(GpsFix, AtmosphericBiasesFollowThePublishedMappings) {
  // DO-229 troposphere mapping 1.001 / sqrt(0.002001 + sin^2 E): 1.000 at the zenith, 10.2 at
  // 5 deg; IS-GPS-200 obliquity 1 + 16 (0.53 - E/180)^3: 1.0004 at the zenith, 3.03 at 5 deg.
  EXPECT_NEAR(troposphere_mapping(90.0 * kDeg), 1.0, 1e-3);
  EXPECT_NEAR(troposphere_mapping(5.0 * kDeg), 10.22, 0.01);
  EXPECT_NEAR(ionosphere_obliquity(90.0 * kDeg), 1.000432, 1e-6);
  EXPECT_NEAR(ionosphere_obliquity(5.0 * kDeg), 3.027, 0.001);
  // The biases enter the pseudoranges: a fix with them is off, without them exact.
  const Eigen::Vector3d truth = Wgs84::ecef_from_geodetic({45.0 * kDeg, 7.0 * kDeg, 0.0});
  GpsReceiverConfig config = noiseless();
  config.pseudoranges.troposphere_zenith_delay_m = 2.4;
  config.pseudoranges.ionosphere_zenith_delay_m = 5.0;
  GpsReceiver biased(GpsConstellation::baseline_24(), config);
  const GpsFix fix = biased.update(500.0, truth);
  ASSERT_TRUE(fix.valid);
  const double error_m = (fix.position_ecef_m - truth).norm();
  EXPECT_GT(error_m, 1.0);
  EXPECT_LT(error_m, 50.0);
  // The delays grow toward the horizon; what the clock does not absorb pushes the fix up (the
  // high satellites look relatively nearer): measured +27 m up, 31 m into the clock.
  EXPECT_GT((enu_from_ecef(truth) * (fix.position_ecef_m - truth)).z(), 1.0);
}

TEST(GpsFix, BadInputsAreRejected) {
  GpsReceiver receiver(GpsConstellation::baseline_24());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(receiver.update(nan, Eigen::Vector3d(6378137.0, 0.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(receiver.update(0.0, Eigen::Vector3d(nan, 0.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(receiver.update(0.0, Eigen::Vector3d(1000.0, 0.0, 0.0)), std::invalid_argument);
  GpsReceiverConfig config;
  config.clock_bias_s = 5.0;
  EXPECT_THROW(GpsReceiver(GpsConstellation::baseline_24(), config), std::invalid_argument);
  config = GpsReceiverConfig{};
  config.pseudoranges.troposphere_zenith_delay_m = nan;
  EXPECT_THROW(GpsReceiver(GpsConstellation::baseline_24(), config), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::nav
