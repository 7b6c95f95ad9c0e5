#include "ios/ios_station.hpp"
#include "common/util/build_paths.hpp"

#include "common/instructor/request_json.hpp"
#include "common/navdb/nav_database.hpp"
#include "common/runtime/sim_command_codec.hpp"
#include "common/util/cli_checks.hpp"
#include "common/util/monotonic_clock.hpp"
#include "ios/model/access_policy.hpp"
#include "ios/model/command_tracker.hpp"
#include "ios/model/live_fields.hpp"
#include "ios/model/map_layers.hpp"
#include "ios/station_replay.hpp"
#include "ios/station_scenario.hpp"
#include "common/util/config_node.hpp"
#include "tools/topic/typed_flattener.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

namespace fedsim::ios {

namespace {

using nlohmann::json;

double clock_s() { return static_cast<double>(util::monotonic_ns()) * 1e-9; }

/// Lets through what the page can use of a topic written every frame: the first sample of a
/// window of `period_s`, and the samples that arrive with it (the other engines' or channels'
/// instances of the same frame, within `burst_s`).
class RateGate {
 public:
  explicit RateGate(double period_s, double burst_s = 0.002) : period_s_(period_s), burst_s_(burst_s) {}
  bool admit(double now_s) {
    if (now_s - window_start_s_ >= period_s_) {
      window_start_s_ = now_s;
      return true;
    }
    return now_s - window_start_s_ < burst_s_;
  }

 private:
  double period_s_, burst_s_;
  double window_start_s_ = -1e9;
};

/// Everything the threads share, under one mutex.
struct Shared {
  std::mutex mutex;
  LiveFields fields;
  CommandTracker tracker;
  struct Federate {
    int state = 0;
    std::string message;
    std::uint64_t frames = 0, overruns = 0, late_inputs = 0, faults = 0;
    double compute_mean_us = 0, compute_max_us = 0, uptime_s = 0;
  };
  std::map<std::string, Federate> federates;
  struct Picture {
    std::string name;
    std::string encoding;
    std::string data;
    std::uint64_t frame = 0;
    std::uint64_t count = 0;
    int width = 0, height = 0;
  };
  std::map<int, Picture> pictures;
  std::map<std::string, std::string> settings;  // "weather" -> describe(...)
  std::uint32_t next_sequence = 1;
  std::uint64_t pushes = 0;
  double first_push_s = 0.0, last_push_s = 0.0;

  FieldLookup lookup() {
    return [this](const std::string& topic, const std::string& field) { return fields.value(topic, field); };
  }
};

/// Takes the samples a monitor port receives into the registry, flattened as the recorder
/// flattens them, at most a few times a second (RateGate).
template <class T>
class FieldTap {
 public:
  FieldTap(const runtime::Topic<T>& topic, Shared& shared, double period_s)
      : topic_name_(topic.name()), shared_(shared), gate_(period_s), flattener_(topic) {}

  void take(const T& sample) {
    std::lock_guard tap_lock(tap_mutex_);
    const double now = clock_s();
    if (!gate_.admit(now)) return;
    std::vector<std::string> cells;
    try {
      cells = flattener_.cells(sample);
    } catch (const std::exception&) {
      return;  // a sample the IDL's type cannot carry: nothing to show
    }
    const std::string instance = instance_name(topic_name_, flattener_.names(), cells);
    std::lock_guard lock(shared_.mutex);
    shared_.fields.update(instance, flattener_.names(), cells, now);
  }


 private:
  std::string topic_name_;
  Shared& shared_;
  RateGate gate_;
  std::mutex tap_mutex_;
  tools::TypedFlattener<T> flattener_;
};

const char* federate_state_name(int s) {
  static const char* kNames[] = {"starting", "ready", "running", "stopping", "failed", "lost"};
  return s >= 0 && s < 6 ? kNames[s] : "?";
}

const char* run_state_name(double s) { return s == 0 ? "run" : s == 1 ? "freeze" : s == 2 ? "reset" : "?"; }

std::string settings_key(const msg::SimCommand& c) {
  switch (c.kind()) {
    case msg::COMMAND_RUN_STATE: return "run state";
    case msg::COMMAND_REPOSITION: return "reposition";
    case msg::COMMAND_WEATHER: return "weather";
    case msg::COMMAND_FAILURE: return "failure " + c.target().to_string();
    case msg::COMMAND_RADIO_TUNING: return "radios";
    case msg::COMMAND_TIME_OF_DAY: return "time of day";
    case msg::COMMAND_SNAPSHOT: return "snapshot";
    case msg::COMMAND_SHUTDOWN: return "shutdown";
  }
  return "other";
}

/// The whole live picture as one JSON text (what every push carries).
std::string state_message(Shared& s, double now_s, const ServerStatistics& server, double push_hz,
                          const StationReplay* replay, const json& scenario) {
  json out;
  out["type"] = "state";
  out["wall_s"] = now_s;
  out["topics"] = json::parse(s.fields.to_json());
  json timing = json::object();
  if (const auto f = s.fields.value("timing", "frame")) timing["frame"] = *f;
  if (const auto t = s.fields.value("timing", "sim_time_s")) timing["sim_time_s"] = *t;
  if (const auto r = s.fields.value("timing", "run_state")) timing["run_state"] = run_state_name(*r);
  if (const auto m = s.fields.value("timing", "mode")) timing["mode"] = *m == 0 ? "realtime" : "lockstep";
  if (const auto p = s.fields.value("timing", "frame_period_s")) timing["rate_hz"] = *p > 0 ? 1.0 / *p : 0.0;
  out["timing"] = timing;
  json federates = json::array();
  for (const auto& [name, f] : s.federates) {
    federates.push_back({{"name", name}, {"state", federate_state_name(f.state)}, {"message", f.message},
                         {"frames", f.frames}, {"overruns", f.overruns}, {"late_inputs", f.late_inputs},
                         {"faults", f.faults}, {"compute_mean_us", f.compute_mean_us},
                         {"compute_max_us", f.compute_max_us}, {"uptime_s", f.uptime_s}});
  }
  out["federates"] = federates;
  json pictures = json::array();
  for (const auto& [id, p] : s.pictures) {
    pictures.push_back({{"channel_id", id}, {"name", p.name}, {"count", p.count}, {"frame", p.frame},
                        {"width", p.width}, {"height", p.height}});
  }
  out["pictures"] = pictures;
  json commands = json::array();
  for (const auto& c : s.tracker.commands()) {
    commands.push_back({{"sequence", c.sequence}, {"text", c.text}, {"status", status_name(c.status)},
                        {"evidence", c.evidence}, {"age_s", now_s - c.sent_s}});
  }
  out["commands"] = commands;
  out["settings"] = s.settings;
  if (replay) out["replay"] = replay->state();
  out["scenario"] = scenario;
  const double span = s.last_push_s - s.first_push_s;
  out["server"] = {{"clients", server.clients}, {"pushes", s.pushes}, {"push_hz", push_hz},
                   {"push_hz_measured", s.pushes > 1 && span > 0 ? (s.pushes - 1) / span : 0.0},
                   {"bytes_sent", server.bytes_sent}, {"refused", server.refused}};
  return out.dump();
}

json error_body(const std::string& what) { return json{{"error", what}}; }

/// The station: its ports, the server and the pusher.
class Station final : public runtime::Component {
 public:
  explicit Station(const StationOptions& options)
      : Component(options.federate.name),
        options_(options),
        server_(options.server),
        scenario_(options.scenarios.empty() ? std::filesystem::path(fedsim::util::data_dir()) / "scenarios"
                                            : std::filesystem::path(options.scenarios)),
        commands_(writes(runtime::topics::sim_command)),
        replay_port_(writes(runtime::topics::replay_state)) {
    // Before anything joins the federation: a public address without a token exits 2.
    if (const std::string problem = bind_problem(options_.server.bind_address, options_.server.token);
        !problem.empty()) {
      throw ServerError(problem);
    }
    declare_monitors();
    register_routes();
    server_.set_greeting([this] { return current_state(); });
  }

  ~Station() override { stop_serving(); }

  // Over DDS the replay gets the host's participant (a recording is read back through dynamic
  // types, which no catalogue port carries); in-process there is none, and no replay.
  void on_start(const runtime::HostServices& host) override {
    db_.emplace(nav::NavDatabase::open(options_.navdb_file.empty() ? nav::default_database_path() : options_.navdb_file));
    server_.start();  // a port in use or a missing page: the station does not run
    announce();
    if (host.dds) {
      replay_ = std::make_unique<StationReplay>(host.dds, options_.ring_minutes * 60.0, options_.recordings,
                                                [this] { return tick_frame_.load(); });
    } else {
      started_in_process_ = true;
    }
    {
      std::lock_guard lock(publish_mutex_);
      accepting_commands_ = true;
    }
    pusher_ = std::thread([this] { push_loop(); });
  }

  void on_command(const msg::SimCommand& command) override { note_setting(command); }

  void step(const runtime::FrameContext& frame) override {
    note_frame(frame);
    send_pending_commands();
  }

  void on_stop() override {
    stop_serving();
    replay_.reset();
    print_summary();
  }

 private:
  void announce() {
    std::cout << "fedsim-ios: instructor station at " << server_.url() << std::endl;
    if (!options_.port_file.empty()) {
      std::ofstream(options_.port_file) << server_.port() << "\n";
    }
  }

  /// Stops the pusher and the page (the page can no longer send once the station stops).
  void stop_serving() {
    stopping_.store(true);
    wake_.notify_all();
    if (pusher_.joinable()) pusher_.join();
    {
      std::lock_guard lock(publish_mutex_);
      accepting_commands_ = false;
    }
    server_.stop();
  }

  template <class T>
  void tap(const runtime::Topic<T>& topic, std::string_view qos = runtime::qos::kState) {
    auto field_tap = std::make_shared<FieldTap<T>>(topic, shared_, 1.0 / (2.0 * options_.push_hz));
    monitors(topic, qos).on_arrival([field_tap](const T& sample, const runtime::WriterId&) { field_tap->take(sample); });
  }

  /// The topics the page shows, read as monitors (best effort, keep last 1 where the topic
  /// allows: they never hold a frame back), every sample as it arrives (a few a second kept).
  void declare_monitors() {
    namespace topics = runtime::topics;
    tap(topics::aircraft_state);
    tap(topics::engine_state);
    tap(topics::navigation_state);
    tap(topics::autopilot_state);
    tap(topics::motion_state);
    tap(topics::control_loading_state);
    tap(topics::visual_status);
    tap(topics::pilot_controls, runtime::qos::kPilotControls);  // its writer's exclusive ownership
    monitors(topics::visual_picture, runtime::qos::kPicture)
        .on_arrival([this](const msg::VisualPicture& p, const runtime::WriterId&) { note_picture(p); });
    monitors(topics::federate_status, runtime::qos::kStatus)
        .on_arrival([this](const msg::FederateStatus& s, const runtime::WriterId&) { note_status(s); });
  }

  // The frame thread only stores the tick (no lock: a push being built never holds a frame).
  void note_frame(const runtime::FrameContext& f) {
    tick_frame_.store(f.frame, std::memory_order_relaxed);
    tick_sim_time_s_.store(f.sim_time_s, std::memory_order_relaxed);
    tick_run_state_.store(static_cast<int>(f.run_state), std::memory_order_relaxed);
    tick_mode_.store(static_cast<int>(f.mode), std::memory_order_relaxed);
    tick_period_s_.store(f.frame_period_s, std::memory_order_relaxed);
    ticks_.fetch_add(1, std::memory_order_release);
    if (scenario_.running()) run_scenario(f);
  }

  /// The station's "timing" view in the registry, from the newest tick (under shared_.mutex).
  void copy_tick_locked(double now) {
    if (ticks_.load(std::memory_order_acquire) == 0) return;
    shared_.fields.set("timing", "frame", static_cast<double>(tick_frame_.load()), now);
    shared_.fields.set("timing", "sim_time_s", tick_sim_time_s_.load(), now);
    shared_.fields.set("timing", "run_state", tick_run_state_.load(), now);
    shared_.fields.set("timing", "mode", tick_mode_.load(), now);
    shared_.fields.set("timing", "frame_period_s", tick_period_s_.load(), now);
  }

  /// The page's scenario, one frame: stepped with the registry if it is free at once, its
  /// commands sent afterwards (send_request takes the registry itself).
  void run_scenario(const runtime::FrameContext& f) {
    const auto actions = scenario_.frame(f.sim_time_s, f.frame_period_s, [this](const auto& step) {
      std::unique_lock lock(shared_.mutex, std::try_to_lock);
      if (!lock) return false;
      step(shared_.lookup());
      return true;
    });
    for (const auto& a : actions) {
      if (a.kind == scenario::Action::Kind::kLog) {
        log().info("scenario t={:.2f}s (line {}): {}", f.sim_time_s, a.line, a.text);
        continue;
      }
      const instructor::InstructorRequest request =
          a.kind == scenario::Action::Kind::kStop ? instructor::InstructorRequest(instructor::ShutdownRequest{}) : a.command;
      send_request(request, "scenario line " + std::to_string(a.line));
    }
  }

  HttpResponse scenario_request(const HttpRequest& r) {
    json body;
    try {
      body = json::parse(r.body);
    } catch (const json::parse_error& e) {
      return {400, "application/json", error_body(std::string("the request is not JSON: ") + e.what()).dump()};
    }
    const std::string action = body.value("action", std::string());
    if (action == "stop") {
      scenario_.stop();
      return {200, "application/json", json{{"running", false}}.dump()};
    }
    if (action != "start") return {400, "application/json", error_body("scenario: action start or stop").dump()};
    const std::string name = body.value("name", std::string());
    try {
      scenario_.start(name);
    } catch (const std::invalid_argument& e) {
      return {400, "application/json", error_body(e.what()).dump()};
    }
    log().info("scenario {} started from {}", name, r.remote_address);
    return {200, "application/json", json{{"running", true}, {"name", name}}.dump()};
  }

  void note_status(const msg::FederateStatus& s) {
    std::lock_guard lock(shared_.mutex);
    auto& f = shared_.federates[s.federate().to_string()];
    f.state = static_cast<int>(s.state());
    f.message = s.message().to_string();
    f.frames = s.frames_done();
    f.overruns = s.overruns();
    f.late_inputs = s.late_inputs();
    f.faults = s.faults();
    f.compute_mean_us = s.compute_mean_us();
    f.compute_max_us = s.compute_max_us();
    f.uptime_s = s.uptime_s();
  }

  void note_picture(const msg::VisualPicture& p) {
    std::lock_guard lock(shared_.mutex);
    auto& pic = shared_.pictures[p.channel_id()];
    pic.name = p.name().to_string();
    pic.encoding = p.encoding().to_string();
    pic.data.assign(p.data().begin(), p.data().end());
    pic.frame = p.stamp().frame();
    pic.width = p.width_px();
    pic.height = p.height_px();
    ++pic.count;
  }

  void note_setting(const msg::SimCommand& c) {
    const auto request = runtime::from_sim_command(c);
    if (!request) return;
    std::lock_guard lock(shared_.mutex);
    shared_.settings[settings_key(c)] = instructor::describe(*request) + " (from " + c.issuer().to_string() + ")";
  }

  void push_loop() {
    const auto period = std::chrono::duration<double>(1.0 / options_.push_hz);
    auto next = std::chrono::steady_clock::now();
    std::unique_lock wait_lock(wake_mutex_);
    while (!stopping_.load()) {
      next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
      wake_.wait_until(wait_lock, next, [this] { return stopping_.load(); });
      if (stopping_.load()) break;
      std::string message;
      const ServerStatistics statistics = server_.statistics();  // before shared_.mutex: one lock order
      const json scenario = scenario_.state();                  // likewise
      {
        std::lock_guard lock(shared_.mutex);
        const double now = clock_s();
        copy_tick_locked(now);
        for (const auto& c : shared_.tracker.update(now, shared_.lookup())) {
          log().info("command {} '{}': {} ({})", c.sequence, c.text, status_name(c.status), c.evidence);
        }
        if (shared_.pushes == 0) shared_.first_push_s = now;
        shared_.last_push_s = now;
        ++shared_.pushes;
        message = state_message(shared_, now, statistics, options_.push_hz, replay_.get(), scenario);
      }
      server_.broadcast(message);
    }
  }

  /// Publishes `command` (tracked until the federation confirms it); false if not connected.
  /// Takes shared_.mutex: the caller must not hold it.
  bool send_request(const instructor::InstructorRequest& command, const std::string& from,
                    std::optional<ExpectedPosition> expected = std::nullopt, std::uint32_t* sequence_out = nullptr) {
    msg::SimCommand sample = runtime::to_sim_command(command);
    sample.issuer(options_.federate.name);
    std::uint32_t sequence = 0;
    {
      std::lock_guard lock(shared_.mutex);
      copy_tick_locked(clock_s());
      sequence = shared_.next_sequence++;
      shared_.tracker.sent(sequence, command, clock_s(), shared_.lookup(), expected);
    }
    sample.sequence_number(sequence);
    if (sequence_out) *sequence_out = sequence;
    {
      std::lock_guard lock(publish_mutex_);
      if (!accepting_commands_) return false;
      pending_commands_.push_back(sample);
    }
    log().info("command {} from {}: {}", sequence, from, instructor::describe(command));
    return true;
  }

  /// On the frame thread: what the page and the page's scenario asked since the last frame goes
  /// out on the command port (a host's ports are written from its frame thread).
  void send_pending_commands() {
    {
      std::lock_guard lock(publish_mutex_);
      sending_.swap(pending_commands_);
    }
    for (const auto& sample : sending_) {
      if (!commands_.write(sample)) log().error("command {} was refused by the middleware", sample.sequence_number());
    }
    sending_.clear();
  }

  HttpResponse send_command(const HttpRequest& request) {
    instructor::InstructorRequest command;
    try {
      command = instructor::request_from_json_text(request.body);
    } catch (const instructor::RequestError& e) {
      return {400, "application/json", error_body(e.what()).dump()};
    }
    std::optional<ExpectedPosition> expected;
    if (const auto* r = std::get_if<instructor::RepositionRequest>(&command);
        r && r->kind != instructor::RepositionRequest::Kind::kPoint) {
      expected = expected_position(*db_, r->airport, r->runway, r->gate_distance_m);
      if (!expected) {
        return {400, "application/json",
                error_body("reposition: no runway " + r->runway + " at " + r->airport + " in the navigation database").dump()};
      }
    }
    std::uint32_t sequence = 0;
    if (!send_request(command, request.remote_address, expected, &sequence)) {
      return {503, "application/json", error_body("the station is not connected to the federation").dump()};
    }
    return {200, "application/json", json{{"sequence", sequence}, {"text", instructor::describe(command)}}.dump()};
  }

  void register_routes() {
    server_.handle("POST", "/api/command", [this](const HttpRequest& r) { return send_command(r); });
    server_.handle("GET", "/api/state", [this](const HttpRequest&) {
      return HttpResponse{200, "application/json", current_state()};
    });
    server_.handle("GET", "/api/map", [this](const HttpRequest& r) {
      std::string airport = r.parameter("airport");
      if (airport.empty()) airport = options_.airport;
      const std::string radius = r.parameter("radius_nm");
      double radius_nm = options_.map_radius_nm;
      if (!radius.empty()) {
        char* end = nullptr;
        radius_nm = std::strtod(radius.c_str(), &end);
        if (end == radius.c_str() || *end != '\0') {
          return HttpResponse{400, "application/json", error_body("radius_nm '" + radius + "' is not a number").dump()};
        }
      }
      try {
        return HttpResponse{200, "application/json", map_json(*db_, airport, radius_nm)};
      } catch (const std::invalid_argument& e) {
        return HttpResponse{404, "application/json", error_body(e.what()).dump()};
      }
    });
    server_.handle("GET", "/api/picture", [this](const HttpRequest& r) {
      const std::string channel = r.parameter("channel");
      std::lock_guard lock(shared_.mutex);
      for (const auto& [id, p] : shared_.pictures) {
        if (channel.empty() || channel == std::to_string(id) || channel == p.name) {
          return HttpResponse{200, p.encoding.empty() ? "image/jpeg" : p.encoding, p.data};
        }
      }
      return HttpResponse{404, "application/json", error_body("no picture from channel '" + channel + "' yet").dump()};
    });
    server_.handle("POST", "/api/replay", [this](const HttpRequest& r) {
      if (!replay_) {
        return HttpResponse{503, "application/json",
                            error_body(started_in_process_ ? "a replay needs a live DDS federation (this run is in-process)"
                                                           : "the station is not connected yet")
                                .dump()};
      }
      json body;
      try {
        body = json::parse(r.body);
      } catch (const json::parse_error& e) {
        return HttpResponse{400, "application/json", error_body(std::string("the request is not JSON: ") + e.what()).dump()};
      }
      try {
        const json reply = replay_->request(body);
        log().info("replay from {}: {}", r.remote_address, body.dump());
        return HttpResponse{200, "application/json", reply.dump()};
      } catch (const std::invalid_argument& e) {
        return HttpResponse{400, "application/json", error_body(e.what()).dump()};
      }
    });
    server_.handle("POST", "/api/scenario", [this](const HttpRequest& r) { return scenario_request(r); });
    server_.handle("GET", "/api/recordings", [this](const HttpRequest&) {
      return HttpResponse{200, "application/json", json(replay_ ? replay_->recordings() : std::vector<std::string>{}).dump()};
    });
    server_.handle("GET", "/api/config", [this](const HttpRequest&) {
      return HttpResponse{200, "application/json",
                          json{{"airport", options_.airport}, {"push_hz", options_.push_hz},
                               {"federate", options_.federate.name}}.dump()};
    });
  }

  std::string current_state() {
    const ServerStatistics statistics = server_.statistics();
    const json scenario = scenario_.state();
    std::lock_guard lock(shared_.mutex);
    const double now = clock_s();
    copy_tick_locked(now);
    return state_message(shared_, now, statistics, options_.push_hz, replay_.get(), scenario);
  }

  void print_summary() {
    const ServerStatistics s = server_.statistics();
    std::lock_guard lock(shared_.mutex);
    const double span = shared_.last_push_s - shared_.first_push_s;
    std::size_t confirmed = 0, unconfirmed = 0;
    for (const auto& c : shared_.tracker.commands()) {
      confirmed += c.status == CommandStatus::kConfirmed;
      unconfirmed += c.status == CommandStatus::kUnconfirmed;
    }
    std::printf("fedsim-ios: %llu pushes (%.1f/s), %llu messages and %.1f KB to pages, %llu requests (%llu refused), "
                "%zu commands (%zu confirmed, %zu unconfirmed)\n",
                static_cast<unsigned long long>(shared_.pushes), span > 0 ? (shared_.pushes - 1) / span : 0.0,
                static_cast<unsigned long long>(s.messages_sent), s.bytes_sent / 1024.0,
                static_cast<unsigned long long>(s.requests), static_cast<unsigned long long>(s.refused),
                shared_.tracker.commands().size(), confirmed, unconfirmed);
    std::fflush(stdout);
  }

  StationOptions options_;
  std::optional<nav::NavDatabase> db_;  // opened by on_start
  WebServer server_;
  Shared shared_;
  StationScenario scenario_;               // the page's scenario, run on the frame thread
  runtime::Output<msg::SimCommand>& commands_;
  // What a replay publishes (StationReplay writes it through its own writer on the host's
  // participant; declared here so that --print-ports and fedsim graph show it).
  runtime::Output<msg::AircraftState>& replay_port_;
  std::mutex publish_mutex_;
  bool accepting_commands_ = false;             // between on_start and on_stop (publish_mutex_)
  std::vector<msg::SimCommand> pending_commands_;  // from the page (publish_mutex_)
  std::vector<msg::SimCommand> sending_;           // frame thread only
  std::unique_ptr<StationReplay> replay_;  // over DDS only: built on the host's participant
  std::atomic<bool> started_in_process_{false};
  std::thread pusher_;
  std::atomic<bool> stopping_{false};
  // The newest tick, as the frame thread left it.
  std::atomic<std::uint64_t> tick_frame_{0}, ticks_{0};
  std::atomic<double> tick_sim_time_s_{0.0}, tick_period_s_{0.0};
  std::atomic<int> tick_run_state_{0}, tick_mode_{0};
  std::mutex wake_mutex_;
  std::condition_variable wake_;
};

/// The token from a file (first line) or FEDSIM_IOS_TOKEN; never from the command line, where
/// every user of the machine can read it (ps).
std::string read_token(const std::string& token_file) {
  if (!token_file.empty()) {
    std::ifstream in(token_file);
    if (!in) throw std::runtime_error("--token-file " + token_file + ": cannot read it");
    std::string token;
    std::getline(in, token);
    while (!token.empty() && (token.back() == '\r' || token.back() == ' ')) token.pop_back();
    if (token.empty()) throw std::runtime_error("--token-file " + token_file + ": the first line is empty");
    return token;
  }
  const char* env = std::getenv("FEDSIM_IOS_TOKEN");
  return env ? env : "";
}

/// FEDSIM_IOS_PORT gives the default port (as FEDSIM_DOMAIN gives the domain): a deployment run
/// by a test takes any free port without editing the file.
int port_from_environment(int fallback) {
  const char* env = std::getenv("FEDSIM_IOS_PORT");
  if (!env) return fallback;
  char* end = nullptr;
  const long port = std::strtol(env, &end, 10);
  if (end == env || *end != '\0' || port < 0 || port > 65535) {
    throw std::runtime_error(std::string("FEDSIM_IOS_PORT '") + env + "' is not a port number (0..65535)");
  }
  return static_cast<int>(port);
}

}  // namespace

runtime::FederateProgram program() {
  struct Parsed {
    StationOptions options;
    std::string token_file;
    CLI::Option* http_port = nullptr;
  };
  auto parsed = std::make_shared<Parsed>();
  parsed->options.server.web_root = fedsim::util::source_dir() + "/federates/ios/web";
  runtime::FederateProgram p;
  p.program = "fedsim-ios";
  p.default_name = "ios";
  p.description = "the instructor station: a web page (map, plots, instruments, channel pictures, federation, "
                  "commands) served on 127.0.0.1";
  p.add_options = [parsed](CLI::App& app) {
    StationOptions& o = parsed->options;
    parsed->http_port =
        app.add_option("--http-port", o.server.port, "TCP port of the page (0 = any free port; default FEDSIM_IOS_PORT or 8470)")
            ->check(util::FiniteRange(0, 65535))
            ->capture_default_str();
    app.add_option("--bind", o.server.bind_address,
                   "address to listen on; anything but loopback needs --token-file or FEDSIM_IOS_TOKEN")
        ->capture_default_str();
    app.add_option("--token-file", parsed->token_file, "file whose first line is the access token (>= 16 characters)");
    app.add_option("--port-file", o.port_file, "write the port to this file once listening");
    app.add_option("--push-hz", o.push_hz, "pushes of the live state to the page per second")
        ->check(util::FiniteRange(1.0, 60.0))
        ->capture_default_str();
    app.add_option("--airport", o.airport, "the map's airport (ICAO ident)")->capture_default_str();
    app.add_option("--map-radius-nm", o.map_radius_nm, "navaids within this distance of the airport [NM]")
        ->check(util::FiniteRange(1.0, 200.0))
        ->capture_default_str();
    app.add_option("--ring-minutes", o.ring_minutes, "live aircraft state kept for replay [min]")
        ->check(util::FiniteRange(0.5, 120.0))
        ->capture_default_str();
    app.add_option("--recordings", o.recordings, "folder of recordings the page may replay (fedsim record / fedsim run --out)")
        ->capture_default_str();
    app.add_option("--scenarios", o.scenarios, "folder of scenario files the page may run (default: data/scenarios)");
    app.add_option("--navdb", o.navdb_file, "navigation database (default: the one the build made)");
    app.add_option("--web-root", o.server.web_root, "folder of the page's files")->capture_default_str();
  };
  p.make_component = [parsed](const runtime::FederateOptions& common) {
    StationOptions o = parsed->options;
    o.federate = common;
    if (parsed->http_port == nullptr || parsed->http_port->count() == 0) o.server.port = port_from_environment(o.server.port);
    o.server.token = read_token(parsed->token_file);
    return std::unique_ptr<runtime::Component>(std::make_unique<Station>(o));
  };
  return p;
}

}  // namespace fedsim::ios
