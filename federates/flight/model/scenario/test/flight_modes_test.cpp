// Longitudinal modes from trim: an elevator doublet excites the short period (seen in the pitch
// rate) and the phugoid (seen in the airspeed); their periods, identified from the response
// by Prony's method, must fall in the band of the aircraft's class.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "flight/model/scenario/test/flight_test_support.hpp"

namespace fedsim::flight {
namespace {

using namespace testing;

struct ModeBands {
  std::string pack;
  double doublet_amplitude;  // elevator command
  double doublet_half_s;     // each half of the doublet
  double phugoid_run_s;      // how long to watch the phugoid
  // Bands (s) and damping limits.
  double short_period_min_s, short_period_max_s;
  double short_period_zeta_min, short_period_zeta_max;
  double phugoid_min_s, phugoid_max_s;
  double phugoid_zeta_max;
};

// Bands and where they come from:
//  C172 (1089 kg, 100 KTAS at 4000 ft). Short period: Nelson, Flight Stability and Automatic
//   Control, 2nd ed., ch. 4 (the Navion, a 1300 kg four-seat single): omega_n 3.6 rad/s,
//   zeta 0.69, damped period 2.4 s; the short-period approximation with the pack's own
//   derivatives (omega_n^2 = -M_alpha + M_q Z_alpha / V) gives 6.5 rad/s, 1.3 s: band
//   0.8 to 3.5 s, zeta 0.35 (MIL-F-8785C level 1, category B lower limit) to 0.9. Phugoid:
//   Lanchester's approximation T = pi sqrt(2) V / g = 23 s at 51 m/s; the Navion's is 30 s,
//   zeta 0.08: band 18 to 45 s, lightly damped (zeta < 0.2).
//  737 (48.5 t, Mach 0.76 at FL300). Short period: Etkin & Reid, Dynamics of Flight, 3rd ed.,
//   the Boeing 747 example of the longitudinal-dynamics chapter (Mach 0.8, 40,000 ft): damped
//   period 7.1 s, zeta 0.39; a 737 is smaller and
//   quicker: band 2.5 to 8 s, zeta 0.3 to 0.9. Phugoid: Lanchester 102 s at 226 m/s; the 747's
//   is 93 s, zeta 0.05: band 60 to 150 s, zeta < 0.2.
const std::vector<ModeBands> kBands = {
    {"c172.yaml", 0.1, 1.0, 300.0, 0.8, 3.5, 0.35, 0.9, 18.0, 45.0, 0.2},
    {"b737.yaml", 0.05, 2.0, 700.0, 2.5, 8.0, 0.3, 0.9, 60.0, 150.0, 0.2},
};

class LongitudinalModes : public ::testing::TestWithParam<ModeBands> {};

TEST_P(LongitudinalModes, DoubletShowsShortPeriodAndPhugoidInTheirBands) {
  const ModeBands& b = GetParam();
  AircraftModel::Options options;
  options.integrator = IntegrationMethod::kRk4;
  auto model = make_model(b.pack, options);
  const TrimResult trim = Trim(*model).solve(cruise(b.pack));
  ASSERT_TRUE(trim.converged) << trim.reason;

  // Doublet: stick forward, back, then hands off at the trimmed controls.
  constexpr double kRateHz = 100.0;
  const double dt = 1.0 / kRateHz;
  const double start_s = 1.0, release_s = start_s + 2.0 * b.doublet_half_s;
  std::vector<double> pitch_rate, airspeed;
  for (int i = 0; i * dt < b.phugoid_run_s; ++i) {
    const double t = i * dt;
    AircraftControls c = trim.controls;
    if (t >= start_s && t < start_s + b.doublet_half_s) c.elevator += b.doublet_amplitude;
    if (t >= start_s + b.doublet_half_s && t < release_s) c.elevator -= b.doublet_amplitude;
    model->set_controls(c);
    model->step(dt);
    pitch_rate.push_back(model->outputs().omega_body_radps.y());
    airspeed.push_back(model->outputs().tas_mps);
  }

  // Short period: the pitch rate's free response for 3 s after the release, 20 Hz, second order
  // (the phugoid is a slow drift at this scale, absorbed by the fit's constant).
  const auto release = static_cast<std::size_t>(release_s * kRateHz) + 5;
  const auto sp = prony_modes(decimate(pitch_rate, release, 5, 60), 5 * dt, 2);
  ASSERT_FALSE(sp.empty());
  ASSERT_GT(sp.front().s.imag(), 0.0) << "short period not oscillatory";
  // Phugoid: the airspeed at 1 Hz from 20 s on; third order (the phugoid pair and the slow
  // real height mode).
  const auto ph = prony_modes(decimate(airspeed, static_cast<std::size_t>(20.0 * kRateHz), 100,
                                       static_cast<std::size_t>(b.phugoid_run_s - 30.0)),
                              1.0, 3);
  ASSERT_FALSE(ph.empty());
  ASSERT_GT(ph.front().s.imag(), 0.0) << "phugoid not oscillatory";

  const Mode& short_period = sp.front();
  const Mode& phugoid = ph.front();
  std::printf(
      "%s: short period T %.2f s (omega_n %.2f rad/s, zeta %.2f); phugoid T %.1f s (zeta %.3f)\n",
      b.pack.c_str(), short_period.damped_period_s(), short_period.natural_frequency_radps(),
      short_period.damping_ratio(), phugoid.damped_period_s(), phugoid.damping_ratio());
  EXPECT_GT(short_period.damped_period_s(), b.short_period_min_s);
  EXPECT_LT(short_period.damped_period_s(), b.short_period_max_s);
  EXPECT_GT(short_period.damping_ratio(), b.short_period_zeta_min);
  EXPECT_LT(short_period.damping_ratio(), b.short_period_zeta_max);
  EXPECT_GT(phugoid.damped_period_s(), b.phugoid_min_s);
  EXPECT_LT(phugoid.damped_period_s(), b.phugoid_max_s);
  EXPECT_GT(phugoid.damping_ratio(), 0.0);  // stable
  EXPECT_LT(phugoid.damping_ratio(), b.phugoid_zeta_max);
  // The two modes are well apart, as they must be for the identification to mean anything.
  EXPECT_GT(phugoid.damped_period_s(), 10.0 * short_period.damped_period_s());
}

INSTANTIATE_TEST_SUITE_P(BothPacks, LongitudinalModes, ::testing::ValuesIn(kBands),
                         [](const auto& info) { return info.param.pack.substr(0, 4); });

TEST(ModeIdentification, PronyRecoversAKnownDampedOscillation) {
  // The identification itself: y = 2 + e^(-0.3 t) cos(2 t) sampled at 20 Hz.
  std::vector<double> y;
  for (int i = 0; i < 80; ++i) {
    const double t = 0.05 * i;
    y.push_back(2.0 + std::exp(-0.3 * t) * std::cos(2.0 * t));
  }
  const auto modes = prony_modes(y, 0.05, 2);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_NEAR(modes[0].s.real(), -0.3, 1e-6);
  EXPECT_NEAR(modes[0].s.imag(), 2.0, 1e-6);
  EXPECT_NEAR(modes[0].damped_period_s(), kPi, 1e-5);
}

}  // namespace
}  // namespace fedsim::flight
