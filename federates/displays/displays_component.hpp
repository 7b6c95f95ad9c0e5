// fedsim-displays' adapter: the cockpit displays (seed Chapter 5: 5.8 EFIS) as a federate. Every
// render slot it fills the displays model's inputs from the aircraft, navigation and autopilot
// states (display_mapping.hpp), draws the PFD and the ND (model/: OpenGL through OSMesa,
// FreeType text) and says what it drew.
//
// Ports (units in the IDL):
//   reads    fedsim/aircraft_state     attitude, speeds, altitude, accelerations
//   reads    fedsim/navigation_state   NAV1/NAV2 (localizer, glide slope, VOR, DME), ADF, marker, FD
//   reads    fedsim/autopilot_state    the FMA and the flight-director commands
//   writes   fedsim/visual_status      per picture drawn: render time, rate (one instance per display)
//   writes   fedsim/visual_picture     a JPEG of each display every 1/--stream-hz (0: none)
//   commands snapshot (a PNG of each display, or of the one the command targets: "pfd", "nd")
//
// The pictures and status reuse the image generator's topics and types (idl/visual.idl,
// idl/status.idl): a display is a "channel" with its own key (--channel-id: PFD 100, ND 101 by
// default, far from the outside-world channels 0, 1, 2...) and name ("pfd", "nd"), so the
// instructor station shows it as it shows a channel, by name, with no new IDL. The status's
// fov_h_rad is 0 (a display has no field of view) and state_age_ms the age of the aircraft
// state drawn (not extrapolated: the instruments show the last state, as the real ones do).
//
// Render slots are counted in frames (as fedsim-visual's), so a lockstep run draws the same
// pictures every time. The navigation and autopilot states are optional: before one arrives
// (or with no such federate) the PFD shows no localizer, glide slope, FD or FMA.
// Faults, by name: "input_rejected" (a state with a NaN or out-of-range field: the last pictures
// stay), "command_rejected" (a bad snapshot tag), "snapshot_failed", "final_png_failed",
// "picture_too_large".
#pragma once

#include "common/navdb/nav_database.hpp"
#include "common/picture/image.hpp"
#include "common/picture/jpeg_encoder.hpp"
#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "displays/display_mapping.hpp"
#include "displays/model/display_renderer.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::displays {

enum class DisplayKind { kPfd, kNd };

/// One display the federate draws: its kind, size, name and key on the picture topics.
struct DisplaySpec {
  DisplayKind kind = DisplayKind::kPfd;
  std::string name;         // "pfd", "nd"
  std::uint16_t id = 100;   // channel_id on fedsim/visual_status and fedsim/visual_picture
  int width_px = 400;
  int height_px = 400;
};

struct DisplaysSetup {
  std::vector<DisplaySpec> displays;      // at least one
  std::unique_ptr<DisplayRenderer> renderer;
  double render_hz = 10.0;                // pictures per second of frames (at most one per frame) [Hz]
  double stream_hz = 2.0;                 // JPEGs published per second of frames (0: none) [Hz]
  picture::JpegOptions jpeg{80, 1};
  double nd_range_nm = 40.0;              // the ND's range selector [NM]
  std::shared_ptr<const nav::NavDatabase> navdb;  // navaids on the ND, magnetic variation (null: none, 0)
  std::string snapshot_dir = ".";
  std::string final_png_dir;              // "<name>.png" of each display written here on stop ("" = none)
  std::int64_t start_utc_ns = 0;          // snapshot requests issued before this are history
  std::string state_qos;                  // profile of the three readers ("" = catalogue)
  bool read_autopilot = true;             // false: no autopilot in the deployment (no FMA/FD)
  std::string gl_note;                    // why --gl auto fell back to OSMesa ("" = it did not)
};

class DisplaysComponent final : public runtime::Component {
 public:
  DisplaysComponent(std::string name, DisplaysSetup setup);

  void on_command(const msg::SimCommand& command) override;
  void step(const runtime::FrameContext& frame) override;
  void on_stop() override;

  /// The last picture of a display (for tests); empty before the first.
  const picture::Image& image(std::size_t display) const { return drawn_[display].image; }

 private:
  struct Drawn {
    picture::Image image;
    bool have = false;
    std::uint64_t frames = 0, pictures = 0;
    std::uint32_t snapshots = 0;
    std::int64_t last_stream_slot = -1;
    std::optional<std::string> pending_snapshot;
    msg::VisualChannelStatus status;
    msg::VisualPicture picture;
  };
  bool slot(const runtime::FrameContext& frame, double hz, std::int64_t& last) const;
  bool check_new_state(const runtime::FrameContext& frame);
  void render_all(const runtime::FrameContext& frame);
  void write_snapshot(std::size_t i, const runtime::FrameContext& frame);
  void publish_picture(std::size_t i);

  runtime::Input<msg::AircraftState>& aircraft_state_;
  runtime::Input<msg::NavigationState>& navigation_state_;
  runtime::Input<msg::AutopilotState>* autopilot_state_;  // null: --no-autopilot
  runtime::Output<msg::VisualChannelStatus>& status_out_;
  runtime::Output<msg::VisualPicture>& picture_out_;
  DisplaysSetup setup_;
  std::vector<Drawn> drawn_;
  std::uint64_t state_seen_ = 0;
  bool state_usable_ = false;
  std::int64_t last_render_slot_ = -1;
  msg::FrameStamp image_stamp_;
  picture::Image scaled_;
  std::int64_t rate_window_start_ns_ = 0;
  std::uint32_t rate_window_renders_ = 0;
  float frame_rate_hz_ = 0.0f;  // pictures per wall-clock second, last full window [Hz]
};

runtime::FederateProgram program();

}  // namespace fedsim::displays
