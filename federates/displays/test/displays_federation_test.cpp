// fedsim-displays as a process over DDS on 127.0.0.1 (domain 187): a short lockstep federation
// (timing, flight, displays) on the KSFO 28R approach. The PFD and ND pictures published on
// fedsim/visual_picture decode as JPEGs of the displays' size, their status reports the frames
// drawn, and the last pictures are written as PNGs on stop. The control: a picture of another
// channel id than the two displays' never arrives (only displays are in this federation).
#include "common/picture/image.hpp"
#include "common/picture/jpeg_encoder.hpp"
#include "common/runtime/federate_options.hpp"
#include "common/runtime/subscription.hpp"
#include "common/runtime/topic_catalogue.hpp"
#include "common/util/build_paths.hpp"
#include "common/util/child_process.hpp"

#include <gtest/gtest.h>

#include <map>
#include <mutex>

namespace fedsim::displays {
namespace {

std::string bin(const std::string& name) { return fedsim::util::bin_dir() + "/" + name; }

std::unique_ptr<util::ChildProcess> start(const std::string& dir, const std::string& name, int domain,
                                          const std::string& binary, std::vector<std::string> args) {
  std::vector<std::string> argv = {bin(binary), "--name", name, "--domain", std::to_string(domain),
                                   "--qos-file", runtime::default_qos_file()};
  argv.insert(argv.end(), args.begin(), args.end());
  return std::make_unique<util::ChildProcess>(argv, dir + "/" + name + ".log");
}

TEST(DisplaysFederation, PublishesDecodablePicturesAndWritesTheFinalPngs) {
  const int domain = 187;
  const std::string dir = util::temp_dir("displays");
  struct Seen {
    std::mutex mutex;
    std::map<int, std::vector<std::uint8_t>> jpeg;
    std::map<int, std::string> name;
    std::map<int, std::uint64_t> frames;
  } seen;
  runtime::ParticipantOptions o;
  o.name = "test-ios";
  o.domain_id = domain;
  o.qos_file = runtime::default_qos_file();
  auto dds = runtime::DdsParticipant::create(o);
  runtime::Subscription<msg::VisualPicture> pictures(
      dds, runtime::topics::visual_picture, {}, [&](const msg::VisualPicture& m, const auto&) {
        std::lock_guard lock(seen.mutex);
        seen.jpeg[m.channel_id()] = m.data();
        seen.name[m.channel_id()] = m.name().to_string();
      });
  runtime::Subscription<msg::VisualChannelStatus> status(
      dds, runtime::topics::visual_status, {}, [&](const msg::VisualChannelStatus& m, const auto&) {
        std::lock_guard lock(seen.mutex);
        seen.frames[m.channel_id()] = m.frames_rendered();
      });
  const std::string b737 = fedsim::util::data_dir() + "/aircraft/b737.yaml";
  auto flight = start(dir, "flight", domain, "fedsim-flight",
                      {"--aircraft", b737, "--airport", "KSFO", "--runway", "28R", "--approach-nm", "3", "--alt-ft",
                       "1000", "--kcas", "145", "--flaps", "0.875", "--gear-down", "--state-qos", "lockstep_data"});
  auto displays = start(dir, "displays", domain, "fedsim-displays",
                        {"--width-px", "300", "--height-px", "300", "--render-hz", "10", "--stream-hz", "5",
                         "--final-png-dir", dir, "--state-qos", "lockstep_data"});
  auto timing = start(dir, "timing", domain, "fedsim-timing",
                      {"--mode", "lockstep", "--rate", "50", "--expect", "flight,displays", "--frames", "150",
                       "--shutdown-on-exit"});
  ASSERT_TRUE(timing->wait(60)) << timing->output();
  EXPECT_EQ(timing->exit_code(), 0) << timing->output();
  for (auto* p : {flight.get(), displays.get()}) ASSERT_TRUE(p->wait(20)) << p->output();
  EXPECT_EQ(displays->exit_code(), 0) << displays->output();

  for (const char* name : {"pfd", "nd"}) {
    const picture::Image last = picture::read_png(dir + "/" + name + ".png");
    EXPECT_EQ(last.width_px, 300) << name;
    EXPECT_EQ(last.height_px, 300) << name;
  }
  std::lock_guard lock(seen.mutex);
  ASSERT_EQ(seen.jpeg.count(100), 1u) << displays->output();
  ASSERT_EQ(seen.jpeg.count(101), 1u) << displays->output();
  EXPECT_EQ(seen.name[100], "pfd");
  EXPECT_EQ(seen.name[101], "nd");
  EXPECT_EQ(seen.jpeg.size(), 2u);  // nobody else publishes pictures here
  const picture::Image pfd = picture::decode_jpeg(seen.jpeg[100].data(), seen.jpeg[100].size());
  EXPECT_EQ(pfd.width_px, 300);
  EXPECT_EQ(pfd.height_px, 300);
  // 150 frames at 50 Hz, 10 pictures a second: 30 each (the last statuses may still be in flight).
  EXPECT_GE(seen.frames[100], 20u);
  EXPECT_LE(seen.frames[100], 31u);
}

}  // namespace
}  // namespace fedsim::displays
