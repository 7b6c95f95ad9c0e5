// Pilot controls from outside, over DDS on 127.0.0.1 (issue 11 item 5): fedsim-timing (realtime,
// 50 Hz) and fedsim-flight run as processes; this test plays outside writers of
// fedsim/pilot_controls, each writing one sample per frame tick stamped with the tick's frame
// (as docs/interop.md asks of a trainer), and reads back fedsim/applied_controls and
// fedsim/aircraft_state. Each test has its own DDS domain.
#include "common/runtime/federate_options.hpp"
#include "common/util/build_paths.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"
#include "common/runtime/topic_catalogue.hpp"
#include "common/util/child_process.hpp"
#include "common/util/wait_until.hpp"

#include <fastdds/dds/publisher/Publisher.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <thread>

namespace fedsim::flight {
namespace {

using util::ChildProcess;

std::string bin(const std::string& name) { return fedsim::util::bin_dir() + "/" + name; }

struct Federation {
  Federation(int domain, const std::string& tag, double duration_s) : dir(util::temp_dir(tag)) {
    auto common = [&](const std::string& name) {
      return std::vector<std::string>{"--name", name, "--domain", std::to_string(domain), "--qos-file",
                                      runtime::default_qos_file()};
    };
    auto args = common("flight");
    args.insert(args.begin(), bin("fedsim-flight"));
    for (const char* a : {"--aircraft", "c172", "--trim", "level", "--ktas", "100"}) args.push_back(a);
    flight = std::make_unique<ChildProcess>(args, dir + "/flight.log");
    args = common("timing");
    args.insert(args.begin(), bin("fedsim-timing"));
    for (const std::string& a : std::vector<std::string>{"--mode", "realtime", "--rate", "50", "--expect", "flight",
                                                         "--duration", std::to_string(duration_s),
                                                         "--shutdown-on-exit"}) {
      args.push_back(a);
    }
    timing = std::make_unique<ChildProcess>(args, dir + "/timing.log");
  }
  /// Waits for both to stop; the flight's log.
  std::string finish() {
    EXPECT_TRUE(timing->wait(60)) << timing->output();
    EXPECT_TRUE(flight->wait(20)) << flight->output();
    return flight->output();
  }
  std::string dir;
  std::unique_ptr<ChildProcess> flight, timing;
};

std::shared_ptr<runtime::DdsParticipant> participant(int domain, const std::string& name) {
  runtime::ParticipantOptions o;
  o.name = name;
  o.domain_id = domain;
  o.qos_file = runtime::default_qos_file();
  return runtime::DdsParticipant::create(o);
}

/// A raw writer of fedsim/pilot_controls from the catalogue profile with another ownership
/// strength (an outside trainer that must win over fedsim-io's 10).
runtime::fdds::DataWriter* writer_with_strength(runtime::DdsParticipant& dds, std::uint32_t strength) {
  runtime::fdds::DataWriterQos qos;
  dds.publisher()->get_datawriter_qos_from_profile(std::string(runtime::qos::kPilotControls), qos);
  qos.ownership_strength().value = strength;
  auto* topic = dds.topic<msg::PilotControls>(runtime::topics::pilot_controls.name());
  return dds.publisher()->create_datawriter(topic, qos);
}

msg::PilotControls controls(std::uint64_t frame, float aileron, float throttle = 0.5f) {
  msg::PilotControls s;
  s.stamp().frame(frame);
  s.aileron(aileron);
  for (auto& m : s.mixture()) m = 1.0f;
  for (auto& p : s.propeller()) p = 1.0f;
  s.throttle()[0] = throttle;
  return s;
}

/// What the flight federate reports it flew, by its frame.
struct Flown {
  explicit Flown(std::shared_ptr<runtime::DdsParticipant> dds)
      : applied(dds, runtime::topics::applied_controls, std::string_view{},
                [this](const msg::PilotControls& s, const auto&) {
                  std::lock_guard lock(mutex);
                  by_frame[s.stamp().frame()] = s;
                }),
        state(dds, runtime::topics::aircraft_state, std::string_view{}, [this](const msg::AircraftState& s, const auto&) {
          std::lock_guard lock(mutex);
          state_throttle[s.stamp().frame()] = s.controls().throttle()[0];
        }) {}
  std::map<std::uint64_t, msg::PilotControls> frames() {
    std::lock_guard lock(mutex);
    return by_frame;
  }
  std::mutex mutex;
  std::map<std::uint64_t, msg::PilotControls> by_frame;
  std::map<std::uint64_t, double> state_throttle;
  runtime::Subscription<msg::PilotControls> applied;
  runtime::Subscription<msg::AircraftState> state;
};

/// Calls `on_tick(frame)` for every frame tick (the outside writer's clock).
std::unique_ptr<runtime::Subscription<msg::FrameTick>> on_ticks(std::shared_ptr<runtime::DdsParticipant> dds,
                                                                std::function<void(std::uint64_t)> on_tick) {
  return std::make_unique<runtime::Subscription<msg::FrameTick>>(
      dds, runtime::topics::frame_tick, std::string_view{},
      [on_tick](const msg::FrameTick& t, const auto&) { on_tick(t.frame()); });
}

// Two writers of aircraft 0: fedsim-io's strength (10) and a trainer's (20). The flight
// federate warns of the second writer, and from the trainer's first sample on it flies only the
// trainer's (exclusive ownership), never the two alternately. When the trainer deletes its
// writer, the aircraft goes back to the first writer. Negative control: before the trainer
// appears, the first writer's controls are flown.
TEST(PilotInputDds, ASecondWriterIsWarnedOfAndOnlyTheStrongerOneFlies) {
  const int domain = 225;
  Federation fed(domain, "ctl-owner", 6.0);
  auto dds = participant(domain, "test-writers");
  Flown flown(dds);
  runtime::Publisher<msg::PilotControls> io_like(dds, runtime::topics::pilot_controls);
  std::mutex trainer_mutex;
  runtime::fdds::DataWriter* trainer = nullptr;
  std::atomic<std::uint64_t> last_tick{0};
  auto ticks = on_ticks(dds, [&](std::uint64_t frame) {
    last_tick.store(frame);
    io_like.publish(controls(frame, 0.1f));
    std::lock_guard lock(trainer_mutex);
    if (trainer != nullptr) {
      msg::PilotControls strong = controls(frame, -0.1f);
      trainer->write(&strong);
    }
  });
  auto flew = [&](float aileron, std::uint64_t after) {
    return util::wait_until([&] {
      for (const auto& [f, s] : flown.frames()) if (f > after && s.aileron() == aileron) return true;
      return false;
    }, 30);
  };
  ASSERT_TRUE(flew(0.1f, 0)) << fed.flight->output();
  {
    std::lock_guard lock(trainer_mutex);
    trainer = writer_with_strength(*dds, 20);
    ASSERT_NE(trainer, nullptr);
  }
  ASSERT_TRUE(flew(-0.1f, 0)) << fed.flight->output();
  const std::uint64_t strong_until = last_tick.load() + 100;  // two seconds of both writers
  util::wait_until([&] { return last_tick.load() >= strong_until || !fed.timing->running(); }, 30);
  {
    std::lock_guard lock(trainer_mutex);
    dds->publisher()->delete_datawriter(trainer);
    trainer = nullptr;
  }
  const std::uint64_t deleted_at = last_tick.load();
  EXPECT_TRUE(flew(0.1f, deleted_at)) << "the first writer flies again once the trainer's writer is gone";
  const std::string log = fed.finish();
  ticks->close();

  std::uint64_t first_strong = 0;
  std::size_t weak_between = 0, strong = 0;
  for (const auto& [frame, s] : flown.frames()) {
    if (s.aileron() == -0.1f) {
      if (first_strong == 0) first_strong = frame;
      ++strong;
    } else if (first_strong != 0 && frame <= deleted_at) {
      ++weak_between;
    }
  }
  EXPECT_GT(strong, 50u) << "the stronger writer flies";
  EXPECT_EQ(weak_between, 0u) << "the two writers alternated";
  EXPECT_NE(log.find("controls_second_writer"), std::string::npos) << log;
  EXPECT_EQ(log.find("fault=controls_second_writer"), std::string::npos)
      << "a takeover is a warning, not a fault that fails the run\n" << log;
  EXPECT_NE(log.find("second writer seen 1 times"), std::string::npos) << log;
  EXPECT_NE(log.find("fedsim/pilot_controls has 2 writers"), std::string::npos) << log;
  EXPECT_NE(log.find("fedsim/pilot_controls has one writer again"), std::string::npos) << log;
  EXPECT_EQ(log.find("incompatible"), std::string::npos) << log;  // both offer the right QoS
}

// Per frame, one good sample (aileron 0.1) and, in turn, one for aircraft 7, one with a NaN
// elevator, one with 1e30, one stamped 2^62 (each with aileron 0.7): none of the bad ones is
// flown, each kind is counted and logged, and the good ones are (negative control).
TEST(PilotInputDds, BadSamplesAreRefusedCountedAndNeverFlown) {
  const int domain = 226;
  Federation fed(domain, "ctl-bad", 4.0);
  auto dds = participant(domain, "test-writer");
  Flown flown(dds);
  runtime::Publisher<msg::PilotControls> writer(dds, runtime::topics::pilot_controls);
  auto ticks = on_ticks(dds, [&](std::uint64_t frame) {
    msg::PilotControls bad = controls(frame, 0.7f);
    switch (frame % 4) {
      case 0: bad.aircraft_id(7); break;
      case 1: bad.elevator(std::numeric_limits<float>::quiet_NaN()); break;
      case 2: bad.rudder(1e30f); break;
      default: bad.stamp().frame(std::uint64_t{1} << 62); break;
    }
    writer.publish(bad);
    writer.publish(controls(frame, 0.1f));
  });
  const std::string log = fed.finish();
  ticks->close();
  std::size_t good = 0;
  for (const auto& [frame, s] : flown.frames()) {
    EXPECT_NE(s.aileron(), 0.7f) << "frame " << frame << " flew a refused sample";
    EXPECT_TRUE(std::isfinite(s.elevator())) << "frame " << frame;
    if (s.aileron() == 0.1f) ++good;
  }
  EXPECT_GT(good, 50u) << log;
  for (const char* kind : {"controls_other_aircraft", "controls_not_finite", "controls_out_of_range",
                           "controls_bad_stamp"}) {
    EXPECT_NE(log.find(std::string("fault=") + kind + " count=1:"), std::string::npos) << kind << "\n" << log;
  }
  EXPECT_NE(log.find("pilot_controls for aircraft_id 7 ignored (this is aircraft 0)"), std::string::npos) << log;
  EXPECT_NE(log.find("pilot_controls stamped frame 4611686018427387904 refused"), std::string::npos) << log;

}

// A flood: 20 samples per frame, each with its own throttle. Every frame, fedsim/applied_controls
// is exactly the throttle the model flew (the aircraft state's, computed from the model), and
// each value flown is one the writer sent.
TEST(PilotInputDds, UnderAFloodAppliedControlsAreExactlyWhatTheModelFlew) {
  const int domain = 227;
  Federation fed(domain, "ctl-flood", 4.0);
  auto dds = participant(domain, "test-flood");
  Flown flown(dds);
  runtime::Publisher<msg::PilotControls> writer(dds, runtime::topics::pilot_controls);
  std::mutex sent_mutex;
  std::set<float> sent;
  auto ticks = on_ticks(dds, [&](std::uint64_t frame) {
    for (int i = 0; i < 20; ++i) {
      const float throttle = static_cast<float>((frame % 50) * 20 + i) / 1000.0f;
      {
        std::lock_guard lock(sent_mutex);
        sent.insert(throttle);
      }
      writer.publish(controls(frame, 0.0f, throttle));
    }
  });
  const std::string log = fed.finish();
  ticks->close();
  std::lock_guard lock(flown.mutex);
  std::size_t compared = 0;
  for (const auto& [frame, s] : flown.by_frame) {
    const auto state = flown.state_throttle.find(frame);
    if (state == flown.state_throttle.end()) continue;  // best effort: a state sample not received
    EXPECT_EQ(static_cast<float>(state->second), s.throttle()[0]) << "frame " << frame;
    if (frame > 5) EXPECT_TRUE(sent.count(s.throttle()[0])) << "frame " << frame << " flew " << s.throttle()[0];
    ++compared;
  }
  EXPECT_GT(compared, 100u) << log;
}

// A matched writer that stops writing (it stays matched): the runtime reports it silent by
// topic, the flight federate flies the last good input, held and counted, and the federation
// is not starved: the flight keeps stepping frame after frame at the tick rate.
TEST(PilotInputDds, ASilentWriterIsReportedAndTheLastGoodInputIsHeldWithoutStarving) {
  const int domain = 224;
  Federation fed(domain, "ctl-silent", 4.0);
  auto dds = participant(domain, "test-silent");
  Flown flown(dds);
  runtime::Publisher<msg::PilotControls> writer(dds, runtime::topics::pilot_controls);
  std::atomic<std::uint64_t> last_written{0};
  auto ticks = on_ticks(dds, [&](std::uint64_t frame) {
    if (frame > 50) return;  // silent from frame 51, still matched
    writer.publish(controls(frame, 0.2f));
    last_written.store(frame);
  });
  const std::string log = fed.finish();
  ticks->close();
  const auto frames = flown.frames();
  std::size_t held = 0;
  for (const auto& [frame, s] : frames) {
    if (frame > last_written.load() + 20 && s.aileron() == 0.2f) ++held;
  }
  EXPECT_GT(held, 80u) << "frames after the silence flown with the last good input\n" << log;
  EXPECT_NE(log.find("fault=silent_writer count=1: fedsim/pilot_controls: a matched writer wrote nothing"),
            std::string::npos) << log;
  EXPECT_NE(log.find("flying the last good input, held"), std::string::npos) << log;
  // Frames waited for the silent input only until it was found silent (--silent-frames, 10),
  // not every frame after (each such wait is a "late input").
  std::smatch late;
  ASSERT_TRUE(std::regex_search(log, late, std::regex("stopping .* late_inputs=([0-9]+)"))) << log;
  EXPECT_LE(std::stoi(late[1]), 15) << log;
  EXPECT_GE(std::stoi(late[1]), 5) << log;  // it was waited for at first: the writer was matched
}

// A writer whose QoS does not match the reader's (here SHARED ownership, the lockstep_data
// profile) is logged by the flight federate with the topic and the policy.
TEST(PilotInputDds, AnIncompatibleQosWriterIsLoggedWithTopicAndPolicy) {
  const int domain = 228;
  Federation fed(domain, "ctl-qos", 2.0);
  auto dds = participant(domain, "test-shared");
  runtime::Publisher<msg::PilotControls> shared(dds, runtime::topics::pilot_controls,
                                               runtime::qos::kLockstepData);
  EXPECT_TRUE(util::wait_until([&] { return shared.incompatible_readers() > 0; }, 30));
  const std::string log = fed.finish();
  EXPECT_NE(log.find("topic=fedsim/pilot_controls: a remote writer has QoS incompatible with this "
                     "reader (profile 'pilot_controls'): policy OWNERSHIP"),
            std::string::npos)
      << log;
  EXPECT_GE(shared.incompatible_readers(), 1u);
}

}  // namespace
}  // namespace fedsim::flight
