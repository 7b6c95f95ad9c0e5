#include "ios/ios_station.hpp"
#include "common/util/build_paths.hpp"

#include "common/instructor/request_json.hpp"
#include "common/navdb/nav_database.hpp"
#include "common/runtime/federate.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/runtime/sim_command_codec.hpp"
#include "common/runtime/subscription.hpp"
#include "common/util/monotonic_clock.hpp"
#include "ios/model/command_tracker.hpp"
#include "ios/model/live_fields.hpp"
#include "ios/model/map_layers.hpp"
#include "ios/station_ports.hpp"
#include "ios/station_replay.hpp"
#include "ios/station_scenario.hpp"
#include "common/util/config_node.hpp"
#include "tools/topic/typed_flattener.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <condition_variable>
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

/// Takes the samples of one catalogue topic into the registry, flattened as the recorder
/// flattens them, at most a few times a second (RateGate).
template <class T>
class TopicTap {
 public:
  TopicTap(const std::shared_ptr<runtime::DdsParticipant>& dds, const runtime::Topic<T>& topic, Shared& shared,
           double period_s)
      : topic_name_(topic.name()), shared_(shared), gate_(period_s), flattener_(topic) {
    subscription_ = std::make_unique<runtime::Subscription<T>>(
        dds, topic, runtime::qos::kState, [this](const T& sample, const auto&) { take(sample); });
  }
  ~TopicTap() { subscription_.reset(); }  // no callback after this

 private:
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

  std::string topic_name_;
  Shared& shared_;
  RateGate gate_;
  std::mutex tap_mutex_;
  tools::TypedFlattener<T> flattener_;
  std::unique_ptr<runtime::Subscription<T>> subscription_;
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

/// The station: the federate, its readers and writer, the server and the pusher.
class Station {
 public:
  explicit Station(const StationOptions& options)
      : options_(options),
        db_(nav::NavDatabase::open(options.navdb_file.empty() ? nav::default_database_path() : options.navdb_file)),
        server_(options.server),
        scenario_(options.scenarios.empty() ? std::filesystem::path(fedsim::util::data_dir()) / "scenarios"
                                            : std::filesystem::path(options.scenarios)) {
    register_routes();
    server_.set_greeting([this] { return current_state(); });
  }

  int run() {
    server_.start();  // before anything joins the federation: a bad port or address exits 2
    announce();
    runtime::Federate federate(options_.federate);
    federate_ = &federate;
    subscribe(federate);
    replay_ = std::make_unique<StationReplay>(federate.dds(), options_.ring_minutes * 60.0, options_.recordings,
                                              [this] { return tick_frame_.load(); });
    auto& commands = federate.publish(runtime::topics::sim_command, runtime::qos::kCommand);
    commands_ = &commands;
    federate.on_command([this](const msg::SimCommand& c) { note_setting(c); });
    std::thread pusher([this] { push_loop(); });
    const int rc = federate.run([this](const runtime::FrameContext& frame) { note_frame(frame); });
    stopping_.store(true);
    wake_.notify_all();
    pusher.join();
    {
      std::lock_guard lock(publish_mutex_);
      commands_ = nullptr;  // the page can no longer send once the federate is gone
    }
    server_.stop();
    replay_.reset();
    taps_.clear();
    print_summary();
    return rc;
  }

 private:
  void announce() {
    std::cout << "fedsim-ios: instructor station at " << server_.url() << std::endl;
    if (!options_.port_file.empty()) {
      std::ofstream(options_.port_file) << server_.port() << "\n";
    }
  }

  template <class T>
  void tap(runtime::Federate& federate, const runtime::Topic<T>& topic) {
    taps_.push_back(std::make_shared<TopicTap<T>>(federate.dds(), topic, shared_, 1.0 / (2.0 * options_.push_hz)));
  }

  void subscribe(runtime::Federate& federate) {
    for (const StationRead& read : kStationReads) {
      if (read.topic == runtime::topics::visual_picture.name()) {
        taps_.push_back(std::make_shared<runtime::Subscription<msg::VisualPicture>>(
            federate.dds(), runtime::topics::visual_picture, read.qos,
            [this](const msg::VisualPicture& p, const auto&) { note_picture(p); }));
        continue;
      }
      runtime::topics::visit(read.topic, [&](const auto& topic) { tap(federate, topic); });
    }
    taps_.push_back(std::make_shared<runtime::Subscription<msg::FederateStatus>>(
        federate.dds(), runtime::topics::federate_status, runtime::qos::kStatus,
        [this](const msg::FederateStatus& s, const auto&) { note_status(s); }));
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
        if (federate_) federate_->log().info("scenario t={:.2f}s (line {}): {}", f.sim_time_s, a.line, a.text);
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
    if (federate_) federate_->log().info("scenario {} started from {}", name, r.remote_address);
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
          if (federate_) federate_->log().info("command {} '{}': {} ({})", c.sequence, c.text, status_name(c.status), c.evidence);
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
      if (!commands_ || !commands_->publish(sample)) return false;
    }
    if (federate_) federate_->log().info("command {} from {}: {}", sequence, from, instructor::describe(command));
    return true;
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
      expected = expected_position(db_, r->airport, r->runway, r->gate_distance_m);
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
        return HttpResponse{200, "application/json", map_json(db_, airport, radius_nm)};
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
      if (!replay_) return HttpResponse{503, "application/json", error_body("the station is not connected yet").dump()};
      json body;
      try {
        body = json::parse(r.body);
      } catch (const json::parse_error& e) {
        return HttpResponse{400, "application/json", error_body(std::string("the request is not JSON: ") + e.what()).dump()};
      }
      try {
        const json reply = replay_->request(body);
        if (federate_) federate_->log().info("replay from {}: {}", r.remote_address, body.dump());
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
  nav::NavDatabase db_;
  WebServer server_;
  Shared shared_;
  runtime::Federate* federate_ = nullptr;
  std::mutex publish_mutex_;
  runtime::Publisher<msg::SimCommand>* commands_ = nullptr;
  std::vector<std::shared_ptr<void>> taps_;
  std::unique_ptr<StationReplay> replay_;  // built once the federate's participant exists
  StationScenario scenario_;               // the page's scenario, run on the frame thread
  std::atomic<bool> stopping_{false};
  // The newest tick, as the frame thread left it.
  std::atomic<std::uint64_t> tick_frame_{0}, ticks_{0};
  std::atomic<double> tick_sim_time_s_{0.0}, tick_period_s_{0.0};
  std::atomic<int> tick_run_state_{0}, tick_mode_{0};
  std::mutex wake_mutex_;
  std::condition_variable wake_;
};

}  // namespace

int run_station(const StationOptions& options) {
  runtime::install_shutdown_handler();
  std::unique_ptr<Station> station;
  try {
    station = std::make_unique<Station>(options);
  } catch (const std::exception& e) {
    std::cerr << "fedsim-ios: " << e.what() << "\n";
    return 2;
  }
  try {
    return station->run();
  } catch (const ServerError& e) {
    std::cerr << "fedsim-ios: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "fedsim-ios: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fedsim::ios
