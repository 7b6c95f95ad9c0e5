// Every topic type survives CDR serialisation through its generated type support.
#include "common/runtime/topic_types.hpp"

#include <fastrtps/rtps/common/SerializedPayload.h>
#include <gtest/gtest.h>

namespace fedsim::runtime {
namespace {

template <class T>
T round_trip(const T& in) {
  typename TopicType<T>::PubSubType type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(const_cast<T*>(&in))());
  EXPECT_TRUE(type.serialize(const_cast<T*>(&in), &payload));
  T out;
  EXPECT_TRUE(type.deserialize(&payload, &out));
  return out;
}

TEST(IdlRoundTrip, FrameTickAndDone) {
  msg::FrameTick tick;
  tick.frame(123456789012ull);
  tick.sim_frame(42);
  tick.sim_time_s(0.84);
  tick.dt_s(0.02);
  tick.run_state(msg::RUN_STATE_RESET);
  tick.reset_count(3);
  tick.mode(msg::TIMING_MODE_LOCKSTEP);
  EXPECT_EQ(round_trip(tick), tick);
  msg::FrameDone done;
  done.federate("flight");
  done.frame(99);
  done.compute_time_us(12.5f);
  EXPECT_EQ(round_trip(done), done);
}

TEST(IdlRoundTrip, CommandWithNestedStructs) {
  msg::SimCommand cmd;
  cmd.kind(msg::COMMAND_REPOSITION);
  cmd.target("ownship");
  cmd.sequence_number(7);
  cmd.reposition().kind(msg::REPOSITION_APPROACH_GATE);
  cmd.reposition().airport("KSFO");
  cmd.reposition().runway("28L");
  cmd.reposition().gate_distance_m(9260.0);
  cmd.weather().wind_speed_mps(12.0);
  cmd.failure().active(true);
  EXPECT_EQ(round_trip(cmd), cmd);
}

TEST(IdlRoundTrip, ControlsAndAircraftState) {
  msg::PilotControls c;
  c.aircraft_id(2);
  c.stamp().frame(5);
  c.elevator(-0.25f);
  c.throttle()[3] = 0.75f;
  c.gear_down(true);
  c.radios().nav1_khz(110300);
  EXPECT_EQ(round_trip(c), c);
  msg::AircraftState s;
  s.latitude_rad(0.6588);
  s.position_ecef_m()[2] = 4.1e6;
  s.q_ned_from_body()[0] = 1.0;
  s.air().mach(0.78);
  s.gear()[7].normal_force_n(1000.0f);
  s.gear_count(3);
  EXPECT_EQ(round_trip(s), s);
  msg::EngineState e;
  e.engine_index(1);
  e.n1_pct(88.0);
  EXPECT_EQ(round_trip(e), e);
}

TEST(IdlRoundTrip, NavigationMotionLoadingStatusVisual) {
  msg::NavigationState n;
  n.nav()[1].ident("SFO");
  n.nav()[1].dme_slant_range_m(18520.0);
  n.nav()[1].to_from(msg::TO_FROM_FROM);
  n.gps().hdop(1.3);
  n.fd().roll_command_rad(0.3);
  EXPECT_EQ(round_trip(n), n);
  msg::MotionPlatformState m;
  m.status(msg::MOTION_ENGAGED);
  m.jack_length_m()[5] = 1.2;
  EXPECT_EQ(round_trip(m), m);
  msg::ControlLoadingState l;
  l.pitch().force_n(55.0);
  l.stick_shaker(true);
  EXPECT_EQ(round_trip(l), l);
  msg::FederateStatus st;
  st.federate("nav");
  st.state(msg::FEDERATE_LOST);
  st.message("lost: liveliness");
  EXPECT_EQ(round_trip(st), st);
  msg::VisualChannelStatus v;
  v.channel_id(2);
  v.name("right");
  v.fov_h_rad(0.9f);
  EXPECT_EQ(round_trip(v), v);
}

}  // namespace
}  // namespace fedsim::runtime
