// The stall-entry pilot against a simple longitudinal plant whose elevator sets the pitch
// attitude, whose pitch attitude sets the deceleration, and whose lift runs out at a stall
// speed: the entry follows the reference rate, the wings are held level, the stall is
// identified by each of its indications, and the recovery lowers the nose.
#include "io/model/stall_entry_pilot.hpp"

#include "io/model/control_inputs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fedsim::io {
namespace {

constexpr double kKt = 1852.0 / 3600.0;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

/// A crude aeroplane: pitch attitude lags the elevator (nose up for aft stick, limited by the
/// elevator's travel); the speed falls with pitch (gravity) and drag; below `stall_kt` the nose
/// drops whatever the pilot does (a pitch break). Roll decays with the ailerons.
struct Plant {
  double t = 0, cas_kt = 100, theta_deg = 3, q_dps = 0, phi_deg = 5, p_dps = 0;
  double stall_kt = 60;
  double max_theta_deg = 90;  // the most nose-up the elevator can hold
  double thrust_kt_s = 0;     // an extra push along the path
  void step(const ControlInputs& c, double dt) {
    const double elevator = c[Channel::kElevator];
    double wanted_theta = std::min(3.0 - 25.0 * elevator, max_theta_deg);
    if (cas_kt < stall_kt) wanted_theta = theta_deg - 20.0;  // pitch break
    const double q_dot = 2.0 * (wanted_theta - theta_deg) - 2.0 * q_dps;
    q_dps += q_dot * dt;
    theta_deg += q_dps * dt;
    cas_kt += (-0.3 - 0.3 * (theta_deg - 3.0) + thrust_kt_s) * dt;  // kt/s: drag, plus gravity along the path
    p_dps += (40.0 * c[Channel::kAileron] - 2.0 * p_dps) * dt;
    phi_deg += p_dps * dt;
    t += dt;
  }
  PilotObservation seen(double elevator) const {
    PilotObservation o;
    o.sim_time_s = t;
    o.cas_mps = cas_kt * kKt;
    o.theta_rad = theta_deg * kDeg;
    o.q_radps = q_dps * kDeg;
    o.phi_rad = phi_deg * kDeg;
    o.p_radps = p_dps * kDeg;
    o.elevator = elevator;
    return o;
  }
};

struct Flight {
  double rate_kt_s = 0;  // speed loss per second over 10..40 s
  double max_phi_after_10s_deg = 0;
};

Flight fly(StallEntryPilot& pilot, Plant& plant, double seconds) {
  ControlInputs c = default_controls();
  double cas_10 = 0, cas_40 = 0;
  Flight f;
  const double dt = 0.02;
  for (int i = 0; i < static_cast<int>(seconds / dt); ++i) {
    pilot.observe(plant.seen(c[Channel::kElevator]));
    pilot.sample(plant.t, c);
    plant.step(c, dt);
    if (std::fabs(plant.t - 10.0) < dt / 2) cas_10 = plant.cas_kt;
    if (std::fabs(plant.t - 40.0) < dt / 2) cas_40 = plant.cas_kt;
    if (plant.t > 10.0) f.max_phi_after_10s_deg = std::max(f.max_phi_after_10s_deg, std::fabs(plant.phi_deg));
  }
  f.rate_kt_s = (cas_10 - cas_40) / 30.0;
  return f;
}

TEST(StallEntryPilot, FollowsTheEntryRateAndHoldsTheWingsLevel) {
  for (double rate : {1.0, 0.5}) {  // the second is the negative control: the rate is the pilot's
    StallEntryParameters p;
    p.entry_rate_kt_per_s = rate;
    StallEntryPilot pilot(p);
    Plant plant;
    plant.stall_kt = 20;  // no stall in the window measured
    const Flight f = fly(pilot, plant, 41.0);
    EXPECT_NEAR(f.rate_kt_s, rate, 0.1 * rate) << rate;
    EXPECT_LT(f.max_phi_after_10s_deg, 1.0);  // from 5 deg of bank to level
    EXPECT_EQ(pilot.phase(), StallEntryPhase::kEntry);
  }
}

TEST(StallEntryPilot, IdentifiesAPitchBreakAndRecovers) {
  StallEntryPilot pilot({});
  Plant plant;  // the nose drops below 60 kt: about 40 s into a 1 kt/s entry from 100 kt
  ControlInputs c = default_controls();
  double theta_at_stall = 0;
  for (int i = 0; i < 4000 && pilot.phase() != StallEntryPhase::kStalled; ++i) {
    pilot.observe(plant.seen(c[Channel::kElevator]));
    pilot.sample(plant.t, c);
    plant.step(c, 0.02);
    theta_at_stall = plant.theta_deg;
  }
  ASSERT_EQ(pilot.phase(), StallEntryPhase::kStalled);
  EXPECT_EQ(pilot.stall_indication(), "pitch break");
  EXPECT_NEAR(pilot.stall_cas_mps() / kKt, 60.0, 2.0);
  EXPECT_EQ(c[Channel::kThrottle1], 1.0);  // recovery: full power
  EXPECT_EQ(c[Channel::kThrottle4], 1.0);
  // Recovery: the pilot holds the entry's attitude (3 deg) while the power (modelled as a push
  // along the path, the stall broken) builds the speed back.
  plant.stall_kt = 0;
  plant.thrust_kt_s = 3;
  for (int i = 0; i < 1000; ++i) {
    pilot.observe(plant.seen(c[Channel::kElevator]));
    pilot.sample(plant.t, c);
    plant.step(c, 0.02);
  }
  EXPECT_NEAR(plant.theta_deg, 3.0, 0.5);
  EXPECT_GT(std::fabs(theta_at_stall - 3.0), 1.0);  // it was elsewhere when the stall came
}

TEST(StallEntryPilot, IdentifiesTheAftStop) {
  StallEntryPilot pilot({});
  Plant plant;
  plant.stall_kt = 0;
  plant.max_theta_deg = 8;   // the nose will not rise past 8 deg...
  plant.thrust_kt_s = 1.5;   // ...where the plant loses only 0.3 kt/s: slower than the entry
  ControlInputs c = default_controls();
  for (int i = 0; i < 20000 && pilot.phase() != StallEntryPhase::kStalled; ++i) {
    pilot.observe(plant.seen(c[Channel::kElevator]));
    pilot.sample(plant.t, c);
    plant.step(c, 0.02);
  }
  ASSERT_EQ(pilot.phase(), StallEntryPhase::kStalled);
  EXPECT_EQ(pilot.stall_indication(), "elevator at the aft stop");
}

TEST(StallEntryPilot, WaitsForTheFirstObservationAndIgnoresBrokenOnes) {
  StallEntryPilot pilot({});
  ControlInputs c = default_controls();
  c[Channel::kElevator] = 0.123;
  c[Channel::kThrottle1] = 0.6;
  pilot.sample(0.0, c);  // nothing seen yet: the start's controls stay
  EXPECT_EQ(c[Channel::kElevator], 0.123);
  EXPECT_EQ(c[Channel::kThrottle1], 0.6);
  Plant plant;
  PilotObservation broken = plant.seen(0.123);
  broken.cas_mps = std::nan("");
  pilot.observe(broken);
  EXPECT_EQ(pilot.phase(), StallEntryPhase::kWaiting);
  pilot.observe(plant.seen(0.123));
  EXPECT_EQ(pilot.phase(), StallEntryPhase::kEntry);
  pilot.sample(0.0, c);
  EXPECT_EQ(c[Channel::kThrottle1], 0.0);  // idle from the first sample of the entry
  EXPECT_NEAR(c[Channel::kElevator], 0.123, 1e-12);
}

TEST(StallEntryPilot, RefusesBadParametersByName) {
  StallEntryParameters p;
  p.entry_rate_kt_per_s = std::nan("");
  EXPECT_THROW(
      {
        try {
          StallEntryPilot pilot(p);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("entry_rate_kt_per_s"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
  p = {};
  p.throttle = 1.5;
  EXPECT_THROW(StallEntryPilot{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::io
