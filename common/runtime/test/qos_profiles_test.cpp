// The QoS profiles file loads, every named profile creates its endpoint, and the profiles
// behave as qos/README.md says (late joiners get the last command).
#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"

#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

namespace fedsim::runtime {
namespace {

/// A test topic of type T (not in the catalogue) on which to try a profile.
template <class T>
Topic<T> test_topic(const std::string& name) {
  typename TopicType<T>::PubSubType support;
  return Topic<T>{TopicInfo{name, support.getName(), "state", false, "qos test"}};
}

ParticipantOptions options_on(int domain, const std::string& name) {
  ParticipantOptions o;
  o.name = name;
  o.domain_id = domain;
  o.qos_file = default_qos_file();
  return o;
}

TEST(QosProfiles, EveryProfileCreatesWriterAndReader) {
  auto dds = DdsParticipant::create(options_on(120, "qos-test"));
  for (const std::string_view profile : qos::all()) {
    SCOPED_TRACE(profile);
    const auto topic = test_topic<msg::FederateStatus>("qos_test/" + std::string(profile));
    EXPECT_NO_THROW(Publisher<msg::FederateStatus>(dds, topic, profile));
    EXPECT_NO_THROW(Subscription<msg::FederateStatus>(dds, topic, profile));
    const std::string reliable = std::string(profile) + std::string(qos::kReliableSuffix);
    if (profile == qos::kTick || profile == qos::kFrameDone) {
      EXPECT_NO_THROW(Publisher<msg::FederateStatus>(dds, topic, reliable));
      EXPECT_NO_THROW(Subscription<msg::FederateStatus>(dds, topic, reliable));
    }
  }
  EXPECT_EQ(qos::all().size(), 8u);
}

TEST(TopicCatalogue, EveryTopicHasItsIdlNameTypeAndAKnownProfile) {
  ASSERT_EQ(topics::all().size(), 15u);
  for (const TopicInfo* t : topics::all()) {
    SCOPED_TRACE(t->name);
    EXPECT_EQ(t->name.rfind("fedsim/", 0), 0u);
    EXPECT_EQ(t->type_name.rfind("fedsim::msg::", 0), 0u);
    EXPECT_NE(std::find(qos::all().begin(), qos::all().end(), t->default_qos), qos::all().end());
    EXPECT_EQ(topics::find(t->name), t);
    // The typed lookup (recorders, the in-process host) knows every topic by name.
    std::string visited_type;
    EXPECT_TRUE(topics::visit(t->name, [&](const auto& topic) { visited_type = topic.info.type_name; }));
    EXPECT_EQ(visited_type, t->type_name);
  }
  EXPECT_FALSE(topics::visit("fedsim/no_such_topic", [](const auto&) {}));
  EXPECT_EQ(topics::aircraft_state.name(), msg::TOPIC_AIRCRAFT_STATE);
  EXPECT_EQ(topics::aircraft_state.info.type_name, "fedsim::msg::AircraftState");
  EXPECT_TRUE(topics::pilot_controls.info.lockstep_input);
  EXPECT_FALSE(topics::sim_command.info.lockstep_input);
  EXPECT_EQ(topics::find("fedsim/no_such_topic"), nullptr);
  EXPECT_TRUE(topics::is_backbone(msg::TOPIC_FRAME_TICK));
  EXPECT_FALSE(topics::is_backbone(msg::TOPIC_AIRCRAFT_STATE));
}

TEST(QosProfiles, ProfilesCarryTheDocumentedPolicies) {
  auto dds = DdsParticipant::create(options_on(120, "qos-test"));
  Publisher<msg::AircraftState> state(dds, test_topic<msg::AircraftState>("qos_test/state"),
                                      qos::kState);
  Publisher<msg::SimCommand> command(dds, test_topic<msg::SimCommand>("qos_test/command"),
                                     qos::kCommand);
  Publisher<msg::FrameDone> done(dds, test_topic<msg::FrameDone>("qos_test/done"), qos::kFrameDone);
  using namespace eprosima::fastdds::dds;
  EXPECT_EQ(state.writer()->get_qos().reliability().kind, BEST_EFFORT_RELIABILITY_QOS);
  EXPECT_EQ(state.writer()->get_qos().history().depth, 1);
  // No DDS deadline on state (a timer re-armed per sample); silence is counted in frames.
  EXPECT_EQ(state.writer()->get_qos().deadline().period, eprosima::fastrtps::c_TimeInfinite);
  EXPECT_EQ(command.writer()->get_qos().reliability().kind, RELIABLE_RELIABILITY_QOS);
  EXPECT_EQ(command.writer()->get_qos().durability().kind, TRANSIENT_LOCAL_DURABILITY_QOS);
  EXPECT_EQ(done.writer()->get_qos().liveliness().kind, AUTOMATIC_LIVELINESS_QOS);
  // Pilot controls: one owner per aircraft (exclusive ownership; fedsim-io's strength is 10).
  Publisher<msg::PilotControls> controls(dds, test_topic<msg::PilotControls>("qos_test/controls"),
                                         qos::kPilotControls);
  Subscription<msg::PilotControls> controls_reader(dds, test_topic<msg::PilotControls>("qos_test/controls"),
                                                   qos::kPilotControls);
  EXPECT_EQ(controls.writer()->get_qos().ownership().kind, EXCLUSIVE_OWNERSHIP_QOS);
  EXPECT_EQ(controls.writer()->get_qos().ownership_strength().value, 10u);
  EXPECT_EQ(controls.writer()->get_qos().reliability().kind, RELIABLE_RELIABILITY_QOS);
  EXPECT_EQ(controls.writer()->get_qos().durability().kind, TRANSIENT_LOCAL_DURABILITY_QOS);
  EXPECT_EQ(controls.writer()->get_qos().history().depth, 2);
  EXPECT_EQ(state.writer()->get_qos().ownership().kind, SHARED_OWNERSHIP_QOS);  // negative control
}

// A best-effort writer and a reliable reader never match: both runtime endpoints see the
// incompatible remote (each logs it with topic and policy: qos_mismatch.hpp) and count it. A
// compatible pair counts nothing (negative control).
TEST(QosProfiles, AnIncompatibleRemoteIsCountedOnBothSides) {
  auto dds = DdsParticipant::create(options_on(229, "qos-mismatch-test"));
  const auto topic = test_topic<msg::FederateStatus>("qos_test/mismatch");
  Publisher<msg::FederateStatus> best_effort(dds, topic, qos::kState);
  Subscription<msg::FederateStatus> reliable(dds, topic, qos::kCommand);
  Subscription<msg::FederateStatus> matching(dds, topic, qos::kState);
  for (int i = 0; i < 250 && (best_effort.incompatible_readers() == 0 || reliable.incompatible_writers() == 0 ||
                              matching.matched_writers() == 0);
       ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(best_effort.incompatible_readers(), 1u);
  EXPECT_EQ(reliable.incompatible_writers(), 1u);
  EXPECT_EQ(matching.matched_writers(), 1);
  EXPECT_EQ(matching.incompatible_writers(), 0u);
  EXPECT_STREQ(qos_policy_name(eprosima::fastdds::dds::RELIABILITY_QOS_POLICY_ID), "RELIABILITY");
}

TEST(QosProfiles, UnknownProfileAndMissingFileGiveClearErrors) {
  auto o = options_on(120, "qos-test");
  o.participant_profile = "no_such_profile";
  try {
    DdsParticipant::create(o);
    FAIL();
  } catch (const DdsError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_profile"), std::string::npos);
  }
  o = options_on(120, "qos-test");
  o.qos_file = "/nonexistent/qos.xml";
  EXPECT_THROW(DdsParticipant::create(o), DdsError);
  auto dds = DdsParticipant::create(options_on(120, "qos-test"));
  EXPECT_THROW(Publisher<msg::FrameDone>(dds, test_topic<msg::FrameDone>("qos_test/x"),
                                         "no_such_writer_profile"),
               DdsError);
}

TEST(QosProfiles, LateJoinerReceivesTheLastCommandOfEachKind) {
  auto writer_side = DdsParticipant::create(options_on(121, "commander"));
  Publisher<msg::SimCommand> commands(writer_side, runtime::topics::sim_command, runtime::qos::kCommand);
  msg::SimCommand cmd;
  cmd.kind(msg::COMMAND_RUN_STATE);
  for (std::uint32_t seq = 1; seq <= 3; ++seq) {
    cmd.sequence_number(seq);
    cmd.run_state(seq == 3 ? msg::RUN_STATE_FREEZE : msg::RUN_STATE_RUN);
    commands.publish(cmd);
  }
  msg::SimCommand weather;
  weather.kind(msg::COMMAND_WEATHER);
  weather.sequence_number(4);
  weather.weather().wind_speed_mps(15.0);
  commands.publish(weather);

  // A participant that joins afterwards.
  auto late = DdsParticipant::create(options_on(121, "late-joiner"));
  std::mutex m;
  std::vector<msg::SimCommand> received;
  Subscription<msg::SimCommand> sub(late, runtime::topics::sim_command, runtime::qos::kCommand,
                                    [&](const msg::SimCommand& c, const auto&) {
                                      std::lock_guard lock(m);
                                      received.push_back(c);
                                    });
  for (int i = 0; i < 200; ++i) {
    {
      std::lock_guard lock(m);
      if (received.size() >= 2) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  std::lock_guard lock(m);
  ASSERT_EQ(received.size(), 2u);
  bool saw_run_state = false, saw_weather = false;
  for (const auto& c : received) {
    if (c.kind() == msg::COMMAND_RUN_STATE) {
      saw_run_state = true;
      EXPECT_EQ(c.sequence_number(), 3u);  // only the latest of that kind
      EXPECT_EQ(c.run_state(), msg::RUN_STATE_FREEZE);
    }
    if (c.kind() == msg::COMMAND_WEATHER) {
      saw_weather = true;
      EXPECT_DOUBLE_EQ(c.weather().wind_speed_mps(), 15.0);
    }
  }
  EXPECT_TRUE(saw_run_state && saw_weather);
}

}  // namespace
}  // namespace fedsim::runtime
