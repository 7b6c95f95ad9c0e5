// Closed loop on VORs of the navigation database (the built nav.sqlite, OurAirports' records:
// SFO VOR-DME 115.80, slaved variation 17.0 E), received through common/radio's NavRadio as the
// navigation federate's NAV1 is, the 737 pack flown by the AFCS at 250 KCAS, 10,000 ft (290 KTAS):
// (a) VOR/LOC captures a radial 15-20 NM out from a 30 and a 45 deg intercept, with and without
//     the DME: overshoot < 0.3 of full scale (3 deg), tracking within 0.1 (1 deg) after capture;
// (b) station passage inbound and out the other side, the course held through the cone of
//     confusion, the outbound course (the same, or 30 deg to the right) re-captured;
// (c) a flagged VOR disengages with the VOR FLAG alert; an armed mode never captures one;
// (d) negative control: not armed, the aircraft keeps its heading across the radial.
#include "closed_loop_support.hpp"

#include "common/navdb/nav_database.hpp"
#include "common/radio/in_memory_station_source.hpp"
#include "common/radio/nav_radio.hpp"
#include "common/radio/station_outages.hpp"

#include <GeographicLib/Geodesic.hpp>

namespace fedsim::flight::afcs::testing {
namespace {

constexpr std::uint32_t kSfoKhz = 115800;

/// NAV1 over the navigation database's stations on the frequencies the tests tune.
struct Nav1 {
  nav::NavDatabase database = nav::NavDatabase::open(nav::default_database_path());
  radio::InMemoryStationSource stations;
  radio::StationOutages outages;
  radio::NavRadio radio;
  nav::Navaid sfo;

  explicit Nav1(const radio::VorReceiverSettings& settings = {}) : radio(stations, outages, settings) {
    for (nav::Navaid& n : database.on_frequency(kSfoKhz)) {
      if (n.ident == "SFO") sfo = n;
      stations.add(std::move(n));
    }
  }
};

const GeographicLib::Geodesic& wgs84() { return GeographicLib::Geodesic::WGS84(); }

/// The point `along_m` from the station on the true azimuth `radial_rad`, then `left_m` to the
/// left of the direction `course_rad` (true), at `altitude_m`.
GeodeticPosition point_from(const nav::Navaid& station, double radial_rad, double along_m, double course_rad,
                            double left_m, double altitude_m) {
  double lat = 0.0, lon = 0.0, lat2 = 0.0, lon2 = 0.0;
  wgs84().Direct(station.position.lat_rad / kDeg, station.position.lon_rad / kDeg, radial_rad / kDeg, along_m, lat, lon);
  wgs84().Direct(lat, lon, (course_rad - 90.0 * kDeg) / kDeg, left_m, lat2, lon2);
  return {lat2 * kDeg, lon2 * kDeg, altitude_m};
}

/// Distance left of the course line through the station [m]: the course `course_rad` (true at
/// the station) flown FROM (outbound, along its radial) or TO (inbound, on the reciprocal radial).
double left_of_course_m(const nav::Navaid& station, double course_rad, bool from, const FlightSample& s) {
  double distance = 0.0, azimuth1 = 0.0, azimuth2 = 0.0;
  wgs84().Inverse(station.position.lat_rad / kDeg, station.position.lon_rad / kDeg, s.lat_rad / kDeg,
                  s.lon_rad / kDeg, distance, azimuth1, azimuth2);
  const double radial = from ? course_rad : course_rad + units::kPi;
  return (from ? 1.0 : -1.0) * distance * std::sin(radial - azimuth1 * kDeg);
}

/// Clean, 250 KCAS, level at 10,000 ft at `start`, heading `heading_rad`, ALT HLD and SPEED,
/// NAV1 on SFO with the OBS `obs_deg` (magnetic).
std::unique_ptr<ClosedLoopFlight> at_10000_ft(Nav1& nav1, const GeodeticPosition& start, double heading_rad,
                                              double obs_deg) {
  auto f = make_flight();
  const TrimResult t = f->start_level_at(start, heading_rad, 290 * kKt, clean_configuration());
  EXPECT_TRUE(t.converged) << t.reason;
  f->set_nav1(&nav1.radio, {kSfoKhz, obs_deg * kDeg});
  engage_holding(*f);
  return f;
}

/// The OBS's course, true (the VOR is aligned to its slaved variation).
double course_true_rad(const Nav1& nav1, double obs_deg) {
  return obs_deg * kDeg + nav1.sfo.slaved_variation_rad;
}

struct CaptureFigures {
  double capture_s = NAN;
  double capture_deviation = NAN;  // full scale, at the capture point
  double overshoot = 0.0;          // full scale, beyond the course after the first crossing
  double overshoot_m = 0.0;
  double tracking = 0.0;           // |deviation| from 60 s after capture, full scale
  double tracking_m = 0.0;
  double distance_nm = 0.0;        // from the station at capture
};

/// Figures of a run started on side `side` (+1 left of the course: deviation +).
CaptureFigures capture_figures(const ClosedLoopFlight& f, const Nav1& nav1, double course, bool from, double side) {
  CaptureFigures out;
  out.capture_s = time_entered(f.transitions(), ModeTransition::Channel::kLateral, "VOR/LOC");
  if (std::isnan(out.capture_s)) return out;
  bool crossed = false;
  for (const FlightSample& s : f.history()) {
    if (!s.vor_valid) continue;
    const double left = left_of_course_m(nav1.sfo, course, from, s);
    if (std::isnan(out.capture_deviation) && s.time_s >= out.capture_s) {
      out.capture_deviation = s.vor_deviation;
      double d = 0.0;
      wgs84().Inverse(nav1.sfo.position.lat_rad / kDeg, nav1.sfo.position.lon_rad / kDeg, s.lat_rad / kDeg,
                      s.lon_rad / kDeg, d);
      out.distance_nm = d / kNm;
    }
    if (!crossed && side * s.vor_deviation < 0.0) crossed = true;
    if (crossed) {
      out.overshoot = std::max(out.overshoot, -side * s.vor_deviation);
      out.overshoot_m = std::max(out.overshoot_m, -side * left);
    }
    if (s.time_s >= out.capture_s + 60.0) {
      out.tracking = std::max(out.tracking, std::abs(s.vor_deviation));
      out.tracking_m = std::max(out.tracking_m, std::abs(left));
    }
  }
  return out;
}

// SFO R-240 outbound (course 257.0 true), 3 NM to either side, converging so as to cross the
// radial about 18 NM from the station (the needle pegged at the start: 13 deg off).
TEST(VorInFlight, RadialCaptureFrom30And45DegreesOvershootsLessThan3DegreesAndTracksWithin1Degree) {
  constexpr double kObsDeg = 240.0;
  for (const bool dme : {true, false})
  for (const double intercept : {30.0, 45.0})
  for (const double side : {+1.0, -1.0}) {
    Nav1 nav1;
    if (!dme) nav1.outages.set_off_air("SFO", radio::StationComponent::kDme);
    const double course = course_true_rad(nav1, kObsDeg);
    const double offset_m = 3.0 * kNm;
    const double along_m = 18.0 * kNm - offset_m / std::tan(intercept * kDeg);
    auto f = at_10000_ft(nav1, point_from(nav1.sfo, course, along_m, course, side * offset_m, 10000 * kFt),
                         course + side * intercept * kDeg, kObsDeg);
    f->press(button(&McpButtons::vor_localizer));
    f->run_for(240.0);
    const std::string name = std::string("vor_capture_") + (side > 0 ? "left_" : "right_") +
                             std::to_string(static_cast<int>(intercept)) + (dme ? "" : "_no_dme");
    maybe_trace(*f, name);
    maybe_print_transitions(*f);
    const CaptureFigures c = capture_figures(*f, nav1, course, true, side);
    ASSERT_FALSE(std::isnan(c.capture_s)) << name;
    std::printf("VOR capture SFO R-240, %.0f deg from the %s%s: captured %.1f NM out at %.2f of full scale, "
                "overshoot %.3f (%.2f deg, %.0f m), tracking within %.3f (%.0f m) from 60 s after capture\n",
                intercept, side > 0 ? "left" : "right", dme ? "" : ", no DME", c.distance_nm,
                std::abs(c.capture_deviation), c.overshoot, c.overshoot * 10.0, c.overshoot_m, c.tracking,
                c.tracking_m);
    const double armed_s = time_entered(f->transitions(), ModeTransition::Channel::kLateralArmed, "VOR/LOC");
    EXPECT_LT(armed_s, 0.1) << "armed at the press";
    EXPECT_GT(c.capture_s, armed_s + 20.0) << "captured at the lead point, not at once";
    EXPECT_LT(std::abs(c.capture_deviation), 0.5) << "on scale, at the lead point";
    EXPECT_LT(c.overshoot, 0.3);
    EXPECT_LT(c.tracking, 0.1);
    EXPECT_EQ(f->sample().fma.lateral, LateralMode::kLocalizer);
    EXPECT_TRUE(f->sample().fma.vor);
    EXPECT_TRUE(f->sample().fma.autopilot_engaged);
  }
}

/// Inbound to SFO on the OBS `obs_deg` (TO), `before_nm` out and `left_m` off the course.
std::unique_ptr<ClosedLoopFlight> inbound(Nav1& nav1, double obs_deg, double before_nm, double left_m) {
  const double course = course_true_rad(nav1, obs_deg);
  return at_10000_ft(nav1, point_from(nav1.sfo, course + units::kPi, before_nm * kNm, course, left_m, 10000 * kFt),
                     course, obs_deg);
}

struct PassageFigures {
  double over_station_s = NAN;     // OVER STATION entered
  double tracking_s = NAN;         // ... and left
  double max_left_through_m = 0.0; // |left of the inbound course line|, 3 NM either side of the station
  double settled_s = NAN;          // from the end of OVER STATION to within 0.1 of full scale for good
  double overshoot = 0.0;          // beyond the outbound course after its first crossing, full scale
  double outbound_tracking_m = 0.0;  // |left of the outbound course| once settled
};

PassageFigures passage_figures(const ClosedLoopFlight& f, const Nav1& nav1, double inbound_course,
                               double outbound_course) {
  PassageFigures out;
  out.over_station_s = time_entered(f.transitions(), ModeTransition::Channel::kLateralSubmode, "OVER STATION");
  for (const ModeTransition& t : f.transitions()) {
    if (t.channel == ModeTransition::Channel::kLateralSubmode && t.from == "OVER STATION") out.tracking_s = t.time_s;
  }
  // The re-capture: from the side the needle shows when the course is tracked again.
  bool crossed = false;
  double start_side = 0.0;
  for (const FlightSample& s : f.history()) {
    if (s.time_s < out.tracking_s || !s.vor_valid) continue;
    if (start_side == 0.0) start_side = s.vor_deviation >= 0.0 ? 1.0 : -1.0;
    if (!crossed && start_side * s.vor_deviation < 0.0) crossed = true;
    if (crossed) out.overshoot = std::max(out.overshoot, -start_side * s.vor_deviation);
    if (std::abs(s.vor_deviation) >= 0.1) out.settled_s = NAN;
    else if (std::isnan(out.settled_s)) out.settled_s = s.time_s - out.tracking_s;
  }
  for (const FlightSample& s : f.history()) {
    double d = 0.0;
    wgs84().Inverse(nav1.sfo.position.lat_rad / kDeg, nav1.sfo.position.lon_rad / kDeg, s.lat_rad / kDeg,
                    s.lon_rad / kDeg, d);
    if (d < 3.0 * kNm) {
      // Either side of the station the inbound course line goes on as the same great circle.
      out.max_left_through_m =
          std::max(out.max_left_through_m, std::abs(left_of_course_m(nav1.sfo, inbound_course, true, s)));
    }
    if (s.time_s > out.tracking_s + out.settled_s) {
      out.outbound_tracking_m =
          std::max(out.outbound_tracking_m, std::abs(left_of_course_m(nav1.sfo, outbound_course, true, s)));
    }
  }
  return out;
}

// Inbound on SFO R-240 (OBS 060, TO), captured 12 NM out from 300 m off the course, over the
// station at 10,000 ft (the cone of confusion, 60 deg above the station's horizontal, is 3.5 km
// across) and out on R-060 (the same OBS, now FROM); then the same with the OBS turned to 090 over
// the station (outbound on R-090, a 30 deg turn); and with a receiver that never flags the cone
// (its bearing swings overhead: the erratic deviation and TO turning FROM are the cues).
TEST(VorInFlight, StationPassageHoldsTheCourseThroughTheConeThenTracksTheOutboundCourse) {
  for (const double outbound_obs : {60.0, 90.0, -60.0}) {
    const bool cone_flagged = outbound_obs > 0.0;
    radio::VorReceiverSettings settings;
    if (!cone_flagged) settings.cone_of_confusion_elevation_rad = 90.0 * kDeg;
    Nav1 nav1(settings);
    auto f = inbound(nav1, 60.0, 12.0, 300.0);
    f->press(button(&McpButtons::vor_localizer));
    ASSERT_TRUE(f->run_until([](const FlightSample& s) { return s.fma.vor_over_station; }, 300.0));
    const double outbound = std::abs(outbound_obs);
    f->nav1_tuning().obs_course_magnetic_rad = outbound * kDeg;  // the crew sets the outbound course
    f->run_for(300.0);
    const std::string name = "vor_station_passage_" + std::to_string(static_cast<int>(outbound)) +
                             (cone_flagged ? "" : "_no_cone_flag");
    maybe_trace(*f, name);
    maybe_print_transitions(*f);
    const PassageFigures p = passage_figures(*f, nav1, course_true_rad(nav1, 60.0), course_true_rad(nav1, outbound));
    std::printf("VOR station passage SFO%s, inbound OBS 060, outbound OBS %03.0f: OVER STATION for %.1f s, "
                "within %.0f m of the inbound course line 3 NM either side of the station; outbound: "
                "overshoot %.3f of full scale, within 0.1 for good %.0f s after OVER STATION, then within %.0f m\n",
                cone_flagged ? "" : " (cone not flagged)", outbound, p.tracking_s - p.over_station_s,
                p.max_left_through_m, p.overshoot, p.settled_s,
                p.outbound_tracking_m);
    ASSERT_FALSE(std::isnan(p.tracking_s)) << "OVER STATION never ended";
    EXPECT_GT(p.tracking_s - p.over_station_s, 10.0);
    EXPECT_LT(p.tracking_s - p.over_station_s, 60.0);
    if (outbound == 60.0) {
      EXPECT_LT(p.max_left_through_m, 100.0);  // the course held through the cone
      EXPECT_LT(p.settled_s, 1.0);             // ... and still on it
    }
    EXPECT_LT(p.overshoot, 0.3);
    EXPECT_LT(p.settled_s, 150.0);
    EXPECT_TRUE(f->sample().fma.autopilot_engaged);
    EXPECT_EQ(f->sample().fma.alerts, kAlertNone);
    EXPECT_EQ(f->sample().fma.lateral, LateralMode::kLocalizer);
    EXPECT_TRUE(f->sample().fma.vor);
  }
}

// Established outbound on R-240, the station goes off the air (signal VOR, flagged) or NAV1's
// receiver fails (no signal): the autopilot disengages with the VOR FLAG alert, the flight
// director drops to HDG HOLD; armed, a flagged VOR is never captured.
TEST(VorInFlight, AFlaggedVorDisengagesWithAnAlertAndIsNeverCaptured) {
  for (const bool receiver_failed : {false, true}) {
    Nav1 nav1;
    const double course = course_true_rad(nav1, 240.0);
    auto f = at_10000_ft(nav1, point_from(nav1.sfo, course, 15.0 * kNm, course, 500.0, 10000 * kFt), course, 240.0);
    f->press(button(&McpButtons::vor_localizer));
    f->run_for(60.0);
    ASSERT_EQ(f->sample().fma.lateral, LateralMode::kLocalizer);
    if (receiver_failed) {
      nav1.radio.set_failed(true);
    } else {
      nav1.outages.set_off_air("SFO");
    }
    f->run_for(20.0);
    maybe_print_transitions(*f);
    const FlightSample& s = f->sample();
    EXPECT_FALSE(s.fma.autopilot_engaged);
    EXPECT_TRUE(s.fma.alerts & kAlertVorInvalid);
    EXPECT_TRUE(s.fma.alerts & kAlertAutopilotDisconnect);
    EXPECT_EQ(s.fma.lateral, LateralMode::kHeadingHold);
    EXPECT_FALSE(s.fma.vor);
  }
  // Armed with the station off the air from the start: never captured, the heading kept.
  Nav1 nav1;
  nav1.outages.set_off_air("SFO");
  const double course = course_true_rad(nav1, 240.0);
  auto f = at_10000_ft(nav1, point_from(nav1.sfo, course, 15.0 * kNm, course, 3.0 * kNm, 10000 * kFt),
                       course + 30.0 * kDeg, 240.0);
  f->press(button(&McpButtons::vor_localizer));
  f->run_for(180.0);
  EXPECT_TRUE(std::isnan(time_entered(f->transitions(), ModeTransition::Channel::kLateral, "VOR/LOC")));
  EXPECT_TRUE(f->sample().fma.lateral_armed.localizer);
  EXPECT_EQ(f->sample().fma.alerts, kAlertNone);  // not flown: nothing to alert
  EXPECT_NEAR(wrap_angle_rad(f->sample().heading_rad - (course + 30.0 * kDeg)) / kDeg, 0.0, 1.0);
}

// Negative control: the geometry of the 30 deg capture with VOR/LOC not armed (HDG HOLD): the
// aircraft keeps its heading across the radial, and the overshoot figure of the capture test
// would then fail (the needle goes to full scale on the other side).
TEST(VorInFlight, NotArmedTheAircraftKeepsItsHeadingAcrossTheRadial) {
  Nav1 nav1;
  const double course = course_true_rad(nav1, 240.0);
  const double heading = course + 30.0 * kDeg;
  auto f = at_10000_ft(nav1, point_from(nav1.sfo, course, 18.0 * kNm - 3.0 * kNm / std::tan(30.0 * kDeg), course,
                                        3.0 * kNm, 10000 * kFt),
                       heading, 240.0);
  f->run_for(240.0);
  maybe_trace(*f, "vor_not_armed");
  const CaptureFigures c = capture_figures(*f, nav1, course, true, +1.0);
  double heading_error_deg = 0.0, overshoot = 0.0;
  bool crossed = false;
  for (const FlightSample& s : f->history()) {
    heading_error_deg = std::max(heading_error_deg, std::abs(wrap_angle_rad(s.heading_rad - heading)) / kDeg);
    if (s.vor_valid && s.vor_deviation < 0.0) crossed = true;
    if (crossed && s.vor_valid) overshoot = std::max(overshoot, -s.vor_deviation);
  }
  std::printf("VOR/LOC not armed, 30 deg towards SFO R-240: heading within %.2f deg, %.2f of full scale beyond "
              "the radial\n", heading_error_deg, overshoot);
  EXPECT_TRUE(std::isnan(c.capture_s));
  EXPECT_TRUE(crossed);
  EXPECT_GT(overshoot, 0.9);
  EXPECT_LT(heading_error_deg, 1.0);
  EXPECT_EQ(f->sample().fma.lateral, LateralMode::kHeadingHold);
}

// Beyond the calm air: the 30 deg capture in a 30 kt wind across the radial (from its
// right, the aircraft crabbing 6 deg into it) with light turbulence; the same bounds.
TEST(VorInFlight, RadialCaptureIn30KnotsOfCrosswindWithLightTurbulence) {
  for (const double side : {+1.0, -1.0}) {
    Nav1 nav1;
    const double course = course_true_rad(nav1, 240.0);
    auto f = make_flight();
    WeatherSettings w;
    w.wind.altitude_m = {0.0, 10000.0};
    w.wind.speed_mps = {30.0 * kKt, 30.0 * kKt};
    w.wind.from_direction_rad = {course + units::kHalfPi, course + units::kHalfPi};
    w.turbulence = Turbulence::Severity::kLight;
    w.turbulence_seed = 11;
    f->model().set_weather(w);
    const double offset_m = 3.0 * kNm;
    const TrimResult t = f->start_level_at(
        point_from(nav1.sfo, course, 18.0 * kNm - offset_m / std::tan(30.0 * kDeg), course, side * offset_m,
                   10000 * kFt),
        course + side * 30.0 * kDeg, 290 * kKt, clean_configuration());
    ASSERT_TRUE(t.converged) << t.reason;
    f->set_nav1(&nav1.radio, {kSfoKhz, 240.0 * kDeg});
    engage_holding(*f);
    f->mcp().heading_true_rad = course + side * 30.0 * kDeg;  // the intercept heading (HDG SEL) in the wind
    f->press(button(&McpButtons::heading_select));
    f->press(button(&McpButtons::vor_localizer));
    f->run_for(300.0);
    maybe_trace(*f, std::string("vor_capture_crosswind_") + (side > 0 ? "left" : "right"));
    const CaptureFigures c = capture_figures(*f, nav1, course, true, side);
    ASSERT_FALSE(std::isnan(c.capture_s));
    std::printf("VOR capture SFO R-240, 30 deg from the %s, 30 kt crosswind, light turbulence: captured %.1f NM out, "
                "overshoot %.3f of full scale (%.0f m), tracking within %.3f (%.0f m) from 60 s after capture\n",
                side > 0 ? "left" : "right", c.distance_nm, c.overshoot, c.overshoot_m, c.tracking, c.tracking_m);
    EXPECT_LT(c.overshoot, 0.3);
    EXPECT_LT(c.tracking, 0.1);
    EXPECT_TRUE(f->sample().fma.autopilot_engaged);
  }
}

}  // namespace
}  // namespace fedsim::flight::afcs::testing
