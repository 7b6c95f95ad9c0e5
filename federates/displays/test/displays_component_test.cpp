// The displays adapter in the in-process composition (no DDS): it draws the PFD and the ND at
// its render rate (counted in frames), reports each on fedsim/visual_status under its own key
// and name, publishes JPEGs that decode to the display's size, writes snapshots for the display
// a command targets and the last pictures on stop, shows the localizer the navigation state
// gives (the PFD's diamond moves with it), and refuses a NaN state by name, keeping the last
// pictures.
#include "displays/displays_component.hpp"
#include "displays/model/pfd.hpp"

#include "common/picture/jpeg_encoder.hpp"
#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"
#include "common/util/test/case_dir.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace fedsim::displays {
namespace {

using symbology::Rect;
using units::kDegToRad;

class StateWriter final : public runtime::Component {
 public:
  StateWriter()
      : Component("flight"),
        state_(writes(runtime::topics::aircraft_state)),
        nav_(writes(runtime::topics::navigation_state)) {}
  void step(const runtime::FrameContext& frame) override {
    msg::AircraftState s;
    s.theta_rad(2.0 * kDegToRad);
    s.psi_rad(284.0 * kDegToRad);
    s.latitude_rad(37.6 * kDegToRad);
    s.longitude_rad(-122.3 * kDegToRad);
    s.altitude_msl_m(nan ? std::nan("") : 300.0);
    s.height_agl_m(295.0);
    s.air().cas_mps(70.0);
    s.air().tas_mps(70.5);
    s.ground_speed_mps(70.0);
    s.stamp(frame.end_stamp());
    state_.write(s);
    msg::NavigationState n;
    n.nav()[0].frequency_khz(109550);
    n.nav()[0].signal(msg::NAV_SIGNAL_LOCALIZER);
    n.nav()[0].status(msg::SIGNAL_VALID);
    n.nav()[0].course_deviation(localizer_deviation);
    n.nav()[0].glideslope_status(msg::SIGNAL_VALID);
    n.stamp(frame.end_stamp());
    nav_.write(n);
  }
  bool nan = false;
  double localizer_deviation = 0.0;

 private:
  runtime::Output<msg::AircraftState>& state_;
  runtime::Output<msg::NavigationState>& nav_;
};

class Observer final : public runtime::Component {
 public:
  Observer() : Component("ios"), status_(reads(runtime::topics::visual_status)), picture_(reads(runtime::topics::visual_picture)) {}
  void step(const runtime::FrameContext&) override {}
  void tap(runtime::Composition& c) {
    c.on_written<msg::VisualChannelStatus>(runtime::topics::visual_status, [this](const msg::VisualChannelStatus& s) { status[s.name().to_string()] = s; });
    c.on_written<msg::VisualPicture>(runtime::topics::visual_picture, [this](const msg::VisualPicture& p) {
      pictures[p.name().to_string()] = p;
      ++picture_count[p.name().to_string()];
    });
  }
  std::map<std::string, msg::VisualChannelStatus> status;
  std::map<std::string, msg::VisualPicture> pictures;
  std::map<std::string, int> picture_count;

 private:
  runtime::Input<msg::VisualChannelStatus>& status_;
  runtime::Input<msg::VisualPicture>& picture_;
};

std::filesystem::path output_dir() {
  const char* env = std::getenv("FEDSIM_DISPLAYS_TEST_OUTPUT");
  auto dir = std::filesystem::path(env ? env : (std::filesystem::temp_directory_path() / "fedsim_displays_tests").string()) /
             "federate";
  std::filesystem::create_directories(dir);
  return dir;
}

DisplaysSetup small_setup(const std::string& dir) {
  DisplaysSetup s;
  s.displays = {{DisplayKind::kPfd, "pfd", 100, 200, 200}, {DisplayKind::kNd, "nd", 101, 200, 200}};
  s.renderer = std::make_unique<DisplayRenderer>();
  s.render_hz = 10.0;
  s.stream_hz = 2.0;
  s.snapshot_dir = dir;
  s.final_png_dir = dir;
  s.start_utc_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                       std::chrono::system_clock::now().time_since_epoch()).count();
  return s;
}

msg::SimCommand snapshot(const std::string& target, const std::string& tag) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_SNAPSHOT);
  c.target(target);
  c.snapshot().tag(tag);
  c.snapshot().issued_utc_ns(static_cast<unsigned long long>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count()));
  return c;
}

class DisplaysComponentTest : public ::testing::Test {
 protected:
  DisplaysComponentTest() : dir_(util::test::case_dir(output_dir())), displays_("displays", small_setup(dir_.string())), composition_({}) {
    for (const char* f : {"pfd.png", "nd.png", "nd_approach.png", "pfd_approach.png"}) std::filesystem::remove(dir_ / f);
    composition_.add(writer_);
    composition_.add(displays_);
    composition_.add(observer_);
    observer_.tap(composition_);
    msg::SimCommand run;
    run.kind(msg::COMMAND_RUN_STATE);
    run.run_state(msg::RUN_STATE_RUN);
    composition_.command(run);
  }
  const runtime::FaultReport* fault(const std::string& kind) const {
    for (const auto& f : displays_.faults()) {
      if (f.kind == kind) return &f;
    }
    return nullptr;
  }
  // Column of the magenta localizer diamond's centroid in the PFD's localizer scale (NaN: none).
  static double magenta_column(const picture::Image& im) {
    const PfdLayout layout = pfd_layout(im.width_px, im.height_px);
    const Rect r = layout.localizer_scale_px;
    double sum = 0;
    int n = 0;
    for (int row = std::max(0, int(r.y0)); row < std::min(im.height_px, int(r.y1) + 1); ++row) {
      for (int c = std::max(0, int(r.x0)); c < std::min(im.width_px, int(r.x1) + 1); ++c) {
        const picture::Rgba8 p = im.at(c, row);
        if (p.r > 170 && p.b > 170 && p.g < 150) {
          sum += c + 0.5;
          ++n;
        }
      }
    }
    return n > 0 ? sum / n : std::nan("");
  }
  static double dot_px(const picture::Image& im) { return pfd_layout(im.width_px, im.height_px).localizer_dot_px; }

  std::filesystem::path dir_;
  StateWriter writer_;
  DisplaysComponent displays_;
  Observer observer_;
  runtime::Composition composition_;
};

TEST_F(DisplaysComponentTest, DrawsBothDisplaysAtItsRateAndPublishesThem) {
  composition_.run(51);  // 1 s at 50 Hz, 10 pictures a second (the first frame has no state)
  ASSERT_EQ(observer_.status.count("pfd"), 1u);
  ASSERT_EQ(observer_.status.count("nd"), 1u);
  EXPECT_NEAR(static_cast<double>(observer_.status["pfd"].frames_rendered()), 10.0, 1.0);
  EXPECT_EQ(observer_.status["pfd"].channel_id(), 100);
  EXPECT_EQ(observer_.status["nd"].channel_id(), 101);
  EXPECT_GT(observer_.status["nd"].render_time_ms(), 0.0f);
  EXPECT_NE(std::string(observer_.status["pfd"].renderer()).find("OSMesa"), std::string::npos);
  EXPECT_GE(observer_.picture_count["pfd"], 2);
  EXPECT_GE(observer_.picture_count["nd"], 2);
  const auto& jpeg = observer_.pictures["pfd"].data();
  const picture::Image pfd = picture::decode_jpeg(jpeg.data(), jpeg.size());
  EXPECT_EQ(pfd.width_px, 200);
  EXPECT_EQ(std::string(observer_.pictures["nd"].encoding()), "image/jpeg");
  EXPECT_EQ(displays_.fault_count(), 0u);
}

TEST_F(DisplaysComponentTest, TheLocalizerDiamondFollowsTheNavigationState) {
  writer_.localizer_deviation = 0.5;  // 1 dot right
  composition_.run(6);
  const double right = magenta_column(displays_.image(0));
  writer_.localizer_deviation = -0.5;
  composition_.run(6);
  const double left = magenta_column(displays_.image(0));
  ASSERT_TRUE(std::isfinite(right) && std::isfinite(left));
  // 2 dots apart (1 dot = 0.5 of the receiver's full scale), right of left: fly right is right.
  EXPECT_NEAR(right - left, 2.0 * dot_px(displays_.image(0)), 1.5);
}

TEST_F(DisplaysComponentTest, SnapshotsTheTargetedDisplayAndTheLastPicturesOnStop) {
  composition_.run(5);
  composition_.command(snapshot("nd", "approach"));
  composition_.run(2);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "nd_approach.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "pfd_approach.png"));  // not the target
  EXPECT_EQ(observer_.status["nd"].snapshots_written(), 1u);
  composition_.command(snapshot("", "../escape"));
  composition_.run(2);
  ASSERT_NE(fault("command_rejected"), nullptr);
  composition_.stop();
  const picture::Image pfd = picture::read_png((dir_ / "pfd.png").string());
  EXPECT_EQ(pfd.width_px, 200);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "nd.png"));
}

TEST_F(DisplaysComponentTest, ANanStateIsRefusedByNameAndTheLastPicturesStay) {
  composition_.run(10);
  writer_.nan = true;
  composition_.run(1);  // written in this frame, read in the next
  const auto before = observer_.status["pfd"].frames_rendered();
  composition_.run(10);
  ASSERT_NE(fault("input_rejected"), nullptr);
  EXPECT_NE(fault("input_rejected")->last.find("altitude_msl_m"), std::string::npos);
  EXPECT_EQ(observer_.status["pfd"].frames_rendered(), before);  // not drawn
  writer_.nan = false;
  composition_.run(10);
  EXPECT_GT(observer_.status["pfd"].frames_rendered(), before);  // good states drawn again
}

}  // namespace
}  // namespace fedsim::displays
