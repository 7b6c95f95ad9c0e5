// Robustness: no NaN, no crash and no dropped step under extreme inputs and attitudes, for every
// integrator at 50, 100, 200 and 400 Hz.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "flight/model/scenario/test/flight_test_support.hpp"

namespace fedsim::flight {
namespace {

using namespace testing;

enum class Scenario {
  kBangBang,       // every control slammed from stop to stop twice a second
  kStall,          // idle, full aft stick: through the stall
  kInverted,       // upside down at cruise speed
  kZeroAirspeed,   // at rest in the air: falls from zero airspeed
  kGroundAtSpeed,  // hits the runway at 60 m/s, 6 m/s down, banked 17 deg
  kVertical,       // straight up at cruise speed (Euler angles at gimbal lock)
};

const char* name_of(Scenario s) {
  switch (s) {
    case Scenario::kBangBang:
      return "BangBang";
    case Scenario::kStall:
      return "Stall";
    case Scenario::kInverted:
      return "Inverted";
    case Scenario::kZeroAirspeed:
      return "ZeroAirspeed";
    case Scenario::kGroundAtSpeed:
      return "GroundAtSpeed";
    case Scenario::kVertical:
      return "Vertical";
  }
  return "?";
}

bool all_finite(const AircraftOutputs& o) {
  bool ok = std::isfinite(o.geodetic.lat_rad) && std::isfinite(o.geodetic.lon_rad) &&
            std::isfinite(o.geodetic.alt_m) && o.position_ecef_m.allFinite() &&
            o.velocity_ned_mps.allFinite() && o.velocity_body_mps.allFinite() &&
            o.q_ned_from_body.allFinite() && std::isfinite(o.euler.phi_rad) &&
            std::isfinite(o.euler.theta_rad) && std::isfinite(o.euler.psi_rad) &&
            o.omega_body_radps.allFinite() && o.omega_dot_body_radps2.allFinite() &&
            o.acceleration_body_mps2.allFinite() && o.specific_force_eye_body_mps2.allFinite() &&
            std::isfinite(o.tas_mps) && std::isfinite(o.cas_mps) && std::isfinite(o.eas_mps) &&
            std::isfinite(o.mach) && std::isfinite(o.alpha_rad) && std::isfinite(o.beta_rad) &&
            std::isfinite(o.alpha_dot_radps) && std::isfinite(o.beta_dot_radps) &&
            std::isfinite(o.qbar_pa) && o.total_force_body_n.allFinite() &&
            o.total_moment_body_nm.allFinite() && std::isfinite(o.mass_kg) &&
            std::isfinite(o.total_thrust_n);
  for (const EngineOutputs& e : o.engines) {
    ok = ok && std::isfinite(e.thrust_n) && std::isfinite(e.rpm) && std::isfinite(e.n1_pct) &&
         std::isfinite(e.fuel_flow_kgps) && std::isfinite(e.manifold_pressure_pa);
  }
  for (const ContactOutputs& c : o.contacts) ok = ok && std::isfinite(c.normal_force_n);
  return ok;
}

using Param = std::tuple<std::string, IntegrationMethod, double, Scenario>;

class ExtremeConditions : public ::testing::TestWithParam<Param> {};

TEST_P(ExtremeConditions, NeverNaNNeverADroppedStep) {
  const auto& [pack, method, rate_hz, scenario] = GetParam();
  AircraftModel::Options options;
  options.integrator = method;
  auto model = make_model(pack, options);
  const TrimRequest cruise_request = cruise(pack);
  const TrimResult trim = Trim(*model).solve(cruise_request);
  ASSERT_TRUE(trim.converged) << trim.reason;
  AircraftInitialConditions ic = trim.initial_conditions;
  AircraftControls controls = trim.controls;
  const double speed = cruise_request.airspeed_mps;
  double duration_s = 40.0;
  switch (scenario) {
    case Scenario::kBangBang:
      break;
    case Scenario::kStall:
      controls.set_throttle(0.0);
      controls.elevator = -1.0;
      break;
    case Scenario::kInverted:
      ic.attitude.phi_rad = kPi;
      break;
    case Scenario::kZeroAirspeed:
      ic.velocity_mps.setZero();
      ic.omega_body_radps.setZero();
      controls.set_throttle(0.0);
      break;
    case Scenario::kGroundAtSpeed:
      controls.gear_down = true;
      controls.set_throttle(0.5);
      ic.position.alt_m = 2.5;
      ic.velocity_mps = Eigen::Vector3d(0.0, 60.0, 6.0);
      ic.attitude = EulerAngles{0.3, -0.1, 90.0 * kDeg};
      duration_s = 20.0;
      break;
    case Scenario::kVertical:
      ic.attitude.theta_rad = kPi / 2;
      ic.velocity_mps = Eigen::Vector3d(0.0, 0.0, -speed);
      break;
  }
  model->reset(ic, controls);
  ASSERT_TRUE(all_finite(model->outputs()));
  bool stalled = false, touched = false;
  const int frames = static_cast<int>(duration_s * rate_hz);
  for (int i = 0; i < frames; ++i) {
    if (scenario == Scenario::kBangBang) {
      const double s = (i / static_cast<int>(rate_hz / 2.0)) % 2 == 0 ? 1.0 : -1.0;
      controls.elevator = s;
      controls.aileron = -s;
      controls.rudder = s;
      controls.set_throttle(s > 0.0 ? 1.0 : 0.0);
    }
    model->set_controls(controls);
    model->step(1.0 / rate_hz);
    const AircraftOutputs& o = model->outputs();
    ASSERT_TRUE(all_finite(o)) << "non-finite output at t = " << o.time_s;
    ASSERT_FALSE(o.numerical_fault) << "dropped step at t = " << o.time_s;
    stalled = stalled || o.stalled;
    touched = touched || o.weight_on_wheels;
  }
  // The scenarios did what they say.
  if (scenario == Scenario::kStall && model->pack().aerodynamics.stall_hysteresis) {
    EXPECT_TRUE(stalled);
  }
  if (scenario == Scenario::kGroundAtSpeed) {
    EXPECT_TRUE(touched);
  }
  if (scenario == Scenario::kZeroAirspeed) {
    EXPECT_GT(model->outputs().tas_mps, 20.0);
  }
}

std::string param_name(const ::testing::TestParamInfo<Param>& info) {
  const auto& [pack, method, rate_hz, scenario] = info.param;
  return pack.substr(0, 4) + "_" + std::string(to_string(method)) + "_" +
         std::to_string(static_cast<int>(rate_hz)) + "Hz_" + name_of(scenario);
}

INSTANTIATE_TEST_SUITE_P(
    AllIntegratorsAndRates, ExtremeConditions,
    ::testing::Combine(::testing::Values("c172.yaml", "b737.yaml"),
                       ::testing::Values(IntegrationMethod::kEuler, IntegrationMethod::kAb2,
                                         IntegrationMethod::kAb3, IntegrationMethod::kAb4,
                                         IntegrationMethod::kRk4),
                       ::testing::Values(50.0, 100.0, 200.0, 400.0),
                       ::testing::Values(Scenario::kBangBang, Scenario::kStall, Scenario::kInverted,
                                         Scenario::kZeroAirspeed, Scenario::kGroundAtSpeed,
                                         Scenario::kVertical)),
    param_name);

}  // namespace
}  // namespace fedsim::flight
