#include "visual/visual_component.hpp"
#include "common/util/build_paths.hpp"

#include "common/aircraft_pack/pack_facts.hpp"
#include "common/aircraft_pack/pack_path.hpp"
#include "common/frame_clock/rate_slot.hpp"
#include "common/gl/egl_context.hpp"
#include "common/hud/composite.hpp"
#include "common/navdb/nav_database.hpp"
#include "common/picture/snapshot_tag.hpp"
#include "common/units/units.hpp"
#include "common/util/cli_checks.hpp"
#include "common/util/monotonic_clock.hpp"
#include "visual/model/channel_file.hpp"
#include "visual/model/eye_extrapolation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

namespace fedsim::visual {
namespace {

std::int64_t monotonic_ns() { return static_cast<std::int64_t>(util::monotonic_ns()); }
using util::utc_ns;

MovingPose moving_pose_of(const msg::AircraftState& s) {
  MovingPose m;
  m.pose.lat_rad = s.latitude_rad();
  m.pose.lon_rad = s.longitude_rad();
  m.pose.alt_msl_m = s.altitude_msl_m();
  m.pose.phi_rad = s.phi_rad();
  m.pose.theta_rad = s.theta_rad();
  m.pose.psi_rad = s.psi_rad();
  for (int i = 0; i < 3; ++i) {
    m.velocity_ned_mps[i] = s.velocity_ned_mps()[i];
    m.omega_body_radps[i] = s.omega_body_radps()[i];
  }
  return m;
}

// UTC advanced by a span of seconds, carried over midnight (the date as the calendar has it).
UtcTime advanced(UtcTime t, double span_s) {
  t.seconds_of_day += span_s;
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  while (t.seconds_of_day >= 86400.0) {
    t.seconds_of_day -= 86400.0;
    const bool leap = (t.year % 4 == 0 && t.year % 100 != 0) || t.year % 400 == 0;
    const int days = kDays[t.month - 1] + (t.month == 2 && leap ? 1 : 0);
    if (++t.day > days) {
      t.day = 1;
      if (++t.month > 12) {
        t.month = 1;
        ++t.year;
      }
    }
  }
  return t;
}

}  // namespace

std::optional<std::string> apply_weather(const msg::WeatherSettings& w, Environment& environment) {
  Environment next = environment;
  if (!std::isfinite(w.visibility_m()) || !std::isfinite(w.cloud_base_m())) {
    return std::string("weather: visibility_m or cloud_base_m not a finite number");
  }
  if (w.visibility_m() > 0.0) next.visibility_m = w.visibility_m();
  if (w.cloud_base_m() > 0.0) {
    CloudLayer cloud;
    cloud.base_agl_m = w.cloud_base_m();
    cloud.top_agl_m = w.cloud_base_m() + 1000.0;
    next.cloud = cloud;
  } else {
    next.cloud.reset();
  }
  try {
    validate(next, "weather command");
  } catch (const std::invalid_argument& e) {
    return std::string(e.what());
  }
  environment = next;
  return std::nullopt;
}

VisualComponent::VisualComponent(std::string name, VisualSetup setup)
    : Component(std::move(name)),
      aircraft_state_(reads(runtime::topics::aircraft_state, setup.state_qos)),
      autopilot_state_(setup.hud ? &reads(runtime::topics::autopilot_state, setup.state_qos) : nullptr),
      navigation_state_(setup.hud ? &reads(runtime::topics::navigation_state, setup.state_qos) : nullptr),
      visual_status_(writes(runtime::topics::visual_status)),
      visual_picture_(writes(runtime::topics::visual_picture)),
      setup_(std::move(setup)) {
  if (!setup_.renderer) throw std::invalid_argument("fedsim-visual: no renderer");
  if (!(setup_.render_hz > 0.0 && setup_.render_hz <= 1000.0)) throw std::invalid_argument("render_hz: (0, 1000]");
  if (!(setup_.stream_hz >= 0.0 && setup_.stream_hz <= 60.0)) throw std::invalid_argument("stream_hz: [0, 60]");
  validate(setup_.channel, "fedsim-visual");
  validate(setup_.environment, "fedsim-visual");
  validate(setup_.jpeg);
  setup_.renderer->set_clock(monotonic_ns);
  status_.channel_id(setup_.channel_id);
  status_.name(setup_.channel.name);
  status_.width_px(static_cast<std::uint16_t>(setup_.channel.width_px));
  status_.height_px(static_cast<std::uint16_t>(setup_.channel.height_px));
  status_.fov_h_rad(static_cast<float>(setup_.channel.horizontal_fov_rad));
  status_.renderer(setup_.renderer->description().substr(0, 95));
  picture_.channel_id(setup_.channel_id);
  picture_.name(setup_.channel.name);
  picture_.encoding("image/jpeg");
  log().info("channel {} (id {}): {}x{} px, {:.1f} x {:.1f} deg, heading offset {:.1f} deg, eye offset "
             "[{:.3f} {:.3f} {:.3f}] m; {} images/s, {} pictures/s; {}",
             setup_.channel.name, setup_.channel_id, setup_.channel.width_px, setup_.channel.height_px,
             setup_.channel.horizontal_fov_rad * units::kRadToDeg, setup_.channel.vertical_fov_rad * units::kRadToDeg,
             setup_.channel.heading_offset_rad * units::kRadToDeg, setup_.channel.eye_offset_body_m.x(),
             setup_.channel.eye_offset_body_m.y(), setup_.channel.eye_offset_body_m.z(), setup_.render_hz,
             setup_.stream_hz, setup_.renderer->description());
  if (!setup_.gl_note.empty()) log().info("--gl auto: {}", setup_.gl_note);
}

void VisualComponent::on_command(const msg::SimCommand& command) {
  std::optional<std::string> problem;
  switch (command.kind()) {
    case msg::COMMAND_WEATHER:
      problem = apply_weather(command.weather(), setup_.environment);
      if (!problem) {
        log().info("command seq={}: visibility {:.0f} m, {}", command.sequence_number(),
                   setup_.environment.visibility_m,
                   setup_.environment.cloud ? "cloud base " + std::to_string(int(setup_.environment.cloud->base_agl_m)) + " m"
                                            : std::string("no cloud"));
      }
      break;
    case msg::COMMAND_TIME_OF_DAY: {
      const auto& t = command.time_of_day();
      UtcTime utc{t.year(), t.month(), t.day(), t.utc_time_of_day_s()};
      try {
        sun_direction(utc, 0.0, 0.0);  // checks the date and time
        setup_.time_of_day = utc;
        setup_.time_of_day_set = true;
        setup_.environment.airport_lights_on = t.airport_lights_on();
        time_of_day_epoch_sim_s_ = -1.0;  // from the next frame's sim time
        log().info("command seq={}: time of day {:04d}-{:02d}-{:02d} {:.0f} s UTC, lights {}", command.sequence_number(),
                   utc.year, utc.month, utc.day, utc.seconds_of_day, t.airport_lights_on() ? "on" : "off");
      } catch (const std::invalid_argument& e) {
        problem = std::string("time of day: ") + e.what();
      }
      break;
    }
    case msg::COMMAND_SNAPSHOT: {
      const std::string target = command.target().to_string();
      if (!target.empty() && target != setup_.channel.name) return;
      if (static_cast<std::int64_t>(command.snapshot().issued_utc_ns()) < setup_.start_utc_ns) return;  // history
      const std::string tag = command.snapshot().tag().to_string();
      problem = picture::snapshot_tag_problem(tag);
      if (!problem) pending_snapshot_ = tag;
      break;
    }
    default:
      return;
  }
  if (problem) report_fault("command_rejected", "command seq=" + std::to_string(command.sequence_number()) + ": " + *problem);
}

bool VisualComponent::render_slot(const runtime::FrameContext& frame) {
  const double period = frame.frame_period_s > 0.0 ? frame.frame_period_s : 0.02;
  const std::int64_t slot = timing::rate_slot(frame.frame, period, setup_.render_hz);
  if (slot == last_render_slot_) return false;
  last_render_slot_ = slot;
  return true;
}

void VisualComponent::update_sun(double sim_time_s, double lat_rad, double lon_rad) {
  if (!setup_.time_of_day_set) return;
  if (time_of_day_epoch_sim_s_ < 0.0) time_of_day_epoch_sim_s_ = sim_time_s;
  const UtcTime now = advanced(setup_.time_of_day, std::max(0.0, sim_time_s - time_of_day_epoch_sim_s_));
  const SunDirection sun = sun_direction(now, lat_rad, lon_rad);
  setup_.environment.sun_elevation_rad = sun.elevation_rad;
  setup_.environment.sun_azimuth_rad = sun.azimuth_rad;
}

bool VisualComponent::check_new_state(const runtime::FrameContext& frame) {
  const msg::AircraftState* state = aircraft_state_.latest();
  if (state == nullptr) return false;
  if (aircraft_state_.updates() == state_seen_) return state_usable_;
  state_seen_ = aircraft_state_.updates();
  try {
    extrapolate(moving_pose_of(*state), 0.0, "fedsim/aircraft_state");
    state_usable_ = true;
  } catch (const std::invalid_argument& e) {
    report_fault("input_rejected", "frame " + std::to_string(frame.frame) + ": " + e.what() + " (not drawn)");
    state_usable_ = false;
  }
  return state_usable_;
}

std::optional<VisualComponent::Drawn> VisualComponent::render(const runtime::FrameContext& frame) {
  const msg::AircraftState* state = aircraft_state_.latest();
  const std::int64_t start_ns = monotonic_ns();
  // Display time: the start of this frame (the state of the frame before ends there), plus in
  // realtime the time the picture takes to draw. Frozen: nothing moves.
  double span_s = 0.0;
  if (frame.running()) {
    span_s = frame.sim_time_s - state->stamp().sim_time_s();
    if (frame.mode == msg::TIMING_MODE_REALTIME) span_s += mean_render_s_;
  }
  const EyePose eye = extrapolate(moving_pose_of(*state), span_s, "fedsim/aircraft_state");
  update_sun(frame.sim_time_s, eye.lat_rad, eye.lon_rad);
  RenderStats stats = setup_.renderer->render(setup_.channel, eye, setup_.environment, image_);
  if (setup_.hud) {
    const std::int64_t hud_start_ns = monotonic_ns();
    draw_hud(*state, eye);
    stats.render_time_ms += static_cast<double>(monotonic_ns() - hud_start_ns) / 1e6;
  }
  have_image_ = true;
  image_stamp_ = state->stamp();
  ++frames_rendered_;
  mean_render_s_ = frames_rendered_ == 1 ? stats.render_time_ms / 1000.0
                                         : 0.9 * mean_render_s_ + 0.1 * stats.render_time_ms / 1000.0;
  return Drawn{stats, std::clamp(span_s, 0.0, kMaxExtrapolationS), start_ns};
}

void VisualComponent::draw_hud(const msg::AircraftState& state, const EyePose& eye) {
  hud::HudInputs in = symbology_mapping::hud_inputs(state, navigation_state_->latest(), autopilot_state_->latest(),
                                                    setup_.hud_context);
  // The attitude the scene was drawn with (carried forward to the display time), so that the
  // conformal symbols fall on the scene's horizon and runway.
  in.pitch_rad = eye.theta_rad;
  in.roll_rad = eye.phi_rad;
  in.heading_true_rad = std::fmod(eye.psi_rad + 2.0 * units::kTwoPi, units::kTwoPi);
  try {
    setup_.hud->render(in, setup_.channel, hud_image_);
    hud::composite_over(image_, hud_image_);
  } catch (const std::invalid_argument& e) {
    report_fault("input_rejected", std::string("HUD not drawn: ") + e.what());
  }
}

void VisualComponent::publish_status(const runtime::FrameContext& frame, const RenderStats& stats, double state_age_s,
                                     double step_ms) {
  const std::int64_t now = monotonic_ns();
  ++rate_window_images_;
  if (rate_window_start_ns_ == 0) rate_window_start_ns_ = now;
  if (now - rate_window_start_ns_ >= 1'000'000'000) {
    frame_rate_hz_ = static_cast<float>(rate_window_images_ * 1e9 / static_cast<double>(now - rate_window_start_ns_));
    rate_window_start_ns_ = now;
    rate_window_images_ = 0;
  }
  status_.stamp(image_stamp_);
  status_.render_time_ms(static_cast<float>(stats.render_time_ms));
  status_.latency_ms(static_cast<float>(step_ms));
  status_.frame_rate_hz(frame_rate_hz_);
  status_.state_age_ms(static_cast<float>(state_age_s * 1000.0));
  status_.frames_rendered(frames_rendered_);
  status_.snapshots_written(snapshots_written_);
  status_.pictures_sent(pictures_sent_);
  visual_status_.write(status_);
  (void)frame;
}

void VisualComponent::write_snapshot(const runtime::FrameContext& frame) {
  const std::string tag = pending_snapshot_->empty() ? "frame" + std::to_string(frame.frame) : *pending_snapshot_;
  pending_snapshot_.reset();
  const std::string path = (std::filesystem::path(setup_.snapshot_dir) / (setup_.channel.name + "_" + tag + ".png")).string();
  try {
    picture::write_png(image_, path);
    ++snapshots_written_;
    log().info("snapshot frame={} t={:.2f}s -> {}", frame.frame, frame.sim_time_s, path);
  } catch (const std::exception& e) {
    report_fault("snapshot_failed", e.what());
  }
}

void VisualComponent::publish_picture(const runtime::FrameContext& frame) {
  if (setup_.stream_hz <= 0.0 || !have_image_) return;
  const double period = frame.frame_period_s > 0.0 ? frame.frame_period_s : 0.02;
  const std::int64_t slot = timing::rate_slot(frame.frame, period, setup_.stream_hz);
  if (slot == last_stream_slot_) return;
  last_stream_slot_ = slot;
  if (setup_.jpeg.downscale > 1) scaled_ = picture::downscale(image_, setup_.jpeg.downscale);
  const picture::Image& source = setup_.jpeg.downscale > 1 ? scaled_ : image_;
  picture::encode_jpeg(source, setup_.jpeg, picture_.data());
  if (picture_.data().size() > msg::VISUAL_PICTURE_MAX_BYTES) {
    report_fault("picture_too_large", std::to_string(picture_.data().size()) + " bytes (at most " +
                                          std::to_string(msg::VISUAL_PICTURE_MAX_BYTES) +
                                          "): lower --jpeg-quality or raise --stream-downscale");
    return;
  }
  picture_.stamp(image_stamp_);
  picture_.width_px(static_cast<std::uint16_t>(source.width_px));
  picture_.height_px(static_cast<std::uint16_t>(source.height_px));
  if (visual_picture_.write(picture_)) ++pictures_sent_;
}

bool VisualComponent::capture_due() {
  if (setup_.capture_png.empty() || captured_ || aircraft_state_.updates() == capture_state_seen_) return false;
  capture_state_seen_ = aircraft_state_.updates();
  const double height_m = aircraft_state_.latest()->height_agl_m();
  if (!std::isfinite(height_m)) return false;  // a height nobody can descend through: no capture
  if (height_m > setup_.capture_agl_m) {
    capture_armed_ = true;  // a start below the height captures nothing: it never descends through it
    return false;
  }
  return capture_armed_;
}

void VisualComponent::write_capture() {
  captured_ = true;
  try {
    picture::write_png(image_, setup_.capture_png);
    log().info("at {:.0f} ft above the runway (frame {}, t={:.2f}s) -> {}", setup_.capture_agl_m * units::kMToFt,
               image_stamp_.frame(), image_stamp_.sim_time_s(), setup_.capture_png);
  } catch (const std::exception& e) {
    report_fault("snapshot_failed", e.what());
  }
}

void VisualComponent::step(const runtime::FrameContext& frame) {
  const bool usable = check_new_state(frame);  // every new sample is checked, drawn or not
  const bool slot = render_slot(frame);
  const bool snapshot = pending_snapshot_.has_value();
  const bool capture = usable && capture_due();
  if (usable && (slot || snapshot || capture || !have_image_)) {
    const Drawn drawn = *render(frame);
    if (snapshot) write_snapshot(frame);
    if (capture) write_capture();
    publish_status(frame, drawn.stats, drawn.state_age_s, static_cast<double>(monotonic_ns() - drawn.start_ns) / 1e6);
  }
  publish_picture(frame);
}

void VisualComponent::on_stop() {
  if (!setup_.capture_png.empty() && !captured_) {
    log().warn("the aircraft never descended through {:.0f} ft above the runway: {} not written",
               setup_.capture_agl_m * units::kMToFt, setup_.capture_png);
  }
  if (setup_.final_png.empty()) return;
  if (!have_image_) {
    log().warn("no image was rendered (no aircraft state arrived): {} not written", setup_.final_png);
    return;
  }
  picture::write_png(image_, setup_.final_png);
  log().info("last image (frame {}, t={:.2f}s) -> {}", image_stamp_.frame(), image_stamp_.sim_time_s(), setup_.final_png);
}

// ---- the program ----------------------------------------------------------------------------

namespace {

struct Options {
  std::string channels = fedsim::util::data_dir() + "/visual/channels.yaml";
  std::string channel = "centre";
  int channel_id = -1;
  std::string aircraft;
  std::string airport = "KSFO";
  std::vector<std::string> cat2_3;
  std::string navdb;
  double render_hz = 30.0, stream_hz = 5.0;
  int jpeg_quality = 75, stream_downscale = 2;
  std::string snapshot_dir = ".";
  std::string final_png;
  double capture_agl_ft = 0.0;
  std::string capture_png;
  double visibility_m = 20000.0, cloud_base_m = 0.0;
  std::string utc = "2026-06-21T19:00:00";
  std::string lights = "on";
  std::string state_qos;
  bool hud = false;
  std::string gl = "auto";
};

// The airport's ends: those with an ILS drawn as precision CAT I ends (markings, CAT I approach
// lights), the ends named by --cat2-3 as CAT II/III, the rest non-precision.
AirportSceneOptions scene_options(const nav::NavDatabase& db, const Options& o) {
  AirportSceneOptions options;
  options.default_end.category = ApproachCategory::kNonPrecision;
  options.default_end.approach_lighting = ApproachLighting::kNone;
  for (const nav::IlsApproach& ils : db.airport_ils(o.airport)) {
    options.ends[ils.runway] = {ApproachCategory::kPrecisionCatI, ApproachLighting::kIcaoCatI, true,
                                options.default_end.glide_path_rad};
  }
  for (const std::string& end : o.cat2_3) {
    if (!db.runway(o.airport, end)) throw std::invalid_argument("--cat2-3 " + end + ": " + o.airport + " has no such runway end");
    options.ends[end] = {ApproachCategory::kPrecisionCatIIorIII, ApproachLighting::kIcaoCatIIorIII, true,
                         options.default_end.glide_path_rad};
  }
  return options;
}

}  // namespace

runtime::FederateProgram program() {
  auto o = std::make_shared<Options>();
  runtime::FederateProgram p;
  p.program = "fedsim-visual";
  p.default_name = "visual";
  p.description = "image generator: one visual channel of the airport scene (OSMesa), status, pictures and snapshots";
  p.add_options = [o](CLI::App& app) {
    app.add_option("--channels", o->channels, "channel file (YAML, data/visual/README.md)")->capture_default_str();
    app.add_option("--channel", o->channel, "the channel of the file this process draws")->capture_default_str();
    app.add_option("--channel-id", o->channel_id, "its id on fedsim/visual_status (default: its index in the file)")
        ->check(CLI::Range(0, 65535));
    app.add_option("--aircraft", o->aircraft, "aircraft pack: the pilot's eye point (default: the CG)");
    app.add_option("--airport", o->airport, "the airport drawn (its runways from the nav database)")->capture_default_str();
    app.add_option("--cat2-3", o->cat2_3, "runway ends drawn as CAT II/III (markings, ALSF-2-like lights), e.g. 28R")
        ->delimiter(',');
    app.add_option("--navdb", o->navdb, "navigation database (default: the build's)");
    app.add_option("--render-hz", o->render_hz, "images per second (at most one per frame)")
        ->check(util::FiniteRange(0.1, 1000.0))->capture_default_str();
    app.add_option("--stream-hz", o->stream_hz, "JPEG pictures per second on fedsim/visual_picture (0: none)")
        ->check(util::FiniteRange(0.0, 60.0))->capture_default_str();
    app.add_option("--jpeg-quality", o->jpeg_quality, "JPEG quality of the pictures")->check(CLI::Range(1, 100))
        ->capture_default_str();
    app.add_option("--stream-downscale", o->stream_downscale, "pictures reduced by this factor")
        ->check(CLI::Range(1, 8))->capture_default_str();
    app.add_option("--snapshot-dir", o->snapshot_dir, "folder of `fedsim command snapshot` PNGs")->capture_default_str();
    app.add_option("--final-png", o->final_png, "write the last image here when the federate stops");
    app.add_option("--capture-agl-ft", o->capture_agl_ft,
                   "with --capture-png: the height above the runway to capture the picture at, descending "
                   "(e.g. the decision height)")
        ->check(util::FiniteRange(1.0, 10000.0));
    app.add_option("--capture-png", o->capture_png, "write the picture at --capture-agl-ft here");
    app.add_option("--visibility-m", o->visibility_m, "visibility (MOR) until a weather command")
        ->check(util::FiniteRange(10.0, 1e6))->capture_default_str();
    app.add_option("--cloud-base-m", o->cloud_base_m, "cloud base above the airport (0: no cloud)")
        ->check(util::FiniteRange(0.0, 20000.0));
    app.add_option("--utc", o->utc, "UTC date and time at sim time 0 (sun position), YYYY-MM-DDTHH:MM:SS")
        ->capture_default_str();
    app.add_option("--lights", o->lights, "airport lights")->check(CLI::IsMember({"on", "off"}))->capture_default_str();
    app.add_option("--state-qos", o->state_qos, "QoS profile of the aircraft-state reader (default: the catalogue's)");
    app.add_flag("--hud", o->hud, "draw the head-up display over the picture (the pilot's centre channel)");
    app.add_option("--gl", o->gl, "OpenGL context: osmesa (CPU), egl (a GPU's EGL device, else Mesa surfaceless), "
                                  "auto (a GPU's EGL device, else OSMesa)")
        ->check(CLI::IsMember({"osmesa", "egl", "auto"}))->capture_default_str();
  };
  p.make_component = [o](const runtime::FederateOptions& common) {
    VisualSetup setup;
    const std::vector<view::ChannelConfig> channels = load_channels(o->channels);
    const std::size_t index = channel_index(channels, o->channel, o->channels);
    setup.channel = channels[index];
    setup.channel_id = static_cast<std::uint16_t>(o->channel_id >= 0 ? o->channel_id : static_cast<int>(index));
    if (!o->aircraft.empty()) {
      setup.channel.eye_offset_body_m +=
          aircraft_pack::eye_from_cg_m(aircraft_pack::load_pack_facts(aircraft_pack::resolve_pack_path(o->aircraft)));
    }
    const nav::NavDatabase db = nav::NavDatabase::open(o->navdb.empty() ? nav::default_database_path() : o->navdb);
    const std::vector<nav::RunwayEndRecord> ends = db.airport_runways(o->airport);
    if (ends.empty()) throw std::invalid_argument("--airport " + o->airport + ": no runways in " + db.path());
    const gl::GlBackend backend = *gl::parse_gl_backend(o->gl);
    setup.renderer = std::make_unique<Renderer>(build_airport_scene(ends, scene_options(db, *o)),
                                                gl::make_gl_context(backend, &setup.gl_note));
    setup.render_hz = o->render_hz;
    setup.stream_hz = o->stream_hz;
    setup.jpeg = {o->jpeg_quality, o->stream_downscale};
    if (setup.channel.width_px < o->stream_downscale * 16 || setup.channel.height_px < o->stream_downscale * 16) {
      throw std::invalid_argument("--stream-downscale " + std::to_string(o->stream_downscale) + ": the channel is too small");
    }
    if (!std::filesystem::is_directory(o->snapshot_dir)) {
      throw std::invalid_argument("--snapshot-dir " + o->snapshot_dir + ": no such folder");
    }
    setup.snapshot_dir = o->snapshot_dir;
    setup.final_png = o->final_png;
    if (o->capture_png.empty() != (o->capture_agl_ft == 0.0)) {
      throw std::invalid_argument("--capture-png and --capture-agl-ft go together");
    }
    setup.capture_png = o->capture_png;
    setup.capture_agl_m = o->capture_agl_ft * units::kFtToM;
    setup.environment.visibility_m = o->visibility_m;
    if (o->cloud_base_m > 0.0) setup.environment.cloud = CloudLayer{o->cloud_base_m, o->cloud_base_m + 1000.0, 60.0};
    setup.environment.airport_lights_on = o->lights == "on";
    const std::optional<UtcTime> utc = parse_utc(o->utc);
    if (!utc) throw std::invalid_argument("--utc '" + o->utc + "': expected YYYY-MM-DDTHH:MM:SS (UTC, 1800-2200)");
    setup.time_of_day = *utc;
    setup.start_utc_ns = utc_ns();
    setup.state_qos = o->state_qos;
    if (o->hud) {
      setup.hud = std::make_unique<hud::HudRenderer>(gl::make_gl_context(backend), symbology::default_font_paths());
      const nav::RunwayEndRecord& first = ends.front();
      setup.hud_context.magnetic_variation_rad =
          symbology_mapping::magnetic_variation_near(db, first.threshold.lat_rad, first.threshold.lon_rad, 40.0);
    }
    return std::unique_ptr<runtime::Component>(std::make_unique<VisualComponent>(common.name, std::move(setup)));
  };
  return p;
}

}  // namespace fedsim::visual
