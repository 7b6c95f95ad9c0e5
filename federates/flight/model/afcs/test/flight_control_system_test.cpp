// The aircraft's flight control system in flight (model/systems yaw damper and pitch trim,
// from the pack): the 737's Dutch roll identified from a rudder doublet with and without the
// yaw damper, and the trims moving at their pack rates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "flight/model/scenario/test/flight_test_support.hpp"

namespace fedsim::flight {
namespace {

using namespace flight::testing;

struct DutchRoll {
  double damping_ratio = 0.0;
  double period_s = 0.0;
  double natural_frequency_radps = 0.0;
};

/// A rudder doublet (+-amplitude, 1 s each) from trim; the Dutch roll identified in the yaw
/// rate's free response (20 Hz, 30 s, Prony order 4: the Dutch-roll pair, roll and spiral).
DutchRoll doublet(const TrimRequest& request, bool yaw_damper, double amplitude) {
  AircraftModel::Options options;
  options.integrator = IntegrationMethod::kRk4;
  auto model = make_model("b737.yaml", options);
  AircraftControls c = request.controls;
  model->set_controls(c);
  const TrimResult trim = Trim(*model).solve(request);
  EXPECT_TRUE(trim.converged) << trim.reason;
  model->set_yaw_damper_engaged(yaw_damper);
  EXPECT_EQ(model->yaw_damper_engaged(), yaw_damper);
  const double dt = 0.01;
  std::vector<double> yaw_rate;
  for (int i = 0; i * dt < 33.0; ++i) {
    const double t = i * dt;
    AircraftControls u = trim.controls;
    if (t >= 0.5 && t < 1.5) u.rudder += amplitude;
    if (t >= 1.5 && t < 2.5) u.rudder -= amplitude;
    model->set_controls(u);
    model->step(dt);
    yaw_rate.push_back(model->outputs().omega_body_wrt_earth_radps.z());
  }
  const auto modes = prony_modes(decimate(yaw_rate, 260, 5, 600), 5 * dt, 4);
  DutchRoll d;
  for (const auto& m : modes) {
    if (m.s.imag() > 0.0 && m.damped_period_s() > 2.0 && m.damped_period_s() < 15.0) {
      d.damping_ratio = m.damping_ratio();
      d.period_s = m.damped_period_s();
      d.natural_frequency_radps = m.natural_frequency_radps();
      break;
    }
  }
  return d;
}

TrimRequest approach() {
  TrimRequest r;
  r.kind = TrimKind::kLevel;
  r.position = {37.6 * kDeg, -122.4 * kDeg, 3000.0 * kFt};
  r.heading_rad = 298.0 * kDeg;
  r.airspeed_mps = 150.0 * kKt;
  r.controls.flaps = 0.875;
  r.controls.gear_down = true;
  return r;
}

TEST(YawDamper737, DampsTheDutchRollInCruiseAndOnApproach) {
  // Bands: MIL-F-8785C 3.3.1.1 (class III, category B/C, level 1): zeta >= 0.08,
  // zeta omega_n >= 0.15 rad/s; the damper must raise zeta clearly above the bare airframe's.
  for (const TrimRequest& r : {cruise("b737.yaml"), approach()}) {
    const DutchRoll bare = doublet(r, false, 0.05);
    const DutchRoll damped = doublet(r, true, 0.05);
    std::printf("737 at %.0f ft %.0f KTAS: Dutch roll bare zeta %.3f period %.2f s; with yaw damper zeta %.3f "
                "period %.2f s (zeta wn %.3f)\n",
                r.position.alt_m / kFt, r.airspeed_mps / kKt, bare.damping_ratio, bare.period_s,
                damped.damping_ratio, damped.period_s, damped.damping_ratio * damped.natural_frequency_radps);
    ASSERT_GT(bare.period_s, 0.0) << "no Dutch roll found in the bare response";
    ASSERT_GT(damped.period_s, 0.0) << "no Dutch roll found with the damper";
    EXPECT_GT(damped.damping_ratio, bare.damping_ratio + 0.1);
    EXPECT_GE(damped.damping_ratio, 0.08);
    EXPECT_GE(damped.damping_ratio * damped.natural_frequency_radps, 0.15);
  }
}

TEST(PitchTrim, MovesAtThePackRate) {
  for (const char* pack : {"b737.yaml", "c172.yaml"}) {
    AircraftModel::Options options;
    options.integrator = IntegrationMethod::kRk4;
    auto model = make_model(pack, options);
    const TrimResult trim = Trim(*model).solve(cruise(pack));
    ASSERT_TRUE(trim.converged) << trim.reason;
    const double rate = model->pack().flight_controls.pitch_trim->rate_per_s;
    AircraftControls c = trim.controls;
    c.elevator_trim = -0.2;  // nose-up trim wanted
    model->set_controls(c);
    const int steps = static_cast<int>(std::round(0.1 / rate / 0.01));  // about half way
    for (int i = 0; i < steps; ++i) model->step(0.01);
    const double moved = rate * steps * 0.01;
    EXPECT_NEAR(model->outputs().pitch_trim_norm, -moved, 1e-9) << pack;  // at the rate
    if (model->pack().flight_controls.elevator->time_constant_s == 0.0) {
      // The elevator (the 737's has no lag) takes the trim's position, not its command.
      EXPECT_NEAR(model->outputs().elevator_rad,
                  model->pack().flight_controls.elevator->demanded_deflection_rad(c.elevator - moved), 1e-9)
          << pack;
    }
    for (int i = 0; i < 2 * steps; ++i) model->step(0.01);
    EXPECT_NEAR(model->outputs().pitch_trim_norm, -0.2, 1e-9) << pack;  // and stops at the command
  }
}

TEST(PitchTrim, AResetPlacesTheTrimWhereItIsCommanded) {
  auto model = make_model("b737.yaml");
  AircraftControls c;
  c.elevator_trim = 0.3;
  AircraftInitialConditions ic;
  ic.position.alt_m = 1000.0;
  model->reset(ic, c);
  EXPECT_DOUBLE_EQ(model->outputs().pitch_trim_norm, 0.3);
  EXPECT_TRUE(model->outputs().yaw_damper_engaged);  // the pack's engaged_at_start
}

}  // namespace
}  // namespace fedsim::flight
