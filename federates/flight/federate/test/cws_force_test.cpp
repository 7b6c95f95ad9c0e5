// Control-wheel steering from the pilot's force sensors, in the in-process composition with the
// I/O federate's and the control loader's own components (the same adapters fedsim-io
// --loader-in-the-loop, fedsim-control-loading and fedsim-flight --autopilot run over DDS): the
// 737 level at 10,000 ft, CWS engaged by the MCP's CWS button from an input profile, then a
// 60 N pull on the column's force sensor (the profile's column_force_n, + push) for 3 s. With the
// sensors (DISCRETE_FORCE_SENSORS) the pitch attitude rises and, released, the new attitude is
// held; without them (the I/O federate not in the loop) the same pull leaves the attitude held.
// Also: bad force readings are rejected and counted, the previous input kept.
#include "control_loading/control_loading_component.hpp"
#include "flight/federate/flight_program.hpp"
#include "io/io_component.hpp"
#include "io/model/input_profile.hpp"

#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::flight {
namespace {

constexpr double kDeg = units::kDegToRad;
constexpr double kKt = units::kKtToMps;

FlightOptions cruise_options() {
  FlightOptions o;
  o.aircraft = "b737";
  o.autopilot = true;
  o.controls = "relative";
  o.start.trim_kind = "level";
  o.start.alt_ft = 10000.0;
  o.start.kcas = 250.0;
  o.start.heading_deg = 280.0;
  return o;
}

/// CWS at 0.5 s, SPEED (the A/T holds 250 kt) at 1 s, a pull of `pull_n` from 6 s to 9 s.
std::string cws_profile(double pull_n) {
  const std::string f = std::to_string(-pull_n);  // column + push: a pull is negative
  return "time_s,fd,at_arm,mcp_speed_kt,mcp_altitude_ft,mcp_cws,mcp_speed,column_force_n\n"
         "0.0,1,1,250,10000,0,0,0\n"
         "0.5,1,1,250,10000,0,0,0\n0.5,1,1,250,10000,1,0,0\n"
         "0.6,1,1,250,10000,1,0,0\n0.6,1,1,250,10000,0,0,0\n"
         "1.0,1,1,250,10000,0,0,0\n1.0,1,1,250,10000,0,1,0\n"
         "1.1,1,1,250,10000,0,1,0\n1.1,1,1,250,10000,0,0,0\n"
         "6.0,1,1,250,10000,0,0,0\n6.0,1,1,250,10000,0,0," + f + "\n"
         "9.0,1,1,250,10000,0,0," + f + "\n9.0,1,1,250,10000,0,0,0\n";
}

/// The pitch attitude, the FMA and the autopilot's engagement of every frame.
class Recorder final : public runtime::Component {
 public:
  Recorder()
      : Component("recorder"),
        aircraft_(reads(runtime::topics::aircraft_state)),
        autopilot_(reads(runtime::topics::autopilot_state)) {}
  void step(const runtime::FrameContext&) override {
    if (!aircraft_.latest()) return;
    time_s.push_back(aircraft_.latest()->stamp().sim_time_s());
    theta_rad.push_back(aircraft_.latest()->theta_rad());
    const msg::AutopilotState* a = autopilot_.latest();
    cws_pitch.push_back(a && a->fma().autopilot_engaged() && a->fma().pitch() == msg::FMA_PITCH_CWS);
  }
  /// The attitude at `t_s` (the first sample at or after it) [deg].
  double theta_deg_at(double t_s) const {
    for (std::size_t i = 0; i < time_s.size(); ++i) {
      if (time_s[i] >= t_s - 1e-9) return theta_rad[i] / kDeg;
    }
    return theta_rad.back() / kDeg;
  }
  bool cws_from(double t_s) const {
    for (std::size_t i = 0; i < time_s.size(); ++i) {
      if (time_s[i] >= t_s && !cws_pitch[i]) return false;
    }
    return true;
  }
  std::vector<double> time_s, theta_rad;
  std::vector<bool> cws_pitch;

 private:
  runtime::Input<msg::AircraftState>& aircraft_;
  runtime::Input<msg::AutopilotState>& autopilot_;
};

/// The I/O federate (in the control loader's loop or not), the loader, the flight federate with
/// the autopilot, at 50 Hz.
struct CwsFederation {
  CwsFederation(double pull_n, bool force_sensors)
      : io("io", std::make_unique<io::InputProfile>(io::InputProfile::parse(cws_profile(pull_n), "cws.csv")), 0, {},
           force_sensors),
        loader("control_loading", control_loading::ControlLoadingSetup{}),
        flight(make_flight_component("flight", cruise_options())),
        composition({}) {
    composition.add(io);
    composition.add(loader);
    composition.add(*flight);
    composition.add(recorder);
    composition.run(static_cast<std::uint64_t>(30.0 * 50.0));
  }
  io::IoComponent io;
  control_loading::ControlLoadingComponent loader;
  std::unique_ptr<FlightComponent> flight;
  Recorder recorder;
  runtime::Composition composition;
};

TEST(CwsForce, AColumnPullRaisesThePitchAttitudeAndReleasedTheNewAttitudeIsHeld) {
  CwsFederation f(60.0, true);
  const Recorder& r = f.recorder;
  const double before = r.theta_deg_at(6.0), at_release = r.theta_deg_at(9.0);
  const double settled = r.theta_deg_at(12.0), end = r.theta_deg_at(30.0);
  const afcs::AfcsParameters p;
  const double commanded_degps = p.cws_pitch_rate_radps / kDeg * (60.0 - p.cws_breakout_force_n) /
                                 (p.cws_full_column_force_n - p.cws_breakout_force_n);
  std::printf("CWS, 60 N pull for 3 s at 250 KCAS, 10,000 ft: pitch %.2f deg before, %.2f at release, %.2f 3 s "
              "later, %.2f at 30 s: %.2f deg per second of force (commanded %.2f deg/s)\n",
              before, at_release, settled, end, (settled - before) / 3.0, commanded_degps);
  EXPECT_TRUE(r.cws_from(2.0)) << "CWS P engaged by the MCP's button throughout";
  EXPECT_GT(settled - before, 0.8 * 3.0 * commanded_degps);  // the attitude rose with the pull
  EXPECT_LT(settled - before, 1.2 * 3.0 * commanded_degps);
  EXPECT_LT(std::abs(end - settled), 0.3);  // hands off: the new attitude held
  EXPECT_EQ(f.composition.fault_count(), 0u);
}

TEST(CwsForce, WithoutTheForceSensorsBitTheSamePullLeavesTheAttitudeHeld) {
  CwsFederation f(60.0, false);
  const Recorder& r = f.recorder;
  const double before = r.theta_deg_at(6.0), settled = r.theta_deg_at(12.0), end = r.theta_deg_at(30.0);
  std::printf("CWS, the same pull without DISCRETE_FORCE_SENSORS: pitch %.2f deg before, %.2f 3 s after, %.2f at "
              "30 s\n", before, settled, end);
  EXPECT_TRUE(r.cws_from(2.0));
  EXPECT_LT(std::abs(settled - before), 0.3);
  EXPECT_LT(std::abs(end - before), 0.3);
  EXPECT_EQ(f.composition.fault_count(), 0u);
}

TEST(CwsForce, BadForceReadingsAreRejectedAndCountedAndThePreviousInputKept) {
  // An outside writer (the I/O federate clamps its channels to +-1500 N): CWS pressed at frame
  // 25, a 60 N pull from frame 50, a non-finite column force from frame 100.
  class ForceWriter final : public runtime::Component {
   public:
    ForceWriter() : Component("trainer"), out_(writes(runtime::topics::pilot_controls)) {}
    void step(const runtime::FrameContext& frame) override {
      msg::PilotControls c;
      c.discretes(msg::DISCRETE_FORCE_SENSORS);
      c.mcp().heading_true_rad(280.0 * kDeg);
      c.mcp().altitude_msl_m(10000.0 * units::kFtToM);
      c.mcp().airspeed_cas_mps(250.0 * kKt);
      c.mcp().bank_limit_rad(25.0 * kDeg);
      c.mcp().presses()[msg::MCP_CWS] = frame.frame > 25 ? 1 : 0;
      c.pilot_force_n()[0] = frame.frame > 100 ? std::nanf("") : frame.frame > 50 ? -60.0f : 0.0f;
      c.stamp(frame.stamp());
      out_.write(c);
    }

   private:
    runtime::Output<msg::PilotControls>& out_;
  };
  ForceWriter writer;
  auto flight = make_flight_component("flight", cruise_options());
  Recorder recorder;
  runtime::Composition composition({});
  composition.add(writer);
  composition.add(*flight);
  composition.add(recorder);
  composition.run(250);
  EXPECT_GE(composition.fault_count(), 140u);
  ASSERT_FALSE(flight->faults().empty());
  EXPECT_EQ(flight->faults()[0].kind, "input_rejected");
  EXPECT_NE(flight->faults()[0].last.find("pilot_force_n[0] (column)"), std::string::npos) << flight->faults()[0].last;
  // The pull before the bad readings still commands nose up (kept, not dropped to hands off).
  EXPECT_TRUE(recorder.cws_from(1.0));
  EXPECT_GT(recorder.theta_deg_at(5.0) - recorder.theta_deg_at(2.0), 1.0);
}

}  // namespace
}  // namespace fedsim::flight
