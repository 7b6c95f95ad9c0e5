#include "ios/station_replay.hpp"

#include "common/util/monotonic_clock.hpp"
#include "tools/topic/topic_replay.hpp"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace fedsim::ios {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kAircraftCsv = "fedsim_aircraft_state.csv";
// While paused, the held state is sent again this often: the flight federate takes control when
// no replayed state came for ReplayPlayback::kHoldFrames (10) frames, 0.2 s at 50 Hz.
constexpr double kHoldRepeatS = 0.05;

double clock_s() { return static_cast<double>(util::monotonic_ns()) * 1e-9; }

double number(const json& body, const char* key, double fallback) {
  if (!body.contains(key)) return fallback;
  if (!body.at(key).is_number()) throw std::invalid_argument(std::string("replay: ") + key + " is not a number");
  const double v = body.at(key).get<double>();
  if (!std::isfinite(v)) throw std::invalid_argument(std::string("replay: ") + key + " is not finite");
  return v;
}

/// A recorded row back into the typed sample: the row's DynamicData serialized and read by the
/// compiled type (the same bytes a live writer sends).
class RowToTyped {
 public:
  explicit RowToTyped(const tools::RowDecoder& decoder)
      : decoder_(decoder),
        dynamic_(decoder.type()),
        data_(eprosima::fastrtps::types::DynamicDataFactory::get_instance()->create_data(decoder.type())) {}
  ~RowToTyped() { eprosima::fastrtps::types::DynamicDataFactory::get_instance()->delete_data(data_); }

  msg::AircraftState convert(const std::vector<std::string>& cells) {
    decoder_.decode(cells, *data_);
    const std::uint32_t size = dynamic_.getSerializedSizeProvider(data_)();
    if (payload_.max_size < size) payload_.reserve(size);
    payload_.length = 0;
    payload_.pos = 0;
    msg::AircraftState out;
    if (!dynamic_.serialize(data_, &payload_) || !typed_.deserialize(&payload_, &out)) {
      throw std::runtime_error("replay: a recorded aircraft state does not convert to the compiled type");
    }
    return out;
  }

 private:
  const tools::RowDecoder& decoder_;
  eprosima::fastrtps::types::DynamicPubSubType dynamic_;
  eprosima::fastrtps::types::DynamicData* data_;
  msg::AircraftStatePubSubType typed_;
  eprosima::fastrtps::rtps::SerializedPayload_t payload_;
};

}  // namespace

StationReplay::StationReplay(std::shared_ptr<runtime::DdsParticipant> dds, double ring_s, fs::path recordings,
                             std::function<std::uint64_t()> current_frame)
    : recordings_(std::move(recordings)), ring_s_(ring_s), current_frame_(std::move(current_frame)) {
  writer_ = std::make_unique<runtime::Publisher<msg::AircraftState>>(dds, runtime::topics::replay_state);
  live_ = std::make_unique<runtime::Subscription<msg::AircraftState>>(
      dds, runtime::topics::aircraft_state, runtime::qos::kState,
      [this](const msg::AircraftState& s, const auto&) { take_live(s); });
  thread_ = std::thread([this] { publish_loop(); });
}

StationReplay::~StationReplay() { stop(); }

void StationReplay::stop() {
  stopping_.store(true);
  if (thread_.joinable()) thread_.join();
  live_.reset();
}

void StationReplay::take_live(const msg::AircraftState& s) {
  if (active_.load()) return;  // what the flight federate writes now is the replay itself
  const double t = s.stamp().sim_time_s();
  if (!std::isfinite(t)) return;
  std::lock_guard lock(mutex_);
  // A reset (sim time back) starts a new timeline: the old one cannot be replayed in order.
  if (!ring_.empty() && t < ring_.back().time_s - 0.5) ring_.clear();
  if (!ring_.empty() && t <= ring_.back().time_s) return;  // frozen: the same state again
  ring_.push_back({t, s});
  while (!ring_.empty() && ring_.back().time_s - ring_.front().time_s > ring_s_) ring_.pop_front();
}

std::vector<StationReplay::Sample> StationReplay::from_ring(double last_s) const {
  std::lock_guard lock(mutex_);
  if (ring_.empty()) throw std::invalid_argument("replay: no live aircraft state recorded yet");
  const double from = ring_.back().time_s - last_s;
  std::vector<Sample> out;
  for (const auto& s : ring_) {
    if (s.time_s >= from) out.push_back(s);
  }
  return out;
}

std::vector<std::string> StationReplay::recordings() const {
  std::vector<std::string> names;
  std::error_code ec;
  if (fs::is_regular_file(recordings_ / kAircraftCsv, ec)) names.push_back(".");
  for (const auto& entry : fs::directory_iterator(recordings_, ec)) {
    if (entry.is_directory(ec) && fs::is_regular_file(entry.path() / kAircraftCsv, ec)) {
      names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<StationReplay::Sample> StationReplay::from_recording(const std::string& name) const {
  // Only a name the station listed: never a path the page makes up.
  const auto names = recordings();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw std::invalid_argument("replay: no recording named '" + name + "' under " + recordings_.string());
  }
  const fs::path file = (name == "." ? recordings_ : recordings_ / name) / kAircraftCsv;
  tools::RecordedTopic recorded;
  try {
    recorded = tools::Recording::load_topic(*runtime::topics::find(runtime::topics::aircraft_state.name()), file);
  } catch (const std::exception& e) {
    throw std::invalid_argument(std::string("replay: ") + e.what());
  }
  RowToTyped convert(*recorded.decoder);
  std::vector<Sample> out;
  out.reserve(recorded.rows.size());
  for (const auto& row : recorded.rows) out.push_back({row.time_s, convert.convert(row.cells)});
  if (out.empty()) throw std::invalid_argument("replay: " + file.string() + " has no samples");
  return out;
}

void StationReplay::start(std::vector<Sample> samples, const std::string& source, double speed) {
  const double now_s = clock_s();
  std::vector<double> times;
  times.reserve(samples.size());
  for (const auto& s : samples) times.push_back(s.time_s);
  ReplayClock clock(std::move(times));  // checks the timeline
  clock.play(now_s, speed);             // checks the speed
  std::lock_guard lock(mutex_);
  samples_ = std::move(samples);
  clock_ = std::move(clock);
  source_ = source;
  published_index_ = static_cast<std::size_t>(-1);
  active_.store(true);
}

json StationReplay::request(const json& body) {
  const double now_s = clock_s();
  if (!body.is_object() || !body.contains("action") || !body.at("action").is_string()) {
    throw std::invalid_argument("replay: a request needs \"action\": start, pause, resume, seek, speed or take_control");
  }
  const std::string action = body.at("action").get<std::string>();
  if (action == "start") {
    const double speed = number(body, "speed", 1.0);
    const std::string source = body.value("source", std::string("ring"));
    if (source == "ring") {
      const double last_s = number(body, "last_s", 120.0);
      if (last_s <= 0.0 || last_s > ring_s_) {
        throw std::invalid_argument("replay: last_s must be within (0, " + std::to_string(static_cast<int>(ring_s_)) + "] s");
      }
      start(from_ring(last_s), "the last " + std::to_string(static_cast<int>(last_s)) + " s", speed);
    } else if (source == "recording") {
      const std::string name = body.value("name", std::string());
      start(from_recording(name), "recording " + name, speed);
    } else {
      throw std::invalid_argument("replay: source '" + source + "': ring or recording");
    }
    return state();
  }
  std::lock_guard lock(mutex_);
  if (action == "take_control") {
    active_.store(false);  // nothing more is sent: the flight federate flies on from the last state
    clock_.reset();
    return json{{"active", false}};
  }
  if (!clock_) throw std::invalid_argument("replay: no replay is running");
  if (action == "pause") {
    clock_->pause(now_s);
  } else if (action == "resume") {
    clock_->play(now_s, clock_->speed());
  } else if (action == "seek") {
    clock_->seek(now_s, clock_->start_s() + number(body, "t_s", 0.0));
  } else if (action == "speed") {
    const double speed = number(body, "speed", 1.0);
    const bool playing = clock_->playing();
    clock_->play(now_s, speed);  // sets (and checks) the speed from here
    if (!playing) clock_->pause(now_s);
  } else {
    throw std::invalid_argument("replay: unknown action '" + action + "'");
  }
  json out;
  out["active"] = active_.load();
  return out;
}

json StationReplay::state() const {
  const double now_s = clock_s();
  std::lock_guard lock(mutex_);
  json out;
  out["active"] = active_.load() && clock_.has_value();
  out["ring_s"] = ring_.empty() ? 0.0 : ring_.back().time_s - ring_.front().time_s;
  out["published"] = published_;
  if (clock_) {
    out["source"] = source_;
    out["playing"] = clock_->playing();
    out["speed"] = clock_->speed();
    out["position_s"] = clock_->position_s(now_s) - clock_->start_s();
    out["length_s"] = clock_->end_s() - clock_->start_s();
    out["samples"] = samples_.size();
    out["finished"] = clock_->finished(now_s);
  }
  return out;
}

void StationReplay::publish_loop() {
  double last_send = 0.0;
  while (!stopping_.load()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!active_.load()) continue;
    std::optional<msg::AircraftState> send;
    {
      std::lock_guard lock(mutex_);
      if (!clock_ || samples_.empty()) continue;
      const double now = clock_s();
      const std::size_t index = clock_->due(now);
      // A new sample, or the held one again (paused, or at the end) so the replay keeps the
      // aircraft until the instructor takes control.
      if (index != published_index_ || now - last_send >= kHoldRepeatS) {
        published_index_ = index;
        last_send = now;
        send = samples_[index].state;
        ++published_;
      }
    }
    if (send) {
      send->stamp().frame(current_frame_());
      writer_->publish(*send);
    }
  }
}

}  // namespace fedsim::ios
