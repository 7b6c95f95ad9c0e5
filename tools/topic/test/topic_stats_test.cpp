// The pure parts of `fedsim topic bw` and `fedsim topic info`: the sliding window's statistics,
// byte formatting, and the info text (from a hand-made TopicInfo).
#include "tools/topic/raw_type.hpp"
#include "tools/topic/topic_stats.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace fedsim::tools {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

TEST(BandwidthWindow, RatesAndSizesOverTheWindow) {
  BandwidthWindow window(100);
  // 50 samples at 50 Hz, sizes 100 and 300 alternating: 200 B mean.
  for (int i = 0; i < 50; ++i) window.add(i * kSecond / 50, i % 2 ? 300 : 100);
  const auto s = window.stats(kSecond);  // one second after the first sample
  EXPECT_EQ(s.samples, 50u);
  EXPECT_DOUBLE_EQ(s.span_s, 1.0);
  EXPECT_DOUBLE_EQ(s.samples_per_s, 50.0);
  EXPECT_DOUBLE_EQ(s.bytes_per_s, 10000.0);
  EXPECT_DOUBLE_EQ(s.mean_bytes, 200.0);
  EXPECT_EQ(s.min_bytes, 100u);
  EXPECT_EQ(s.max_bytes, 300u);
  EXPECT_EQ(format_bandwidth(s),
            "10.00 KB/s from 50 samples (50.00 samples/s)\n"
            "\tsample size mean: 200.0 B min: 100 B max: 300 B\n");
}

TEST(BandwidthWindow, KeepsOnlyTheLastSamplesAndFallsWhenQuiet) {
  BandwidthWindow window(10);
  for (int i = 0; i < 30; ++i) window.add(i * kSecond / 10, i < 20 ? 1000 : 10);
  auto s = window.stats(3 * kSecond);
  EXPECT_EQ(s.samples, 10u);           // the last 10 only (all 10 B)
  EXPECT_EQ(s.max_bytes, 10u);
  EXPECT_EQ(window.total_samples(), 30u);
  const double rate = window.stats(3 * kSecond).samples_per_s;
  EXPECT_LT(window.stats(10 * kSecond).samples_per_s, rate);  // quiet since 2.9 s
  EXPECT_EQ(BandwidthWindow(5).stats(kSecond).samples, 0u);   // empty: zeros, no division
  EXPECT_EQ(BandwidthWindow(5).stats(kSecond).bytes_per_s, 0.0);
}

TEST(BandwidthFormat, Units) {
  EXPECT_EQ(format_bytes(12), "12 B");
  EXPECT_EQ(format_bytes(1234), "1.23 KB");
  EXPECT_EQ(format_bytes(2.5e6), "2.50 MB");
}

TEST(TopicInfoFormat, ShowsEachEndpointsQosAndLocators) {
  TopicInfo t;
  t.name = "fedsim/pilot_controls";
  t.type_names = {"fedsim::msg::PilotControls"};
  EndpointInfo w;
  w.guid = "01.0f.aa|0.0.1.3";
  w.participant = "io";
  w.type_name = "fedsim::msg::PilotControls";
  w.keyed = true;
  w.reliable = true;
  w.durability = 1;
  w.exclusive_ownership = true;
  w.ownership_strength = 10;
  w.deadline_s = std::numeric_limits<double>::infinity();
  w.liveliness_lease_s = std::numeric_limits<double>::infinity();
  w.lifespan_s = std::numeric_limits<double>::infinity();
  w.unicast_locators = {"UDPv4:[127.0.0.1]:7413"};
  t.writers.push_back(w);
  EndpointInfo r = w;
  r.writer = false;
  r.participant = "flight";
  r.reliable = false;
  r.deadline_s = 0.2;
  r.unicast_locators.clear();
  t.readers.push_back(r);
  const std::string text = format_topic_info(t);
  EXPECT_NE(text.find("topic: fedsim/pilot_controls\ntype: fedsim::msg::PilotControls\nwriters: 1\n"
                      "  - participant: io\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("    reliability: RELIABLE\n    durability: TRANSIENT_LOCAL\n"
                      "    deadline: infinite\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("    ownership: EXCLUSIVE, strength 10\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    unicast locators: UDPv4:[127.0.0.1]:7413\n"), std::string::npos) << text;
  EXPECT_NE(text.find("readers: 1\n  - participant: flight\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    reliability: BEST_EFFORT\n"), std::string::npos) << text;
  EXPECT_NE(text.find("    deadline: 0.2 s\n"), std::string::npos) << text;
}

TEST(TopicInfoFormat, NamesTheWritersAReaderCannotMatchAndWhy) {
  EndpointInfo w;
  w.participant = "io";
  w.type_name = "T";
  w.reliable = true;
  w.durability = 1;
  w.exclusive_ownership = true;
  w.deadline_s = w.liveliness_lease_s = std::numeric_limits<double>::infinity();
  EndpointInfo r = w;
  r.writer = false;
  r.participant = "flight";
  EXPECT_TRUE(qos_incompatibilities(w, r).empty());  // the same QoS matches
  r.exclusive_ownership = false;
  r.deadline_s = 0.2;  // requests a deadline the writer does not offer
  const auto why = qos_incompatibilities(w, r);
  ASSERT_EQ(why.size(), 2u);
  EXPECT_EQ(why[0], "ownership: reader SHARED, writer EXCLUSIVE");
  EXPECT_EQ(why[1], "deadline: reader requests 0.2 s, writer offers infinite");
  EndpointInfo best_effort_writer = w;
  best_effort_writer.reliable = false;
  best_effort_writer.durability = 0;
  EXPECT_EQ(qos_incompatibilities(best_effort_writer, w).size(), 2u);  // reliability, durability
  EXPECT_TRUE(qos_incompatibilities(w, best_effort_writer).empty());  // offers more: matches
  EndpointInfo xcdr2_writer = w;
  xcdr2_writer.representations = {"XCDR2"};
  EXPECT_EQ(qos_incompatibilities(xcdr2_writer, w).size(), 1u);

  TopicInfo t;
  t.name = "fedsim/pilot_controls";
  t.type_names = {"T"};
  t.writers = {w};
  t.readers = {r};
  EXPECT_NE(format_topic_info(t).find("    DOES NOT MATCH writer io: ownership: reader SHARED, "
                                      "writer EXCLUSIVE, deadline: "),
            std::string::npos)
      << format_topic_info(t);
}

TEST(RawType, AKeyedSampleWithoutKeyHashGetsOneDefinedInstance) {
  // Fast DDS 2.9 asks getKey for a keyed sample that came without a key hash; a false answer
  // made its reader history assert (the `topic hz` abort on a Cyclone writer).
  RawPubSubType type("vendor::Keyed", true, 64);
  RawSample sample{{0x00, 0x01, 0x00, 0x00, 7, 0, 0, 0}};
  eprosima::fastrtps::rtps::InstanceHandle_t handle;
  ASSERT_FALSE(handle.isDefined());
  EXPECT_TRUE(type.getKey(&sample, &handle));
  EXPECT_TRUE(handle.isDefined());
  EXPECT_EQ(handle, RawPubSubType::unknown_key_instance());
}

}  // namespace
}  // namespace fedsim::tools
