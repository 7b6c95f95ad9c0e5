// The approach progress line of `fedsim run` (approach_progress.hpp): the phase from the modes
// and the state, the distance to the threshold measured on the real runway.
#include "flight/model/afcs/approach_progress.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::flight::afcs {
namespace {

const RunwayCentreline& ksfo_28r() {
  static const RunwayCentreline runway = RunwayCentreline::from_table(RunwayTable::load_default(), "KSFO", "28R");
  return runway;
}

// KSFO 28R threshold (data/nav/runways.csv) and a point `nm` before it along the approach course
// (landing heading 298 deg true; a flat-earth offset is plenty for a progress line).
ApproachAircraft before_threshold(double nm) {
  const double lat0 = 37.613538 * units::kDegToRad, lon0 = -122.35716 * units::kDegToRad;
  const double heading = 298.0 * units::kDegToRad;
  const double back_m = nm * units::kNmToM;
  ApproachAircraft a;
  a.lat_rad = lat0 - back_m * std::cos(heading) / 6378137.0;
  a.lon_rad = lon0 - back_m * std::sin(heading) / (6378137.0 * std::cos(lat0));
  a.height_agl_m = 1000.0 * units::kFtToM;
  a.cas_mps = 145.0 * units::kKtToMps;
  a.ground_speed_mps = a.cas_mps;
  return a;
}

ModeState on_glide_slope() {
  ModeState m;
  m.autopilot_engaged = m.autothrottle_engaged = m.flight_director_on = true;
  m.lateral = LateralMode::kLocalizer;
  m.vertical = VerticalMode::kGlideSlope;
  m.thrust = ThrustMode::kSpeed;
  m.vertical_armed.flare = true;
  return m;
}

TEST(ApproachProgress, PhaseFollowsTheModesAndTheGround) {
  ModeState m = on_glide_slope();
  ApproachAircraft a = before_threshold(3.0);
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kGlideSlope);
  m.vertical = VerticalMode::kAltitudeHold;
  m.vertical_armed.glide_slope = true;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kLocalizer);
  m.lateral = LateralMode::kHeadingSelect;
  m.lateral_armed.localizer = true;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kIntercept);
  m.vertical = VerticalMode::kFlare;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kFlare);
  a.on_ground = true;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kRollout);
  a.ground_speed_mps = 0.2;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kStopped);
  m.autopilot_engaged = m.flight_director_on = false;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kStopped);  // stopped outranks the disconnect
  a = before_threshold(3.0);
  m.vertical = VerticalMode::kNone;
  m.lateral = LateralMode::kNone;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kManual);
  m.vertical = VerticalMode::kGoAround;
  EXPECT_EQ(approach_phase(m, a), ApproachPhase::kGoAround);
}

TEST(ApproachProgress, LineGivesDistanceHeightSpeedAndModes) {
  const std::string line = approach_progress_line(on_glide_slope(), before_threshold(3.2), &ksfo_28r());
  const std::string head = "glide slope: ";
  ASSERT_EQ(line.substr(0, head.size()), head) << line;
  // The runway's own centreline (threshold to 10L) against this test's flat-earth point on a
  // 298 deg course: a tenth of a mile apart at most.
  EXPECT_NEAR(std::stod(line.substr(head.size())), 3.2, 0.11) << line;
  EXPECT_NE(line.find(" NM to the threshold, 1000 ft, 145 KCAS | MCP SPD | VOR/LOC | G/S +flare | CMD"),
            std::string::npos) << line;
  EXPECT_LE(line.size(), 127u);  // FederateStatus.message's bound
  // Negative control: another position gives another distance.
  EXPECT_NE(approach_progress_line(on_glide_slope(), before_threshold(5.0), &ksfo_28r()), line);
  // Without a runway the distance is left out.
  EXPECT_EQ(approach_progress_line(on_glide_slope(), before_threshold(3.2), nullptr).find("NM"), std::string::npos);
}

TEST(ApproachProgress, OnTheRunwayTheDistanceIsBeyondTheThreshold) {
  ModeState m = on_glide_slope();
  m.lateral = LateralMode::kRollout;
  m.vertical = VerticalMode::kRollout;
  m.thrust = ThrustMode::kNone;
  m.vertical_armed.flare = false;
  ApproachAircraft a = before_threshold(-0.5);  // 926 m beyond it
  a.on_ground = true;
  a.ground_speed_mps = 60.0 * units::kKtToMps;
  const std::string line = approach_progress_line(m, a, &ksfo_28r());
  const std::string head = "rollout: ";
  ASSERT_EQ(line.substr(0, head.size()), head) << line;
  EXPECT_NEAR(std::stod(line.substr(head.size())), 926.0, 120.0) << line;
  EXPECT_NE(line.find("m beyond the threshold, 60 kt over the ground | - | ROLLOUT | ROLLOUT | CMD"), std::string::npos) << line;
}

}  // namespace
}  // namespace fedsim::flight::afcs
