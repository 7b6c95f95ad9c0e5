// The state topics -> the displays' inputs: deviations in dots with the sign kept (+ fly right,
// + fly up), flags for a tuned station that is not usable, nothing for one not tuned, headings
// magnetic by the local variation, trends, the FD's source, the FMA's words, bearing pointers,
// and a NaN state named by field. Each check has its control (the other sign, the other status).
#include "displays/display_mapping.hpp"
#include "displays/displays_component.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fedsim::displays {
namespace {

using symbology::FlightDirector;
using symbology_mapping::DisplayContext;
using symbology_mapping::flight_director;
using units::kDegToRad;

msg::NavReceiver localizer(double course_deviation, double gs_deviation, msg::SignalStatus gs = msg::SIGNAL_VALID) {
  msg::NavReceiver r;
  r.frequency_khz(109550);  // ISFO 28R
  r.signal(msg::NAV_SIGNAL_LOCALIZER);
  r.status(msg::SIGNAL_VALID);
  r.ident("ISFO");
  r.course_deviation(course_deviation);
  r.glideslope_status(gs);
  r.glideslope_deviation(gs_deviation);
  return r;
}

msg::AircraftState level_state() {
  msg::AircraftState s;
  s.theta_rad(3.0 * kDegToRad);
  s.phi_rad(-10.0 * kDegToRad);
  s.psi_rad(284.0 * kDegToRad);
  s.altitude_msl_m(400.0);
  s.height_agl_m(390.0);
  s.climb_rate_mps(-3.5);
  s.ground_speed_mps(70.0);
  s.velocity_ned_mps({70.0 * std::cos(284.0 * kDegToRad), 70.0 * std::sin(284.0 * kDegToRad), 3.5});
  s.air().cas_mps(72.0);
  s.air().tas_mps(73.0);
  s.velocity_body_dot_mps2({0.2, 0.0, 0.0});
  return s;
}

TEST(DisplayMapping, DeviationDotsAreTwiceTheFullScaleFractionWithTheSignKept) {
  EXPECT_DOUBLE_EQ(deviation_dots(0.5), 1.0);
  EXPECT_DOUBLE_EQ(deviation_dots(-0.25), -0.5);
  EXPECT_DOUBLE_EQ(deviation_dots(2.0), 2.5);  // pegged at the scale's end
  EXPECT_DOUBLE_EQ(deviation_dots(std::nan("")), 0.0);
}

TEST(DisplayMapping, LocalizerFrequenciesAreTheOddTenths) {
  EXPECT_TRUE(is_localizer_frequency(109550));
  EXPECT_TRUE(is_localizer_frequency(108100));
  EXPECT_FALSE(is_localizer_frequency(108200));  // even tenth: a VOR channel
  EXPECT_FALSE(is_localizer_frequency(115800));
  EXPECT_FALSE(is_localizer_frequency(0));
}

TEST(DisplayMapping, PfdGetsTheLocalizerAndGlideSlopeInDots) {
  msg::NavigationState nav;
  nav.nav()[0] = localizer(0.25, -0.5);
  const PfdInputs in = pfd_inputs(level_state(), &nav, nullptr, {});
  EXPECT_EQ(in.localizer, NavSignal::kValid);
  EXPECT_DOUBLE_EQ(in.localizer_deviation_dots, 0.5);   // + fly right stays right
  EXPECT_EQ(in.glideslope, NavSignal::kValid);
  EXPECT_DOUBLE_EQ(in.glideslope_deviation_dots, -1.0);  // fly down: below centre
  // Control: the other side.
  nav.nav()[0] = localizer(-0.25, 0.5);
  const PfdInputs other = pfd_inputs(level_state(), &nav, nullptr, {});
  EXPECT_DOUBLE_EQ(other.localizer_deviation_dots, -0.5);
  EXPECT_DOUBLE_EQ(other.glideslope_deviation_dots, 1.0);
  validate(in, "test");
}

TEST(DisplayMapping, AnUnusableSignalIsAFlagNeverAPointer) {
  msg::NavigationState nav;
  nav.nav()[0] = localizer(0.25, -0.5, msg::SIGNAL_BELOW_RADIO_HORIZON);
  PfdInputs in = pfd_inputs(level_state(), &nav, nullptr, {});
  EXPECT_EQ(in.localizer, NavSignal::kValid);
  EXPECT_EQ(in.glideslope, NavSignal::kFailed);
  EXPECT_DOUBLE_EQ(in.glideslope_deviation_dots, 0.0);
  // A localizer channel tuned, nothing usable received (the receiver failed): LOC and G/S flags.
  msg::NavReceiver failed;
  failed.frequency_khz(109550);
  failed.signal(msg::NAV_SIGNAL_NONE);
  failed.status(msg::SIGNAL_RECEIVER_FAILED);
  EXPECT_EQ(localizer_signal(failed), NavSignal::kFailed);
  EXPECT_EQ(glideslope_signal(failed), NavSignal::kFailed);
  // Nothing on that channel: neither scale nor flag; a VOR tuned: no localizer either.
  failed.status(msg::SIGNAL_NO_STATION);
  EXPECT_EQ(localizer_signal(failed), NavSignal::kNotTuned);
  msg::NavReceiver vor;
  vor.frequency_khz(115800);
  vor.signal(msg::NAV_SIGNAL_VOR);
  vor.status(msg::SIGNAL_VALID);
  EXPECT_EQ(localizer_signal(vor), NavSignal::kNotTuned);
  EXPECT_EQ(course_signal(vor), NavSignal::kValid);
  vor.status(msg::SIGNAL_CONE_OF_CONFUSION);
  EXPECT_EQ(course_signal(vor), NavSignal::kFailed);
  // No navigation state yet: nothing tuned.
  in = pfd_inputs(level_state(), nullptr, nullptr, {});
  EXPECT_EQ(in.localizer, NavSignal::kNotTuned);
  EXPECT_FALSE(in.flight_director.on);
}

TEST(DisplayMapping, AttitudeSpeedsTrendsAndMagneticHeading) {
  DisplayContext context;
  context.magnetic_variation_rad = 13.0 * kDegToRad;  // east: magnetic = true - 13
  const PfdInputs in = pfd_inputs(level_state(), nullptr, nullptr, context);
  EXPECT_DOUBLE_EQ(in.pitch_rad, 3.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(in.roll_rad, -10.0 * kDegToRad);
  EXPECT_NEAR(in.heading_magnetic_rad, 271.0 * kDegToRad, 1e-12);
  EXPECT_NEAR(in.heading_true_rad, 284.0 * kDegToRad, 1e-12);
  EXPECT_DOUBLE_EQ(in.ias_mps, 72.0);
  EXPECT_NEAR(in.ias_trend_mps, 10.0 * 0.2 * 72.0 / 73.0, 1e-12);
  EXPECT_DOUBLE_EQ(in.vertical_speed_mps, -3.5);
  EXPECT_DOUBLE_EQ(in.altitude_trend_m, -21.0);
  EXPECT_DOUBLE_EQ(*in.radio_altitude_m, 390.0);
  // Wrapped into 0..360: a true heading of 5 deg with 13 deg east is 352 magnetic.
  msg::AircraftState north = level_state();
  north.psi_rad(5.0 * kDegToRad);
  EXPECT_NEAR(pfd_inputs(north, nullptr, nullptr, context).heading_magnetic_rad, 352.0 * kDegToRad, 1e-12);
}

TEST(DisplayMapping, FlightDirectorFromTheAutopilotElseTheNavigationComputer) {
  msg::AutopilotState ap;
  ap.fma().flight_director_on(true);
  ap.fd_pitch_valid(true);
  ap.fd_pitch_rad(0.05);
  ap.fd_roll_valid(false);
  ap.fd_roll_rad(std::nan(""));
  FlightDirector fd = flight_director(nullptr, &ap);
  EXPECT_TRUE(fd.on);
  EXPECT_TRUE(fd.pitch_valid);
  EXPECT_DOUBLE_EQ(fd.pitch_command_rad, 0.05);
  EXPECT_FALSE(fd.roll_valid);
  EXPECT_DOUBLE_EQ(fd.roll_command_rad, 0.0);  // a NaN never reaches the bars
  // The autopilot's FD off, the navigation federate's FD in a mode: its bars.
  ap.fma().flight_director_on(false);
  msg::NavigationState nav;
  nav.fd().lateral_mode(msg::FD_LATERAL_NAV);
  nav.fd().roll_valid(true);
  nav.fd().roll_command_rad(-0.2);
  fd = flight_director(&nav, &ap);
  EXPECT_TRUE(fd.on);
  EXPECT_TRUE(fd.roll_valid);
  EXPECT_DOUBLE_EQ(fd.roll_command_rad, -0.2);
  // Neither: off.
  nav.fd().lateral_mode(msg::FD_LATERAL_OFF);
  EXPECT_FALSE(flight_director(&nav, &ap).on);
}

TEST(DisplayMapping, FmaWordsAreTheBoeingAbbreviations) {
  msg::FlightModeAnnunciator fma;
  fma.thrust(msg::FMA_THRUST_SPEED);
  fma.roll(msg::FMA_ROLL_LOCALIZER);
  fma.pitch(msg::FMA_PITCH_ALTITUDE_HOLD);
  fma.pitch_armed_glide_slope(true);
  fma.autopilot_engaged(true);
  const FlightModes m = flight_modes(fma);
  EXPECT_EQ(m.autothrottle_active, "MCP SPD");
  EXPECT_EQ(m.roll_active, "VOR/LOC");
  EXPECT_EQ(m.pitch_active, "ALT HOLD");
  EXPECT_EQ(m.pitch_armed, "G/S");
  EXPECT_EQ(m.afds_status, "CMD");
  EXPECT_EQ(flight_modes(msg::FlightModeAnnunciator{}).roll_active, "");
  PfdInputs in;
  in.modes = m;
  validate(in, "test");  // every word fits the FMA's columns
}

TEST(DisplayMapping, NdCourseBearingPointersAndTrack) {
  msg::NavigationState nav;
  nav.nav()[0] = localizer(0.5, 0.0);
  nav.nav()[0].course_true_rad(297.0 * kDegToRad);
  nav.nav()[0].dme_status(msg::SIGNAL_VALID);
  nav.nav()[0].dme_slant_range_m(9000.0);
  msg::NavReceiver& vor = nav.nav()[1];
  vor.frequency_khz(115800);
  vor.signal(msg::NAV_SIGNAL_VOR);
  vor.status(msg::SIGNAL_VALID);
  vor.ident("SFO");
  vor.bearing_to_station_true_rad(314.0 * kDegToRad);  // 30 deg right of the nose (284)
  nav.adf().status(msg::SIGNAL_NOT_TUNED);
  DisplayContext context;
  context.magnetic_variation_rad = 13.0 * kDegToRad;
  const NdInputs in = nd_inputs(level_state(), &nav, context, {}, 20.0);
  EXPECT_EQ(in.course, NavSignal::kValid);
  EXPECT_TRUE(in.course_is_localizer);
  EXPECT_NEAR(in.selected_course_rad, 284.0 * kDegToRad, 1e-12);  // the front course, magnetic
  EXPECT_DOUBLE_EQ(in.course_deviation_dots, 1.0);
  EXPECT_TRUE(in.dme_valid);
  EXPECT_DOUBLE_EQ(in.dme_distance_m, 9000.0);
  EXPECT_TRUE(in.bearing1.valid);
  EXPECT_NEAR(in.bearing1.relative_bearing_rad, 30.0 * kDegToRad, 1e-12);
  EXPECT_EQ(in.bearing1.ident, "SFO");
  EXPECT_FALSE(in.bearing2.valid);  // the ADF has nothing: the pointer is removed
  EXPECT_NEAR(in.track_rad, 271.0 * kDegToRad, 1e-9);
  validate(in, "test");
}

TEST(DisplayMapping, ABadStateIsNamedByItsField) {
  msg::AircraftState s = level_state();
  EXPECT_EQ(aircraft_state_problem(s), "");
  s.theta_rad(std::nan(""));
  EXPECT_EQ(aircraft_state_problem(s), "field 'theta_rad': not a finite number");
  s = level_state();
  s.air().cas_mps(900.0);
  EXPECT_NE(aircraft_state_problem(s).find("field 'air.cas_mps': 900"), std::string::npos);
}

TEST(DisplayMapping, NearbyNavaidsFromTheDatabase) {
  const nav::NavDatabase db = nav::NavDatabase::open(nav::default_database_path());
  // Over the bay 5 NM east of SFO VOR (37.6195 N, 122.3738 W): SFO to the west, at 5 NM.
  const double lat = 37.6195 * kDegToRad, lon = -122.2690 * kDegToRad;
  const NearbyNavaids near = nearby_navaids(db, lat, lon, 20.0);
  const auto sfo = std::find_if(near.navaids.begin(), near.navaids.end(), [](const Navaid& n) { return n.ident == "SFO"; });
  ASSERT_NE(sfo, near.navaids.end());
  EXPECT_EQ(sfo->kind, NavaidKind::kVorDme);
  EXPECT_NEAR(sfo->distance_m, 5.0 * 1852.0, 0.3 * 1852.0);
  const double bearing_true = sfo->bearing_rad + near.magnetic_variation_rad;
  EXPECT_NEAR(std::remainder(bearing_true - 270.0 * kDegToRad, 2.0 * units::kPi), 0.0, 3.0 * kDegToRad);
  EXPECT_GT(near.magnetic_variation_rad, 10.0 * kDegToRad);  // east, 13-17 deg at SFO
  for (const Navaid& n : near.navaids) EXPECT_LE(n.distance_m, 20.0 * 1852.0);
  // Control: mid-Pacific, nothing within 20 NM.
  EXPECT_TRUE(nearby_navaids(db, 30.0 * kDegToRad, -140.0 * kDegToRad, 20.0).navaids.empty());
}

}  // namespace
}  // namespace fedsim::displays
