// The image-generator adapter in the in-process composition (no DDS): it renders at its render
// rate (in frames, so in FREEZE too), writes a snapshot on command (and ignores a request from
// before it started: the command topic's history), reports the age of the state it drew,
// publishes JPEG pictures that decode to the channel's picture, follows the instructor's fog and
// time of day, and refuses a NaN state, a bad tag and a bad weather value by name.
#include "visual/visual_component.hpp"

#include "common/picture/jpeg_encoder.hpp"
#include "common/runtime/composition.hpp"
#include "common/units/units.hpp"
#include "common/util/test/case_dir.hpp"
#include "visual/model/airport_scene.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>

namespace fedsim::visual {
namespace {

using units::kDegToRad;

// The aircraft on the KSFO 28R approach, 1 NM out on the 3 deg path, flying at 70 m/s.
class StateWriter final : public runtime::Component {
 public:
  StateWriter() : Component("flight"), out_(writes(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext& frame) override {
    const auto& end = test::ksfo_end("28R");
    const double before_m = 1852.0 - 70.0 * frame.end_time_s();
    const EyePose p = test::approach_eye(end, before_m, before_m * std::tan(3.0 * kDegToRad), 0.0);
    msg::AircraftState s;
    s.latitude_rad(p.lat_rad);
    s.longitude_rad(p.lon_rad);
    s.altitude_msl_m(nan_next ? std::nan("") : p.alt_msl_m);
    s.height_agl_m(before_m * std::tan(3.0 * kDegToRad));  // above the runway plane
    s.psi_rad(p.psi_rad);
    s.velocity_ned_mps({70.0 * std::cos(p.psi_rad), 70.0 * std::sin(p.psi_rad), 70.0 * std::tan(3.0 * kDegToRad)});
    s.stamp(stamp_at_start ? frame.stamp() : frame.end_stamp());
    out_.write(s);
    nan_next = false;
  }
  bool nan_next = false;
  bool stamp_at_start = false;  // a state a frame old: its age is one frame

 private:
  runtime::Output<msg::AircraftState>& out_;
};

class Observer final : public runtime::Component {
 public:
  Observer()
      : Component("ios"),
        status_(reads(runtime::topics::visual_status)),
        picture_(reads(runtime::topics::visual_picture)) {}
  void step(const runtime::FrameContext&) override {
    if (status_.latest()) status = *status_.latest();
    if (picture_.latest() && picture_.updates() != pictures_seen) {
      pictures_seen = picture_.updates();
      picture = *picture_.latest();
    }
  }
  msg::VisualChannelStatus status;
  msg::VisualPicture picture;
  std::uint64_t pictures_seen = 0;

 private:
  runtime::Input<msg::VisualChannelStatus>& status_;
  runtime::Input<msg::VisualPicture>& picture_;
};

VisualSetup small_setup(const std::string& dir) {
  VisualSetup s;
  s.channel.width_px = 160;
  s.channel.height_px = 120;
  s.render_hz = 10.0;
  s.stream_hz = 2.0;
  s.jpeg = {80, 2};
  s.snapshot_dir = dir;
  s.start_utc_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                       std::chrono::system_clock::now().time_since_epoch()).count();
  s.renderer = std::make_unique<Renderer>(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options()));
  return s;
}

msg::SimCommand snapshot(const std::string& tag, std::int64_t issued_utc_ns) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_SNAPSHOT);
  c.snapshot().tag(tag);
  c.snapshot().issued_utc_ns(static_cast<unsigned long long>(issued_utc_ns));
  return c;
}

std::int64_t now_utc_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

class VisualComponentTest : public ::testing::Test {
 protected:
  VisualComponentTest()
      : dir_(util::test::case_dir(test::output_dir() / "component")),
        visual_("visual", (std::filesystem::create_directories(dir_), small_setup(dir_.string()))),
        composition_({}) {
    composition_.add(writer_);
    composition_.add(visual_);
    composition_.add(observer_);
    run_state(msg::RUN_STATE_RUN);
  }
  void run_state(msg::RunState s) {
    msg::SimCommand c;
    c.kind(msg::COMMAND_RUN_STATE);
    c.run_state(s);
    composition_.command(c);
  }
  const runtime::FaultReport* fault(const std::string& kind) const {
    for (const auto& f : visual_.faults()) {
      if (f.kind == kind) return &f;
    }
    return nullptr;
  }
  picture::Image snap(const std::string& tag) {
    composition_.command(snapshot(tag, now_utc_ns()));
    composition_.run(2);
    return picture::read_png((dir_ / ("centre_" + tag + ".png")).string());
  }

  std::filesystem::path dir_;
  StateWriter writer_;
  VisualComponent visual_;
  Observer observer_;
  runtime::Composition composition_;
};

TEST_F(VisualComponentTest, RendersAtItsRateAndReportsWhatItDrew) {
  composition_.run(101);  // 2 s at 50 Hz: 10 images a second (the first frame has no state)
  EXPECT_NEAR(static_cast<double>(observer_.status.frames_rendered()), 20.0, 1.0);
  EXPECT_EQ(observer_.status.width_px(), 160);
  EXPECT_GT(observer_.status.render_time_ms(), 0.0f);
  EXPECT_FLOAT_EQ(observer_.status.state_age_ms(), 0.0f);  // the state of frame N-1 ends at frame N's start
  EXPECT_NE(std::string(observer_.status.renderer()).find("OSMesa"), std::string::npos);
  EXPECT_EQ(visual_.fault_count(), 0u);
  // A state stamped a frame early is a frame old at display time: extrapolated by 20 ms.
  writer_.stamp_at_start = true;
  composition_.run(10);
  EXPECT_NEAR(observer_.status.state_age_ms(), 20.0, 1e-3);
  // FREEZE: still rendering (the instructor may change the weather), nothing extrapolated.
  run_state(msg::RUN_STATE_FREEZE);
  const auto before = observer_.status.frames_rendered();
  composition_.run(50);
  EXPECT_GE(observer_.status.frames_rendered(), before + 9);
  EXPECT_FLOAT_EQ(observer_.status.state_age_ms(), 0.0f);
}

TEST_F(VisualComponentTest, SnapshotsOnCommandButNotFromTheCommandHistory) {
  composition_.run(10);
  // A request issued before the channel started (the transient-local history) is not taken.
  composition_.command(snapshot("old", now_utc_ns() - 3'600'000'000'000LL));
  composition_.run(2);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "centre_old.png"));
  const picture::Image image = snap("now");
  EXPECT_EQ(image.width_px, 160);
  EXPECT_EQ(observer_.status.snapshots_written(), 1u);
  // The runway is ahead: the pictures's lower middle is not the sky's colour of its top.
  EXPECT_GT(std::abs(test::mean_luminance(image, 70, 80, 20, 20) - test::mean_luminance(image, 70, 0, 20, 10)), 0.02);
  // A bad tag is refused by name, and nothing is written.
  composition_.command(snapshot("../escape", now_utc_ns()));
  composition_.run(2);
  ASSERT_NE(fault("command_rejected"), nullptr);
  EXPECT_NE(fault("command_rejected")->last.find("[A-Za-z0-9_-]"), std::string::npos);
  EXPECT_EQ(observer_.status.snapshots_written(), 1u);
}

// The picture at a height (the decision height): drawn in the frame the new state first descends
// through it, whatever the render rate, and only once; a start below the height captures nothing.
TEST(VisualCapture, ThePictureAtTheDecisionHeightIsTakenOnceOnTheWayDown) {
  const std::filesystem::path dir = util::test::case_dir(test::output_dir() / "capture");
  auto fly = [&](double capture_ft, const std::string& file, int frames) {
    VisualSetup setup = small_setup(dir.string());
    setup.render_hz = 0.5;  // one image every 100 frames: the capture must not wait for it
    setup.capture_agl_m = capture_ft * units::kFtToM;
    setup.capture_png = (dir / file).string();
    std::filesystem::remove(setup.capture_png);
    StateWriter writer;
    VisualComponent visual("visual", std::move(setup));
    runtime::Composition composition({});
    composition.add(writer);
    composition.add(visual);
    msg::SimCommand run;
    run.kind(msg::COMMAND_RUN_STATE);
    run.run_state(msg::RUN_STATE_RUN);
    composition.command(run);
    composition.run(frames);
    return std::filesystem::exists(dir / file);
  };
  // From 318 ft at 3.67 m/s down the 3 deg path, 250 ft is crossed after 5.7 s (frame 285).
  EXPECT_FALSE(fly(250.0, "dh_early.png", 250));
  EXPECT_TRUE(fly(250.0, "dh.png", 300));
  const picture::Image at_250 = picture::read_png((dir / "dh.png").string());
  EXPECT_EQ(at_250.width_px, 160);
  // Negative control: a height above the start is never descended through.
  EXPECT_FALSE(fly(400.0, "dh_never.png", 300));
  // Another height, another picture (the runway is nearer).
  EXPECT_TRUE(fly(200.0, "dh_200.png", 600));
  EXPECT_NE(picture::read_png((dir / "dh_200.png").string()).rgba, at_250.rgba);
}

TEST_F(VisualComponentTest, PicturesAreJpegsOfTheChannel) {
  composition_.run(60);
  ASSERT_GE(observer_.pictures_seen, 2u);  // 2 a second
  EXPECT_EQ(std::string(observer_.picture.encoding()), "image/jpeg");
  const picture::Image picture = picture::decode_jpeg(observer_.picture.data().data(), observer_.picture.data().size());
  EXPECT_EQ(picture.width_px, 80);  // halved
  EXPECT_EQ(picture.height_px, 60);
  EXPECT_EQ(observer_.picture.width_px(), 80);
}

TEST_F(VisualComponentTest, FogAndNightChangeThePicture) {
  composition_.run(5);
  const picture::Image clear = snap("clear");
  msg::SimCommand fog;
  fog.kind(msg::COMMAND_WEATHER);
  fog.weather().visibility_m(200.0);
  composition_.command(fog);
  const picture::Image foggy = snap("fog");
  // In 200 m fog the runway 1 NM ahead is gone: the lower picture is as uniform as the airlight.
  auto spread = [](const picture::Image& im) {
    double lo = 1, hi = 0;
    for (int r = 70; r < 110; ++r) {
      for (int c = 20; c < 140; ++c) {
        lo = std::min(lo, im.at(c, r).luminance());
        hi = std::max(hi, im.at(c, r).luminance());
      }
    }
    return hi - lo;
  };
  EXPECT_LT(spread(foggy), 0.5 * spread(clear));
  // Night: 03:00 local (10:00 UTC in June at KSFO) darkens the sky.
  msg::SimCommand night;
  night.kind(msg::COMMAND_TIME_OF_DAY);
  night.time_of_day().year(2026);
  night.time_of_day().month(6);
  night.time_of_day().day(21);
  night.time_of_day().utc_time_of_day_s(10.0 * 3600.0);
  night.time_of_day().airport_lights_on(true);
  composition_.command(night);
  const picture::Image dark = snap("night");
  EXPECT_LT(test::mean_luminance(dark, 0, 0, 160, 20), 0.5 * test::mean_luminance(foggy, 0, 0, 160, 20));
  // Out-of-range values are refused by name and change nothing.
  msg::SimCommand bad = fog;
  bad.weather().visibility_m(std::nan(""));
  composition_.command(bad);
  night.time_of_day().month(13);
  composition_.command(night);
  composition_.run(2);
  ASSERT_NE(fault("command_rejected"), nullptr);
  EXPECT_EQ(fault("command_rejected")->count, 2u);
}

TEST_F(VisualComponentTest, ANanStateIsRejectedAndTheLastPictureStays) {
  composition_.run(10);
  const auto rendered = observer_.status.frames_rendered();
  writer_.nan_next = true;
  composition_.run(3);  // checked when it arrives, whether or not the frame draws
  ASSERT_NE(fault("input_rejected"), nullptr);
  EXPECT_NE(fault("input_rejected")->last.find("alt_msl_m"), std::string::npos) << fault("input_rejected")->last;
  composition_.run(10);
  EXPECT_GT(observer_.status.frames_rendered(), rendered);  // good samples render again
}

// --hud: common/hud's HUD drawn for this channel over its picture. The same state drawn
// with and without it: the HUD's green symbology appears (none of the scene's pixels is that
// green), the flight-path vector's ring is centred where the channel camera projects the
// velocity (the aircraft flies the 3 deg path: the FPV sits 3 deg below the horizon; the scene
// alone has only its few green threshold lights), and the
// corners, away from the symbology, are the scene's pixels unchanged.
picture::Image render_once(bool hud) {
  const auto dir = util::test::case_dir(test::output_dir() / "component");
  StateWriter writer;
  VisualSetup setup = small_setup(dir.string());
  setup.channel.width_px = 320;
  setup.channel.height_px = 240;
  if (hud) setup.hud = std::make_unique<hud::HudRenderer>();
  VisualComponent visual("visual", std::move(setup));
  runtime::Composition composition({});
  composition.add(writer);
  composition.add(visual);
  msg::SimCommand run;
  run.kind(msg::COMMAND_RUN_STATE);
  run.run_state(msg::RUN_STATE_RUN);
  composition.command(run);
  composition.run(3);
  composition.command(snapshot(hud ? "hud" : "no_hud", now_utc_ns()));
  composition.run(1);
  EXPECT_EQ(visual.fault_count(), 0u);
  return picture::read_png((dir / (std::string("centre_") + (hud ? "hud" : "no_hud") + ".png")).string());
}

TEST(VisualHud, TheHudIsCompositedOverTheChannelWhereTheCameraLooks) {
  const picture::Image plain = render_once(false), hud = render_once(true);
  auto hud_green = [](const picture::Rgba8& p) { return p.g > 200 && p.g > p.r + 60 && p.g > p.b + 60; };
  int green_plain = 0, green_hud = 0;
  double sum_row = 0;
  int near_fpv = 0;
  // The FPV: 3 deg below the zero-pitch line; vfov of the default channel, y down.
  view::ChannelConfig channel;
  const double fpv_row = 120.0 * (1.0 + std::tan(3.0 * kDegToRad) / std::tan(channel.vertical_fov_rad / 2.0));
  for (int r = 0; r < 240; ++r) {
    for (int c = 0; c < 320; ++c) {
      green_plain += hud_green(plain.at(c, r));
      if (!hud_green(hud.at(c, r))) continue;
      ++green_hud;
      if (std::abs(c - 160) < 12 && std::abs(r - fpv_row) < 12) {
        sum_row += r + 0.5;
        ++near_fpv;
      }
    }
  }
  EXPECT_LT(green_plain, 40);  // the threshold's green lights only
  EXPECT_GT(green_hud, green_plain + 300);
  ASSERT_GT(near_fpv, 10);  // the FPV's ring is there
  EXPECT_NEAR(sum_row / near_fpv, fpv_row, 2.0);
  for (const auto& [c, r] : {std::pair{2, 2}, std::pair{317, 237}, std::pair{317, 2}, std::pair{2, 237}}) {
    EXPECT_EQ(hud.at(c, r).g, plain.at(c, r).g) << c << "," << r;
  }
}

TEST(VisualHelpers, Weather) {
  Environment e;
  msg::WeatherSettings w;
  w.visibility_m(800.0);
  w.cloud_base_m(300.0);
  EXPECT_FALSE(apply_weather(w, e));
  EXPECT_DOUBLE_EQ(e.visibility_m, 800.0);
  ASSERT_TRUE(e.cloud.has_value());
  EXPECT_DOUBLE_EQ(e.cloud->base_agl_m, 300.0);
  w.visibility_m(0.0);  // unchanged
  w.cloud_base_m(0.0);  // no cloud
  EXPECT_FALSE(apply_weather(w, e));
  EXPECT_DOUBLE_EQ(e.visibility_m, 800.0);
  EXPECT_FALSE(e.cloud.has_value());
  w.visibility_m(5.0);  // below 10 m
  EXPECT_TRUE(apply_weather(w, e));
  EXPECT_DOUBLE_EQ(e.visibility_m, 800.0);
}

}  // namespace
}  // namespace fedsim::visual
