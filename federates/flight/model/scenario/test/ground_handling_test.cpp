// On the runway: the C172's take-off roll lifts off at its handbook speed, and the brakes stop
// a landing roll of either aircraft within what friction allows.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "flight/model/scenario/test/flight_test_support.hpp"
#include "flight/model/scenario/reposition.hpp"

namespace fedsim::flight {
namespace {

using namespace testing;

const Runway kRunway{{34.0 * kDeg, -118.0 * kDeg, 10.0}, 69.0 * kDeg};

double distance_from_start(const AircraftOutputs& o) { return std::hypot(o.north_m, o.east_m); }

TEST(TakeOff, C172LiftsOffAtItsHandbookSpeed) {
  // Cessna 172P Pilot's Operating Handbook (1981), section 4: rotate at 55 KIAS; the flaps-up
  // lift-off follows at 55-60 KIAS; ground roll 890 ft (271 m) at 2400 lb, sea level, 15 C
  // with the short-field technique (flaps 10 deg). Band: lift-off at 50 to 65 KCAS after
  // 200 to 500 m (flaps up, rotation only at 55 KCAS, no steering).
  auto model = make_model("c172.yaml");
  const TrimResult parked = reposition_to_runway(*model, kRunway);
  ASSERT_TRUE(parked.converged) << parked.reason;
  AircraftControls c = parked.controls;
  c.set_throttle(1.0);
  c.brake_left = c.brake_right = 0.0;
  constexpr double kRateHz = 100.0;
  double liftoff_cas = 0.0, liftoff_distance = 0.0, airborne_s = 0.0;
  for (int i = 0; i < 90 * kRateHz && airborne_s < 3.0; ++i) {
    const AircraftOutputs& o = model->outputs();
    if (o.cas_mps >= 55.0 * kKt) c.elevator = -0.35;  // rotate
    model->set_controls(c);
    model->step(1.0 / kRateHz);
    if (model->outputs().weight_on_wheels) {
      airborne_s = 0.0;
      continue;
    }
    if (airborne_s == 0.0) {
      liftoff_cas = model->outputs().cas_mps;
      liftoff_distance = distance_from_start(model->outputs());
    }
    airborne_s += 1.0 / kRateHz;
  }
  std::printf("C172 lift-off at %.1f KCAS after %.0f m\n", liftoff_cas / kKt, liftoff_distance);
  ASSERT_GE(airborne_s, 3.0) << "never left the ground";
  EXPECT_GT(liftoff_cas, 50.0 * kKt);
  EXPECT_LT(liftoff_cas, 65.0 * kKt);
  EXPECT_GT(liftoff_distance, 200.0);
  EXPECT_LT(liftoff_distance, 500.0);
  EXPECT_GT(model->outputs().climb_rate_mps, 0.0);
}

struct Roll {
  double stop_time_s = 0.0;
  double distance_m = 0.0;
  double speed_at_end_mps = 0.0;
};

/// Rolls from `speed_mps` along the runway at idle with the brakes at `brake` until stopped or
/// `max_s` has passed.
Roll landing_roll(const std::string& pack, double speed_mps, double brake, double max_s) {
  auto model = make_model(pack);
  const TrimResult parked = reposition_to_runway(*model, kRunway);
  EXPECT_TRUE(parked.converged) << parked.reason;
  AircraftInitialConditions ic = parked.initial_conditions;
  ic.velocity_mps = speed_mps * Eigen::Vector3d(std::cos(kRunway.heading_rad),
                                                std::sin(kRunway.heading_rad), 0.0);
  AircraftControls c = parked.controls;
  c.set_throttle(0.0);
  c.brake_left = c.brake_right = brake;
  model->reset(ic, c);
  Roll roll;
  constexpr double kRateHz = 100.0;
  for (int i = 0; i < max_s * kRateHz; ++i) {
    model->step(1.0 / kRateHz);
    EXPECT_TRUE(model->outputs().weight_on_wheels);
    if (model->outputs().ground_speed_mps < 0.3) break;
  }
  roll.stop_time_s = model->time_s();
  roll.distance_m = distance_from_start(model->outputs());
  roll.speed_at_end_mps = model->outputs().ground_speed_mps;
  return roll;
}

TEST(Brakes, StopALandingRollWithinWhatFrictionAllows) {
  // Full braking decelerates at most mu_static g (every wheel braked at mu = 0.8), so no stop
  // can be shorter than v^2 / (2 mu g); only the main wheels brake and carry part of the
  // weight, so allow three times that. Without brakes the same roll has barely slowed.
  struct Case {
    const char* pack;
    double speed_mps;
  };
  for (const Case& c : {Case{"c172.yaml", 50.0 * kKt}, Case{"b737.yaml", 130.0 * kKt}}) {
    const double shortest_m = c.speed_mps * c.speed_mps / (2.0 * 0.8 * kG0);
    const Roll braked = landing_roll(c.pack, c.speed_mps, 1.0, 120.0);
    std::printf("%s: %.0f kt to rest in %.1f s and %.0f m (friction limit %.0f m)\n", c.pack,
                c.speed_mps / kKt, braked.stop_time_s, braked.distance_m, shortest_m);
    EXPECT_LT(braked.speed_at_end_mps, 0.3) << c.pack;
    EXPECT_GT(braked.distance_m, shortest_m) << c.pack;
    EXPECT_LT(braked.distance_m, 3.0 * shortest_m) << c.pack;
    const Roll free = landing_roll(c.pack, c.speed_mps, 0.0, braked.stop_time_s);
    EXPECT_GT(free.speed_at_end_mps, 0.6 * c.speed_mps) << c.pack;
  }
}

}  // namespace
}  // namespace fedsim::flight
