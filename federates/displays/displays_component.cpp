#include "displays/displays_component.hpp"

#include "common/frame_clock/rate_slot.hpp"
#include "common/gl/egl_context.hpp"
#include "common/picture/snapshot_tag.hpp"
#include "common/units/units.hpp"
#include "common/util/cli_checks.hpp"
#include "common/util/monotonic_clock.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace fedsim::displays {
namespace {

std::int64_t monotonic_ns() { return static_cast<std::int64_t>(util::monotonic_ns()); }
using util::utc_ns;

}  // namespace

DisplaysComponent::DisplaysComponent(std::string name, DisplaysSetup setup)
    : Component(std::move(name)),
      aircraft_state_(reads(runtime::topics::aircraft_state, setup.state_qos)),
      navigation_state_(reads(runtime::topics::navigation_state, setup.state_qos)),
      // Declared only where an autopilot runs: a lockstep input nobody writes would hold the
      // start for the input join timeout (and `fedsim graph` rightly calls it a problem).
      autopilot_state_(setup.read_autopilot ? &reads(runtime::topics::autopilot_state, setup.state_qos) : nullptr),
      status_out_(writes(runtime::topics::visual_status)),
      picture_out_(writes(runtime::topics::visual_picture)),
      setup_(std::move(setup)) {
  if (!setup_.renderer) throw std::invalid_argument("fedsim-displays: no renderer");
  if (setup_.displays.empty()) throw std::invalid_argument("fedsim-displays: no display to draw");
  if (!(setup_.render_hz > 0.0 && setup_.render_hz <= 1000.0)) throw std::invalid_argument("render_hz: (0, 1000]");
  if (!(setup_.stream_hz >= 0.0 && setup_.stream_hz <= 60.0)) throw std::invalid_argument("stream_hz: [0, 60]");
  if (!(setup_.nd_range_nm >= 5.0 && setup_.nd_range_nm <= 640.0)) throw std::invalid_argument("nd_range_nm: [5, 640]");
  picture::validate(setup_.jpeg);
  setup_.renderer->set_clock(monotonic_ns);
  const std::string renderer = setup_.renderer->description().substr(0, 95);
  drawn_.resize(setup_.displays.size());
  for (std::size_t i = 0; i < drawn_.size(); ++i) {
    const DisplaySpec& d = setup_.displays[i];
    if (d.width_px < 16 * setup_.jpeg.downscale || d.height_px < 16 * setup_.jpeg.downscale) {
      throw std::invalid_argument("display " + d.name + ": smaller than 16 px after the stream's downscale");
    }
    msg::VisualChannelStatus& s = drawn_[i].status;
    s.channel_id(d.id);
    s.name(d.name);
    s.width_px(static_cast<std::uint16_t>(d.width_px));
    s.height_px(static_cast<std::uint16_t>(d.height_px));
    s.fov_h_rad(0.0f);
    s.renderer(renderer);
    drawn_[i].picture.channel_id(d.id);
    drawn_[i].picture.name(d.name);
    drawn_[i].picture.encoding("image/jpeg");
    log().info("display {} (id {}): {}x{} px", d.name, d.id, d.width_px, d.height_px);
  }
  log().info("{} pictures/s, {} JPEGs/s, ND range {} NM, navaids {}; {}", setup_.render_hz, setup_.stream_hz,
             setup_.nd_range_nm, setup_.navdb ? setup_.navdb->path() : std::string("none"), renderer);
  if (!setup_.gl_note.empty()) log().info("--gl auto: {}", setup_.gl_note);
}

void DisplaysComponent::on_command(const msg::SimCommand& command) {
  if (command.kind() != msg::COMMAND_SNAPSHOT) return;
  if (static_cast<std::int64_t>(command.snapshot().issued_utc_ns()) < setup_.start_utc_ns) return;  // history
  const std::string target = command.target().to_string();
  const std::string tag = command.snapshot().tag().to_string();
  bool mine = false;
  for (std::size_t i = 0; i < drawn_.size(); ++i) {
    if (!target.empty() && target != setup_.displays[i].name) continue;
    mine = true;
    if (const auto problem = picture::snapshot_tag_problem(tag)) {
      report_fault("command_rejected", "command seq=" + std::to_string(command.sequence_number()) + ": " + *problem);
      return;
    }
    drawn_[i].pending_snapshot = tag;
  }
  (void)mine;
}

bool DisplaysComponent::slot(const runtime::FrameContext& frame, double hz, std::int64_t& last) const {
  const double period = frame.frame_period_s > 0.0 ? frame.frame_period_s : 0.02;
  const std::int64_t n = timing::rate_slot(frame.frame, period, hz);
  if (n == last) return false;
  last = n;
  return true;
}

bool DisplaysComponent::check_new_state(const runtime::FrameContext& frame) {
  const msg::AircraftState* state = aircraft_state_.latest();
  if (state == nullptr) return false;
  if (aircraft_state_.updates() == state_seen_) return state_usable_;
  state_seen_ = aircraft_state_.updates();
  const std::string problem = aircraft_state_problem(*state);
  state_usable_ = problem.empty();
  if (!state_usable_) {
    report_fault("input_rejected", "frame " + std::to_string(frame.frame) + ": fedsim/aircraft_state " + problem +
                                       " (not drawn)");
  }
  return state_usable_;
}

void DisplaysComponent::render_all(const runtime::FrameContext& frame) {
  const msg::AircraftState& state = *aircraft_state_.latest();
  symbology_mapping::DisplayContext context;
  std::vector<Navaid> navaids;
  if (setup_.navdb) {
    NearbyNavaids near = nearby_navaids(*setup_.navdb, state.latitude_rad(), state.longitude_rad(), setup_.nd_range_nm);
    context.magnetic_variation_rad = near.magnetic_variation_rad;
    navaids = std::move(near.navaids);
  }
  const msg::NavigationState* nav = navigation_state_.latest();
  const msg::AutopilotState* autopilot = autopilot_state_ ? autopilot_state_->latest() : nullptr;
  image_stamp_ = state.stamp();
  // Pictures per wall-clock second, over windows of at least a second (as fedsim-visual's).
  const std::int64_t now_ns = monotonic_ns();
  ++rate_window_renders_;
  if (rate_window_start_ns_ == 0) rate_window_start_ns_ = now_ns;
  if (now_ns - rate_window_start_ns_ >= 1'000'000'000) {
    frame_rate_hz_ = static_cast<float>(rate_window_renders_ * 1e9 / static_cast<double>(now_ns - rate_window_start_ns_));
    rate_window_start_ns_ = now_ns;
    rate_window_renders_ = 0;
  }
  for (std::size_t i = 0; i < drawn_.size(); ++i) {
    const DisplaySpec& d = setup_.displays[i];
    Drawn& out = drawn_[i];
    const std::int64_t start = monotonic_ns();
    DisplayStats stats;
    try {
      if (d.kind == DisplayKind::kPfd) {
        stats = setup_.renderer->render_pfd(pfd_inputs(state, nav, autopilot, context), d.width_px, d.height_px, out.image);
      } else {
        stats = setup_.renderer->render_nd(nd_inputs(state, nav, context, navaids, setup_.nd_range_nm), d.width_px,
                                           d.height_px, out.image);
      }
    } catch (const std::invalid_argument& e) {
      // A value the mapping let through and the model refuses: named, the last picture stays.
      report_fault("input_rejected", "frame " + std::to_string(frame.frame) + ": " + d.name + ": " + e.what());
      continue;
    }
    out.have = true;
    ++out.frames;
    if (out.pending_snapshot) write_snapshot(i, frame);
    out.status.stamp(image_stamp_);
    out.status.render_time_ms(static_cast<float>(stats.render_time_ms));
    out.status.latency_ms(static_cast<float>(static_cast<double>(monotonic_ns() - start) / 1e6));
    out.status.frame_rate_hz(frame_rate_hz_);
    out.status.state_age_ms(static_cast<float>(std::max(0.0, frame.sim_time_s - state.stamp().sim_time_s()) * 1000.0));
    out.status.frames_rendered(out.frames);
    out.status.snapshots_written(out.snapshots);
    out.status.pictures_sent(out.pictures);
    status_out_.write(out.status);
  }
}

void DisplaysComponent::write_snapshot(std::size_t i, const runtime::FrameContext& frame) {
  Drawn& out = drawn_[i];
  const std::string tag = out.pending_snapshot->empty() ? "frame" + std::to_string(frame.frame) : *out.pending_snapshot;
  out.pending_snapshot.reset();
  const std::string path =
      (std::filesystem::path(setup_.snapshot_dir) / (setup_.displays[i].name + "_" + tag + ".png")).string();
  try {
    picture::write_png(out.image, path);
    ++out.snapshots;
    log().info("snapshot frame={} t={:.2f}s -> {}", frame.frame, frame.sim_time_s, path);
  } catch (const std::exception& e) {
    report_fault("snapshot_failed", e.what());
  }
}

void DisplaysComponent::publish_picture(std::size_t i) {
  Drawn& out = drawn_[i];
  const picture::Image& source = setup_.jpeg.downscale > 1 ? (scaled_ = picture::downscale(out.image, setup_.jpeg.downscale))
                                                          : out.image;
  picture::encode_jpeg(source, setup_.jpeg, out.picture.data());
  if (out.picture.data().size() > msg::VISUAL_PICTURE_MAX_BYTES) {
    report_fault("picture_too_large", setup_.displays[i].name + ": " + std::to_string(out.picture.data().size()) +
                                          " bytes: lower --jpeg-quality or raise --stream-downscale");
    return;
  }
  out.picture.stamp(image_stamp_);
  out.picture.width_px(static_cast<std::uint16_t>(source.width_px));
  out.picture.height_px(static_cast<std::uint16_t>(source.height_px));
  if (picture_out_.write(out.picture)) ++out.pictures;
}

void DisplaysComponent::step(const runtime::FrameContext& frame) {
  const bool usable = check_new_state(frame);
  const bool render = slot(frame, setup_.render_hz, last_render_slot_);
  bool snapshot = false, first = false;
  for (const Drawn& d : drawn_) {
    snapshot = snapshot || d.pending_snapshot.has_value();
    first = first || !d.have;
  }
  if (usable && (render || snapshot || first)) render_all(frame);
  if (setup_.stream_hz <= 0.0) return;
  for (std::size_t i = 0; i < drawn_.size(); ++i) {
    if (drawn_[i].have && slot(frame, setup_.stream_hz, drawn_[i].last_stream_slot)) publish_picture(i);
  }
}

void DisplaysComponent::on_stop() {
  if (setup_.final_png_dir.empty()) return;
  try {
    std::filesystem::create_directories(setup_.final_png_dir);  // made when needed (fedsim run's out folder)
  } catch (const std::exception& e) {
    report_fault("final_png_failed", e.what());
    return;
  }
  for (std::size_t i = 0; i < drawn_.size(); ++i) {
    const std::string path = (std::filesystem::path(setup_.final_png_dir) / (setup_.displays[i].name + ".png")).string();
    if (!drawn_[i].have) {
      log().warn("display {}: nothing drawn (no usable aircraft state arrived): {} not written", setup_.displays[i].name,
                 path);
      continue;
    }
    try {
      picture::write_png(drawn_[i].image, path);
    } catch (const std::exception& e) {
      report_fault("final_png_failed", e.what());
      continue;
    }
    log().info("display {}: last picture (frame {}, t={:.2f}s) -> {}", setup_.displays[i].name, image_stamp_.frame(),
               image_stamp_.sim_time_s(), path);
  }
}

// ---- the program ----------------------------------------------------------------------------

namespace {

struct Options {
  std::vector<std::string> displays{"pfd", "nd"};
  int width_px = 400, height_px = 400;
  int channel_id_base = 100;
  double render_hz = 10.0, stream_hz = 2.0;
  int jpeg_quality = 80, stream_downscale = 1;
  int samples = DisplayRenderer::kDefaultSamples;
  double nd_range_nm = 40.0;
  std::string navdb;
  bool no_navdb = false;
  std::string snapshot_dir = ".";
  std::string final_png_dir;
  std::string state_qos;
  bool no_autopilot = false;
  std::string gl = "auto";
};

}  // namespace

runtime::FederateProgram program() {
  auto o = std::make_shared<Options>();
  runtime::FederateProgram p;
  p.program = "fedsim-displays";
  p.default_name = "displays";
  p.description = "cockpit displays: the PFD and ND drawn from the aircraft, navigation and autopilot states "
                  "(OSMesa), status, pictures and snapshots";
  p.add_options = [o](CLI::App& app) {
    app.add_option("--displays", o->displays, "the displays drawn, in order")
        ->delimiter(',')->check(CLI::IsMember({"pfd", "nd"}))->capture_default_str();
    app.add_option("--width-px", o->width_px, "each display's width")->check(CLI::Range(64, 2048))->capture_default_str();
    app.add_option("--height-px", o->height_px, "each display's height")->check(CLI::Range(64, 2048))->capture_default_str();
    app.add_option("--channel-id", o->channel_id_base,
                   "key of the first display on fedsim/visual_status and fedsim/visual_picture (the next: +1)")
        ->check(CLI::Range(0, 65000))->capture_default_str();
    app.add_option("--render-hz", o->render_hz, "pictures per second of frames (at most one per frame)")
        ->check(util::FiniteRange(0.1, 1000.0))->capture_default_str();
    app.add_option("--stream-hz", o->stream_hz, "JPEGs per second on fedsim/visual_picture (0: none)")
        ->check(util::FiniteRange(0.0, 60.0))->capture_default_str();
    app.add_option("--jpeg-quality", o->jpeg_quality, "JPEG quality")->check(CLI::Range(1, 100))->capture_default_str();
    app.add_option("--stream-downscale", o->stream_downscale, "JPEGs reduced by this factor")
        ->check(CLI::Range(1, 8))->capture_default_str();
    app.add_option("--samples", o->samples, "multisampling (1, 2 or 4)")->check(CLI::IsMember({1, 2, 4}))
        ->capture_default_str();
    app.add_option("--nd-range-nm", o->nd_range_nm, "the ND's range (the rose's radius)")
        ->check(util::FiniteRange(5.0, 640.0))->capture_default_str();
    app.add_option("--navdb", o->navdb, "navigation database: the ND's navaids, the magnetic variation (default: the build's)");
    app.add_flag("--no-navdb", o->no_navdb, "no navaids on the ND, headings true (variation 0)");
    app.add_option("--snapshot-dir", o->snapshot_dir, "folder of `fedsim command snapshot` PNGs")->capture_default_str();
    app.add_option("--final-png-dir", o->final_png_dir, "write each display's last picture here on stop (<name>.png; the folder is made if missing)");
    app.add_option("--state-qos", o->state_qos, "QoS profile of the three state readers (default: the catalogue's)");
    app.add_flag("--no-autopilot", o->no_autopilot,
                 "the deployment has no autopilot: fedsim/autopilot_state is not read (no FMA, no FD bars)");
    app.add_option("--gl", o->gl, "OpenGL context: osmesa (CPU), egl (a GPU's EGL device, else Mesa surfaceless), "
                                  "auto (a GPU's EGL device, else OSMesa)")
        ->check(CLI::IsMember({"osmesa", "egl", "auto"}))->capture_default_str();
  };
  p.make_component = [o](const runtime::FederateOptions& common) {
    DisplaysSetup setup;
    std::vector<std::string> seen;
    for (std::size_t i = 0; i < o->displays.size(); ++i) {
      const std::string& name = o->displays[i];
      if (std::find(seen.begin(), seen.end(), name) != seen.end()) {
        throw std::invalid_argument("--displays: '" + name + "' named twice");
      }
      seen.push_back(name);
      DisplaySpec d;
      d.kind = name == "pfd" ? DisplayKind::kPfd : DisplayKind::kNd;
      d.name = name;
      d.id = static_cast<std::uint16_t>(o->channel_id_base + static_cast<int>(i));
      d.width_px = o->width_px;
      d.height_px = o->height_px;
      setup.displays.push_back(d);
    }
    if (setup.displays.empty()) throw std::invalid_argument("--displays: at least one of pfd, nd");
    if (!std::filesystem::is_directory(o->snapshot_dir)) {
      throw std::invalid_argument("--snapshot-dir " + o->snapshot_dir + ": no such folder");
    }
    setup.render_hz = o->render_hz;
    setup.stream_hz = o->stream_hz;
    setup.jpeg = {o->jpeg_quality, o->stream_downscale};
    setup.nd_range_nm = o->nd_range_nm;
    if (!o->no_navdb) {
      setup.navdb = std::make_shared<const nav::NavDatabase>(
          nav::NavDatabase::open(o->navdb.empty() ? nav::default_database_path() : o->navdb));
    }
    setup.snapshot_dir = o->snapshot_dir;
    setup.final_png_dir = o->final_png_dir;
    setup.start_utc_ns = utc_ns();
    setup.state_qos = o->state_qos;
    setup.read_autopilot = !o->no_autopilot;
    setup.renderer = std::make_unique<DisplayRenderer>(
        gl::make_gl_context(*gl::parse_gl_backend(o->gl), &setup.gl_note), symbology::default_font_paths(), o->samples);
    return std::unique_ptr<runtime::Component>(std::make_unique<DisplaysComponent>(common.name, std::move(setup)));
  };
  return p;
}

}  // namespace fedsim::displays
