// fedsim-visual's adapter: one image-generator channel (the seed's nodes 5-7, Chapter 8). Every
// render slot it draws the airport scene (model/: OSMesa renderer, Annex 14 runways, approach
// lights, PAPI, fog, sky by the sun) from the pilot's eye point, carried forward from the
// aircraft state to the display time (model/eye_extrapolation.hpp), and says what it drew.
//
// Ports (units in the IDL):
//   reads    fedsim/aircraft_state   the ownship's CG pose, ground velocity and body rates
//   writes   fedsim/visual_status    per image: render time, the age of the state drawn, rate
//   writes   fedsim/visual_picture   a JPEG of the picture every 1/--stream-hz (0: none)
//   commands weather (visibility, cloud base), time of day (sun, lights), snapshot (a PNG)
//   with --hud also reads fedsim/autopilot_state and fedsim/navigation_state (the FD cue)
//
// HUD (--hud, seed 5.9): common/hud's HUD (in the cockpit displays' symbology) drawn for this
// channel's camera (its ChannelConfig: size, field of view, offsets) from the same extrapolated
// eye attitude the scene was drawn with, composited over the picture (premultiplied "over") before
// it is published, snapshot or written, so that the flight-path vector and the horizon line
// lie on the scene's.
//
// Render slots: an image whenever the frame number crosses a multiple of 1/--render-hz of the
// frame period, counted in frames (so it renders in FREEZE too, and a lockstep run renders the
// same frames every time). A passive channel (not in the timing's --expect) never holds the
// frame back: a slow render only makes the host skip ticks. As a lockstep member its pictures
// are reproducible bit for bit (the renderer has no clock or randomness of its own).
//
// Frames: the eye is the pack's pilot eye point relative to the CG at the pack's loading
// (body axes), plus the channel's own offset; the state's position is the CG's.
// Faults, by name: "input_rejected" (a state sample with a NaN or out-of-range pose: the last
// picture stays), "command_rejected" (a weather, time-of-day or snapshot command out of range).
#pragma once

#include "common/hud/hud_renderer.hpp"
#include "common/picture/jpeg_encoder.hpp"
#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "common/symbology_mapping/symbology_mapping.hpp"
#include "common/view/channel_config.hpp"
#include "visual/model/airport_scene.hpp"
#include "visual/model/environment.hpp"
#include "visual/model/renderer.hpp"
#include "visual/model/sun_position.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace fedsim::visual {

struct VisualSetup {
  view::ChannelConfig channel;             // the eye-point offset from the pack already added
  std::uint16_t channel_id = 0;      // 0 centre, then left, right...
  std::unique_ptr<Renderer> renderer;
  double render_hz = 30.0;           // images per second of frames (at most one per frame) [Hz]
  double stream_hz = 5.0;            // pictures published per second of frames (0: none) [Hz]
  picture::JpegOptions jpeg{75, 2};
  std::string snapshot_dir = ".";    // where snapshot PNGs go
  std::string final_png;             // the last image written here on stop ("" = none)
  // The picture at a height (the decision height of an approach): the first image whose aircraft
  // state is at or below capture_agl_m after one above it, drawn in that frame whatever the
  // render rate, written to capture_png ("" = none). The height is the flight model's
  // height_agl_m (the CG above the runway plane), so every channel captures the same frame.
  double capture_agl_m = 0.0;
  std::string capture_png;
  Environment environment;           // until the instructor says otherwise
  UtcTime time_of_day{2026, 6, 21, 19.0 * 3600.0};  // UTC at sim time 0 (noon at KSFO, PDT)
  bool time_of_day_set = true;       // false: the environment's own sun stays
  std::int64_t start_utc_ns = 0;     // snapshot requests issued before this are history
  std::string state_qos;             // profile of the aircraft-state reader ("" = catalogue)
  std::unique_ptr<hud::HudRenderer> hud;            // the HUD drawn over the picture (null: none)
  symbology_mapping::DisplayContext hud_context;   // the magnetic variation its heading scale uses
  std::string gl_note;                             // why --gl auto fell back to OSMesa ("" = it did not)
};

/// The environment after a weather command (visibility <= 0: unchanged; cloud base <= 0: no
/// cloud, else a 1000 m deep layer from that height above the airport), or the problem.
std::optional<std::string> apply_weather(const msg::WeatherSettings& weather, Environment& environment);

class VisualComponent final : public runtime::Component {
 public:
  VisualComponent(std::string name, VisualSetup setup);

  void on_command(const msg::SimCommand& command) override;
  void step(const runtime::FrameContext& frame) override;
  void on_stop() override;

 private:
  struct Drawn {
    RenderStats stats;
    double state_age_s = 0.0;     // the span the eye was carried forward over [s]
    std::int64_t start_ns = 0;    // monotonic clock when the frame's drawing began [ns]
  };
  bool render_slot(const runtime::FrameContext& frame);
  bool check_new_state(const runtime::FrameContext& frame);
  std::optional<Drawn> render(const runtime::FrameContext& frame);
  void update_sun(double sim_time_s, double lat_rad, double lon_rad);
  void write_snapshot(const runtime::FrameContext& frame);
  /// True in the frame whose new state first descends through the capture height.
  bool capture_due();
  void write_capture();
  void publish_picture(const runtime::FrameContext& frame);
  void publish_status(const runtime::FrameContext& frame, const RenderStats& stats, double state_age_s,
                      double step_ms);

  void draw_hud(const msg::AircraftState& state, const EyePose& eye);

  runtime::Input<msg::AircraftState>& aircraft_state_;
  runtime::Input<msg::AutopilotState>* autopilot_state_ = nullptr;    // with --hud
  runtime::Input<msg::NavigationState>* navigation_state_ = nullptr;  // with --hud
  runtime::Output<msg::VisualChannelStatus>& visual_status_;
  runtime::Output<msg::VisualPicture>& visual_picture_;
  VisualSetup setup_;
  picture::Image image_;
  bool have_image_ = false;
  std::uint64_t state_seen_ = 0;
  bool state_usable_ = false;
  msg::FrameStamp image_stamp_;
  std::int64_t last_render_slot_ = -1, last_stream_slot_ = -1;
  double time_of_day_epoch_sim_s_ = 0.0;  // sim time at which time_of_day applies
  std::optional<std::string> pending_snapshot_;
  bool capture_armed_ = false;            // a state above the capture height was seen
  bool captured_ = false;
  std::uint64_t capture_state_seen_ = 0;  // aircraft_state_.updates() last looked at for it
  double mean_render_s_ = 0.0;            // recent render time (realtime display-time lead) [s]
  std::uint64_t frames_rendered_ = 0, pictures_sent_ = 0;
  std::uint32_t snapshots_written_ = 0;
  std::int64_t rate_window_start_ns_ = 0;
  std::uint32_t rate_window_images_ = 0;
  float frame_rate_hz_ = 0.0f;
  picture::Image scaled_;  // the picture reduced for the stream
  picture::Image hud_image_;
  msg::VisualChannelStatus status_;
  msg::VisualPicture picture_;
};

runtime::FederateProgram program();

}  // namespace fedsim::visual
