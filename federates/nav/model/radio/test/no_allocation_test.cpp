// The per-frame calls allocate nothing once the stations are loaded (the counting operator new
// of fedsim_allocation_counter): a NAV, ADF and marker receive and a flight-director command.
#include "common/radio/in_memory_station_source.hpp"
#include "common/radio/nav_radio.hpp"
#include "common/util/allocation_counter.hpp"
#include "nav/model/radio/adf_radio.hpp"
#include "nav/model/radio/flight_director.hpp"
#include "nav/model/radio/marker_receiver.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

namespace fedsim::nav::test {

using namespace fedsim::radio::test;  // the station records and poses (common/radio/test)
namespace {

TEST(NoAllocation, PerFrameCalls) {
  radio::InMemoryStationSource source;
  source.add(sfo_vor_dme());
  source.add(brijj_ndb());
  source.add(ksfo_28r());
  radio::StationOutages outages;
  outages.set_off_air("XYZ");
  const radio::NavRadio nav(source, outages);
  const AdfRadio adf(source, outages);
  const MarkerReceiver markers;
  const FlightDirector fd;
  const IlsApproach ils = ksfo_28r();
  const radio::AircraftPose pose =
      at_elevation_from_glide_slope(ils, from_localizer(ils, 8 * kNm, 0.5), 3 * kDeg);
  radio::NavReading vor;
  radio::NavReading loc;
  AdfReading ndb;
  MarkerReading marker;
  FlightDirectorCommand command;
  const util::AllocationScope scope;
  for (int frame = 0; frame < 10; ++frame) {
    vor = nav.receive({115800, 0.0}, pose);
    loc = nav.receive({109550, 0.0}, pose);
    ndb = adf.receive(379, pose);
    marker = markers.read({&ils, 1}, pose, outages);
    FlightDirectorInputs in;
    in.pose = pose;
    in.lateral_mode = LateralMode::kNavTrack;
    in.vertical_mode = VerticalMode::kGlideSlopeTrack;
    set_nav_source(loc, in);
    command = fd.command(in);
  }
  EXPECT_EQ(scope.allocations(), 0u);
  EXPECT_TRUE(vor.valid());
  EXPECT_TRUE(loc.valid());
  EXPECT_TRUE(loc.glide_slope.valid());
  EXPECT_TRUE(ndb.valid());
  EXPECT_TRUE(command.roll_valid && command.pitch_valid);
}

}  // namespace
}  // namespace fedsim::nav::test
