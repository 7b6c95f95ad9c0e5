// Replay through the flight federate, in-process: while replayed states arrive they are the
// aircraft's state (exactly, re-stamped), the model waits; when they stop the model takes
// control from the last one and flies on from there. Controls: without a replay the aircraft
// flies its own path; a non-finite replayed sample is refused and counted, never flown.
#include "flight/federate/flight_program.hpp"
#include "flight/federate/replay_playback.hpp"

#include "common/runtime/composition.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace fedsim::flight {
namespace {

constexpr double kDeg = M_PI / 180.0;

/// Plays a recorded straight descent (1 km north of the start, 51 m/s east, 1 m/s down) for
/// frames [first, last), one sample a frame; one NaN sample at `bad_frame` if set.
class Replay final : public runtime::Component {
 public:
  Replay(std::uint64_t first, std::uint64_t last, std::int64_t bad_frame = -1)
      : Component("ios"), out_(writes(runtime::topics::replay_state)), first_(first), last_(last), bad_(bad_frame) {}
  void step(const runtime::FrameContext& frame) override {
    if (frame.frame < first_ || frame.frame >= last_) return;
    out_.write(sample(frame.frame));
  }
  static msg::AircraftState sample(std::uint64_t k) {
    msg::AircraftState s;
    const double t = 0.02 * static_cast<double>(k);
    s.latitude_rad((37.6 + 0.009) * kDeg);
    s.longitude_rad(-122.3 * kDeg + 51.0 * t / (6378137.0 * std::cos(37.609 * kDeg)));
    s.altitude_msl_m(1200.0 - 1.0 * t);
    s.velocity_ned_mps({0.0, 51.0, 1.0});
    s.phi_rad(0.0);
    s.theta_rad(1.0 * kDeg);  // about the C172's trim at 100 KTAS
    s.psi_rad(90.0 * kDeg);
    s.omega_body_radps({0.0, 0.0, 0.0});
    s.air().tas_mps(51.0);
    return s;
  }

 private:
  runtime::Output<msg::AircraftState>& out_;
  std::uint64_t first_, last_;
  std::int64_t bad_;
};

class Track final : public runtime::Component {
 public:
  Track() : Component("recorder"), aircraft_(reads(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext&) override {
    if (aircraft_.latest()) states.push_back(*aircraft_.latest());
  }
  std::vector<msg::AircraftState> states;  // states[k]: written in frame k (read in k + 1)

 private:
  runtime::Input<msg::AircraftState>& aircraft_;
};

std::uint64_t faults_of(const runtime::Component& c, const std::string& kind) {
  for (const auto& f : c.faults()) {
    if (f.kind == kind) return f.count;
  }
  return 0;
}

struct Flight {
  explicit Flight(Replay* replay) {
    FlightOptions o;
    o.aircraft = "c172";
    o.start.trim_kind = "level";
    o.start.ktas = 100.0;
    o.start.alt_ft = 4000.0;
    o.start.heading_deg = 0.0;
    o.start.lat_deg = 37.6;
    o.start.lon_deg = -122.3;
    flight = make_flight_component("flight", o);
    composition.add(*flight);
    if (replay) composition.add(*replay);
    composition.add(track);
    for (int i = 0; i < 400; ++i) composition.step_frame();
  }
  std::unique_ptr<FlightComponent> flight;
  Track track;
  runtime::Composition composition{{}};
};

TEST(ReplayPlayback, TheReplayIsTheAircraftStateThenTheModelTakesControlFromIt) {
  Replay replay(100, 200);
  Flight f(&replay);
  const auto& s = f.track.states;
  ASSERT_GE(s.size(), 390u);
  // Replay samples written in frame k are flown (read) in frame k + 1 and written then.
  for (std::uint64_t k = 101; k <= 200; ++k) {
    const msg::AircraftState want = Replay::sample(k - 1);
    ASSERT_EQ(s[k].latitude_rad(), want.latitude_rad()) << k;
    ASSERT_EQ(s[k].longitude_rad(), want.longitude_rad()) << k;
    ASSERT_EQ(s[k].altitude_msl_m(), want.altitude_msl_m()) << k;
    ASSERT_EQ(s[k].stamp().frame(), k) << "re-stamped as this frame's state";
  }
  // Held for kHoldFrames after the last sample, then the model flies on from it: east at about
  // 51 m/s from where the replay left it (not from its own northbound path at 4000 ft).
  const msg::AircraftState last = Replay::sample(199);
  const std::size_t taken = 200 + ReplayPlayback::kHoldFrames;  // the frame the model flies again
  EXPECT_EQ(s[taken - 1].longitude_rad(), last.longitude_rad());
  const auto& after = s[taken + 50];  // one second later
  const double east_m = (after.longitude_rad() - last.longitude_rad()) * 6378137.0 * std::cos(last.latitude_rad());
  const double north_m = (after.latitude_rad() - last.latitude_rad()) * 6378137.0;
  EXPECT_NEAR(east_m, 51.0, 3.0);
  EXPECT_NEAR(north_m, 0.0, 3.0);
  EXPECT_NEAR(after.altitude_msl_m(), last.altitude_msl_m(), 5.0);
  EXPECT_EQ(faults_of(*f.flight, "input_rejected"), 0u);
}

TEST(ReplayPlayback, WithoutAReplayTheAircraftFliesItsOwnPath) {
  Flight f(nullptr);
  const auto& s = f.track.states;
  ASSERT_GE(s.size(), 390u);
  // Trimmed northbound at 4000 ft: nowhere near the replayed track.
  EXPECT_NEAR(s[150].altitude_msl_m(), 4000.0 * 0.3048, 5.0);
  EXPECT_GT(std::abs(s[150].altitude_msl_m() - Replay::sample(149).altitude_msl_m()), 10.0);
}

TEST(ReplayPlayback, ANonFiniteReplayedSampleIsRefusedAndCounted) {
  ReplayPlayback playback;
  std::string problem;
  msg::AircraftState good = Replay::sample(1);
  EXPECT_EQ(playback.update(1, &good, problem), ReplayPlayback::Event::kStarted);
  msg::AircraftState bad = good;
  bad.altitude_msl_m(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(playback.update(2, &bad, problem), ReplayPlayback::Event::kNone);
  EXPECT_EQ(problem, "altitude_msl_m");
  EXPECT_EQ(playback.last().altitude_msl_m(), good.altitude_msl_m());  // the good one kept
  for (int i = 0; i < ReplayPlayback::kHoldFrames - 2; ++i) playback.update(2, &bad, problem);
  EXPECT_EQ(playback.update(2, &bad, problem), ReplayPlayback::Event::kEnded);
}

}  // namespace
}  // namespace fedsim::flight
