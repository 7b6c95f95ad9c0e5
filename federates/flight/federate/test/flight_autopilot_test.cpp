// The AFCS hosted by the flight federate, flown in the in-process composition with the I/O and
// navigation federates' own components (the same adapters fedsim-io, fedsim-flight --autopilot
// and fedsim-nav run over DDS): the pilot's MCP presses come from a scripted input profile, NAV1
// is tuned to the KSFO 28R localizer from the profile, the AFCS reads the navigation federate's
// ILS readings, and the 737 flies from a 30 deg intercept to an automatic landing and rollout.
// Also: VOR/LOC on SFO VOR (NAV1 on 115.80 MHz, OBS 240) captures the radial from the
// navigation federate's VOR readings; the instructor's autopilot failure disengages it with an
// alert; a bad MCP panel is rejected and counted.
#include "common/util/build_paths.hpp"
#include "flight/federate/flight_program.hpp"
#include "flight/model/afcs/ils_approach_source.hpp"
#include "flight/model/afcs/landing_figures.hpp"
#include "io/io_component.hpp"
#include "io/model/input_profile.hpp"
#include "nav/nav_component.hpp"

#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <memory>
#include <string>

namespace fedsim::flight {
namespace {

constexpr double kFt = units::kFtToM;
constexpr double kKt = units::kKtToMps;
constexpr double kDeg = units::kDegToRad;

/// The pilot's side of the approach: the profile deploy/ils-autoland.yaml flies (NAV1 on I-GWQ
/// 111.70 MHz, A/T armed, CMD, ALT HLD and SPEED, then 145 kt, autobrake 2 and APP).
std::string approach_profile() {
  std::ifstream in(fedsim::util::data_dir() + "/profiles/ils_autoland.csv");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_FALSE(text.str().empty()) << "data/profiles/ils_autoland.csv";
  return text.str();
}

FlightOptions approach_options(bool autopilot) {
  FlightOptions o;
  o.aircraft = "b737";
  o.autopilot = autopilot;
  o.controls = "relative";
  o.start.airport = "KSFO";
  o.start.runway = "28R";
  // As deploy/ils-autoland.yaml starts: 12 NM out, 1.5 NM left of the centreline, 30 deg.
  o.start.approach_nm = 12.0;
  o.start.approach_offset_nm = 1.5;
  o.start.intercept_deg = 30.0;
  o.start.alt_ft = 2500.0;
  o.start.kcas = 150.0;
  o.start.flaps = 0.875;  // flaps 30
  o.start.gear_down = true;
  return o;
}

/// Keeps what the test judges: the aircraft state and the FMA of every frame.
class Recorder final : public runtime::Component {
 public:
  Recorder()
      : Component("recorder"),
        aircraft_(reads(runtime::topics::aircraft_state)),
        autopilot_(reads(runtime::topics::autopilot_state)) {}
  void step(const runtime::FrameContext&) override {
    if (aircraft_.latest()) {
      state = *aircraft_.latest();
      if (state.on_ground() && !touchdown) touchdown = state;
    }
    if (autopilot_.latest()) {
      const msg::AutopilotState& a = *autopilot_.latest();
      if (!first_entered.count(a.fma().roll() * 100 + a.fma().pitch())) {
        first_entered[a.fma().roll() * 100 + a.fma().pitch()] = a.stamp().sim_time_s();
      }
      autopilot = a;
      roll_seen[a.fma().roll()] = true;
      pitch_seen[a.fma().pitch()] = true;
      if (a.fma().pitch() == msg::FMA_PITCH_GLIDE_SLOPE && gs_capture_s < 0) gs_capture_s = a.stamp().sim_time_s();
      if (a.fma().roll() == msg::FMA_ROLL_LOCALIZER && loc_capture_s < 0) loc_capture_s = a.stamp().sim_time_s();
    }
  }
  msg::AircraftState state;
  std::optional<msg::AircraftState> touchdown;
  msg::AutopilotState autopilot;
  std::map<int, double> first_entered;
  std::map<int, bool> roll_seen, pitch_seen;
  double gs_capture_s = -1.0, loc_capture_s = -1.0;

 private:
  runtime::Input<msg::AircraftState>& aircraft_;
  runtime::Input<msg::AutopilotState>& autopilot_;
};

/// The I/O, flight and navigation components with a recorder, in one composition at 50 Hz.
struct ApproachFederation {
  explicit ApproachFederation(const std::string& profile, bool autopilot = true)
      : ApproachFederation(profile, approach_options(autopilot)) {}
  ApproachFederation(const std::string& profile, const FlightOptions& options)
      : io("io", std::make_unique<io::InputProfile>(io::InputProfile::parse(profile, "approach.csv")), 0),
        flight(make_flight_component("flight", options)),
        nav("nav", nav_setup()),
        composition({}) {
    composition.add(io);
    composition.add(*flight);
    composition.add(nav);
    composition.add(recorder);
  }
  static nav::NavSetup nav_setup() {
    nav::NavSetup setup;
    setup.database = std::make_unique<nav::NavDatabase>(nav::NavDatabase::open(nav::default_database_path()));
    return setup;
  }
  /// Runs until the aircraft has stopped on the ground (or `max_s`); returns the time flown.
  double fly_to_stop(double max_s) {
    const auto frames = static_cast<std::uint64_t>(max_s * 50.0);
    for (std::uint64_t i = 0; i < frames; ++i) {
      composition.step_frame();
      if (recorder.touchdown && recorder.state.ground_speed_mps() < 0.5) break;
    }
    return composition.last_frame().sim_time_s;
  }

  io::IoComponent io;
  std::unique_ptr<FlightComponent> flight;
  nav::NavComponent nav;
  Recorder recorder;
  runtime::Composition composition;
};

msg::SimCommand failure(const std::string& target, bool active) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_FAILURE);
  c.target(target);
  c.failure().active(active);
  return c;
}

TEST(FlightAutopilot, FliesTheIlsFromTheNavFederatesReadingsToAStopOnTheCentreline) {
  ApproachFederation f(approach_profile());
  const double flown_s = f.fly_to_stop(480.0);
  const Recorder& r = f.recorder;
  ASSERT_TRUE(r.touchdown) << "no touchdown in " << flown_s << " s";
  const msg::AircraftState& t = *r.touchdown;
  const auto runway =
      RunwayCentreline::from_table(RunwayTable::load_default(), "KSFO", "28R");
  const double beyond_m = runway.beyond_threshold_m(t.latitude_rad(), t.longitude_rad());
  const double left_m = runway.left_m(t.latitude_rad(), t.longitude_rad());
  // The localizer course as data/nav/ils.csv publishes it (what the nav federate's receiver
  // flies): it passes 7.6 m left of the threshold (data/nav/ILS.md "Known offset: KSFO 28R").
  const nav::IlsApproach ils = afcs::load_default_ils_approach("KSFO", "28R");
  const double left_of_course_m =
      radio::course_coordinates(ils, radio::approach_geometry(ils), t.latitude_rad(), t.longitude_rad()).left_m;
  const double sink_mps = t.velocity_ned_mps()[2];
  const double stop_left_m = runway.left_m(r.state.latitude_rad(), r.state.longitude_rad());
  const double stop_beyond_m = runway.beyond_threshold_m(r.state.latitude_rad(), r.state.longitude_rad());
  std::printf("federation autoland: LOC at %.1f s, G/S at %.1f s, touchdown %.0f ft beyond the threshold, "
              "%+.2f m left of the centreline (%+.2f m of the published localizer course), sink %.2f ft/s, bank %+.2f deg, %.1f KCAS; stopped %.0f m beyond, "
              "%+.2f m off, %.0f s flown\n",
              r.loc_capture_s, r.gs_capture_s, beyond_m / kFt, left_m, left_of_course_m, sink_mps / kFt, t.phi_rad() / kDeg,
              t.air().cas_mps() / kKt, stop_beyond_m, stop_left_m, flown_s);
  // The limits (landing_figures.hpp), against the runway's own centreline.
  EXPECT_GT(r.loc_capture_s, 0.0);
  EXPECT_GT(r.gs_capture_s, r.loc_capture_s);
  EXPECT_TRUE(r.roll_seen.count(msg::FMA_ROLL_ALIGN));
  EXPECT_TRUE(r.pitch_seen.count(msg::FMA_PITCH_FLARE));
  EXPECT_TRUE(r.roll_seen.count(msg::FMA_ROLL_ROLLOUT));
  EXPECT_LT(std::abs(left_m), 27.0 * kFt);
  EXPECT_LT(std::abs(left_of_course_m), 2.0);  // the AFCS flew the beam it was given
  EXPECT_LT(sink_mps, 6.0 * kFt);
  EXPECT_GT(beyond_m, 200.0 * kFt);
  EXPECT_LT(beyond_m, 2700.0 * kFt);
  EXPECT_LT(std::abs(t.phi_rad()), 5.0 * kDeg);
  EXPECT_LT(r.state.ground_speed_mps(), 0.5);
  EXPECT_LT(stop_beyond_m, runway.length_m());
  EXPECT_LT(std::abs(stop_left_m), 15.0);
  EXPECT_TRUE(r.autopilot.fma().autopilot_engaged());
  EXPECT_EQ(r.autopilot.fma().alerts(), 0u);
  EXPECT_GT(r.autopilot.transitions(), 6u);
  EXPECT_EQ(f.composition.fault_count(), 0u);
  // Stopped, the autothrottle lets go where it retarded the levers: idle, and the aircraft
  // stays where it stopped (relative controls fly about the levers it back-drove).
  f.composition.run(500);
  EXPECT_LT(r.state.controls().throttle()[0], 0.05);
  EXPECT_LT(r.state.ground_speed_mps(), 0.5);
}

TEST(FlightAutopilot, WithNavOneUntunedTheApproachArmsButNeverCaptures) {
  // Negative control of the test above: the same flight with NAV1 left on 0 (not tuned) never
  // captures the localizer and never lands - the capture came from the nav federate's readings.
  std::string profile = approach_profile();
  for (std::size_t at = profile.find(",111.70,"); at != std::string::npos; at = profile.find(",111.70,", at)) {
    profile.replace(at, 8, ",0,");
  }
  ApproachFederation f(profile);
  f.fly_to_stop(60.0);
  EXPECT_LT(f.recorder.loc_capture_s, 0.0);
  EXPECT_FALSE(f.recorder.touchdown);
  EXPECT_TRUE(f.recorder.autopilot.fma().autopilot_engaged());
  EXPECT_TRUE(f.recorder.autopilot.fma().roll_armed_localizer());
}

TEST(FlightAutopilot, CapturesAVorRadialFromTheNavFederatesVorReadings) {
  // 3 NM left of SFO R-240 (OBS 240, 257.0 deg true), 30 deg towards it, to cross it 18 NM out;
  // 250 KCAS at 10,000 ft, clean. NAV1 on 115.80 from the profile; VOR LOC pressed at 2 s.
  const nav::NavDatabase db = nav::NavDatabase::open(nav::default_database_path());
  const auto sfo = db.nearest_on_frequency(37.6 * kDeg, -122.4 * kDeg, 115800);
  ASSERT_TRUE(sfo && sfo->navaid.ident == "SFO");
  const double course_deg = 240.0 + sfo->navaid.slaved_variation_rad / kDeg;
  const auto& geod = GeographicLib::Geodesic::WGS84();
  double lat = 0, lon = 0, lat2 = 0, lon2 = 0;
  geod.Direct(sfo->navaid.position.lat_rad / kDeg, sfo->navaid.position.lon_rad / kDeg, course_deg,
              (18.0 - 3.0 / std::tan(30.0 * kDeg)) * 1852.0, lat, lon);
  geod.Direct(lat, lon, course_deg - 90.0, 3.0 * 1852.0, lat2, lon2);
  FlightOptions o;
  o.aircraft = "b737";
  o.autopilot = true;
  o.controls = "relative";
  o.start.trim_kind = "level";
  o.start.lat_deg = lat2;
  o.start.lon_deg = lon2;
  o.start.alt_ft = 10000.0;
  o.start.kcas = 250.0;
  o.start.heading_deg = course_deg + 30.0;
  const std::string profile =
      "time_s,nav1_mhz,obs1_deg,fd,at_arm,mcp_speed_kt,mcp_altitude_ft,mcp_cmd,mcp_alt_hld,mcp_speed,mcp_vor_loc\n"
      "0.0,115.80,240,1,1,250,10000,0,0,0,0\n"
      "0.5,115.80,240,1,1,250,10000,0,0,0,0\n0.5,115.80,240,1,1,250,10000,1,0,0,0\n"
      "0.6,115.80,240,1,1,250,10000,1,0,0,0\n0.6,115.80,240,1,1,250,10000,0,0,0,0\n"
      "1.0,115.80,240,1,1,250,10000,0,0,0,0\n1.0,115.80,240,1,1,250,10000,0,1,1,0\n"
      "1.1,115.80,240,1,1,250,10000,0,1,1,0\n1.1,115.80,240,1,1,250,10000,0,0,0,0\n"
      "2.0,115.80,240,1,1,250,10000,0,0,0,0\n2.0,115.80,240,1,1,250,10000,0,0,0,1\n"
      "2.1,115.80,240,1,1,250,10000,0,0,0,1\n2.1,115.80,240,1,1,250,10000,0,0,0,0\n";
  ApproachFederation f(profile, o);
  f.fly_to_stop(10.0);
  EXPECT_TRUE(f.recorder.autopilot.fma().roll_armed_localizer());
  EXPECT_EQ(f.recorder.autopilot.fma().roll(), msg::FMA_ROLL_HEADING_HOLD);
  f.fly_to_stop(230.0);
  std::printf("Federation, SFO R-240 from 30 deg: VOR/LOC captured at %.1f s, %.0f m off the radial at %.0f s\n",
              f.recorder.loc_capture_s, f.recorder.autopilot.cross_track_left_m(),
              f.recorder.autopilot.stamp().sim_time_s());
  EXPECT_GT(f.recorder.loc_capture_s, 30.0);  // at the lead point (about 60 s), not at once
  EXPECT_EQ(f.recorder.autopilot.fma().roll(), msg::FMA_ROLL_LOCALIZER);
  EXPECT_FALSE(f.recorder.autopilot.fma().pitch_armed_glide_slope());
  EXPECT_TRUE(f.recorder.autopilot.fma().autopilot_engaged());
  EXPECT_EQ(f.recorder.autopilot.fma().alerts(), 0u);
  // 1 deg (0.1 of full scale) at 18 NM is 580 m.
  EXPECT_LT(std::abs(f.recorder.autopilot.cross_track_left_m()), 100.0);
}

TEST(FlightAutopilot, TheInstructorsAutopilotFailureDisengagesItWithAnAlert) {
  ApproachFederation f(approach_profile());
  f.fly_to_stop(5.0);
  ASSERT_TRUE(f.recorder.autopilot.fma().autopilot_engaged());
  ASSERT_EQ(f.recorder.autopilot.fma().pitch(), msg::FMA_PITCH_ALTITUDE_HOLD);
  f.composition.command(failure("autopilot", true));
  f.fly_to_stop(1.0);
  EXPECT_FALSE(f.recorder.autopilot.fma().autopilot_engaged());
  EXPECT_NE(f.recorder.autopilot.fma().alerts() & msg::AFCS_ALERT_AP_FAILED, 0u);
  EXPECT_TRUE(f.recorder.autopilot.fma().autothrottle_engaged());  // the A/T is another failure
  f.composition.command(failure("autothrottle", true));
  f.fly_to_stop(1.0);
  EXPECT_FALSE(f.recorder.autopilot.fma().autothrottle_engaged());
  EXPECT_NE(f.recorder.autopilot.fma().alerts() & msg::AFCS_ALERT_AT_FAILED, 0u);
}

TEST(FlightAutopilot, ABadMcpPanelIsRejectedAndCountedAndThePreviousOneKept) {
  // A panel no profile can write (the I/O federate clamps its channels): an outside writer's
  // sample, through a component of its own.
  class BadPanelWriter final : public runtime::Component {
   public:
    BadPanelWriter() : Component("trainer"), out_(writes(runtime::topics::pilot_controls)) {}
    void step(const runtime::FrameContext& frame) override {
      msg::PilotControls c;
      c.gear_down(true);
      c.flaps(0.875);
      c.mcp().airspeed_cas_mps(frame.frame > 100 ? std::nan("") : 150.0 * kKt);
      c.mcp().bank_limit_rad(25.0 * kDeg);
      c.stamp(frame.stamp());
      out_.write(c);
    }

   private:
    runtime::Output<msg::PilotControls>& out_;
  };
  BadPanelWriter writer;
  auto flight = make_flight_component("flight", approach_options(true));
  Recorder recorder;
  runtime::Composition composition({});
  composition.add(writer);
  composition.add(*flight);
  composition.add(recorder);
  composition.run(150);
  EXPECT_GE(composition.fault_count(), 40u);
  ASSERT_FALSE(flight->faults().empty());
  EXPECT_EQ(flight->faults()[0].kind, "input_rejected");
  EXPECT_NE(flight->faults()[0].last.find("airspeed"), std::string::npos) << flight->faults()[0].last;
  EXPECT_TRUE(std::isfinite(recorder.state.air().cas_mps()));
}

}  // namespace
}  // namespace fedsim::flight
