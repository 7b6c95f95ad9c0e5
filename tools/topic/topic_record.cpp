// fedsim record: one CSV file per topic (DIR/<topic with '/' -> '_'>.csv), any fedsim type.
//
// Plain mode: a participant named --name subscribes; a loop writes the queued lines every 100 ms
// and prints progress. Lockstep member (--lockstep-member): a runtime::Federate named --name
// (its readers on a second participant, "<name>-data") whose recorded topics are lockstep inputs, so frame N is acknowledged only after the samples of
// frame N-1 are written: a lockstep run is recorded completely. Either way SIGINT/SIGTERM or
// --duration stops it cleanly: readers closed first, then every received sample written and the
// files flushed.
//
// Topics are discovered first (type name, writer QoS); a topic without a writer yet is attached
// as soon as one appears.
#include "tools/topic/topic_monitor.hpp"
#include "tools/topic/topic_recorder.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/federate.hpp"
#include "common/runtime/shutdown.hpp"

#include <fastdds/dds/subscriber/Subscriber.hpp>

#include <algorithm>
#include <atomic>
#include <ostream>
#include <thread>

namespace fedsim::tools {

namespace {

std::chrono::milliseconds to_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

class Recording {
 public:
  Recording(const RecordOptions& options, std::ostream& out, std::ostream& err)
      : options_(options), out_(out), err_(err), pending_(options.topics) {}

  void set_monitor(TopicMonitor* monitor) { monitor_ = monitor; }
  void set_data_participant(std::shared_ptr<runtime::DdsParticipant> dds) { dds_ = std::move(dds); }
  void set_federate(runtime::Federate* federate) { federate_ = federate; }

  /// Subscribes to every pending topic that has a writer now; throws on a topic whose type is
  /// unknown (a clear error before anything is recorded).
  void attach_ready() {
    std::vector<std::string> still_pending;
    std::vector<std::string> pending;
    {
      std::lock_guard lock(mutex_);
      if (stopping_) return;
      pending = pending_;
    }
    for (const auto& name : pending) {
      const auto topic = monitor_->topic(name);
      if (!topic || topic->writers.empty()) {
        still_pending.push_back(name);
        continue;
      }
      attach(*topic);
    }
    std::lock_guard lock(mutex_);
    pending_ = still_pending;
  }

  void drain_all() {
    for (const auto& r : recorders()) r->drain();
  }
  void flush_all() {
    for (const auto& r : recorders()) r->flush();
  }
  /// Lockstep, at the stop: the writers wrote the last frame's samples in that frame's step,
  /// after this federate stepped it, so they may still be on the way. Waits (at most wait_s)
  /// until every lockstep topic with a writer has delivered `frame`; the topics still short
  /// are named on err.
  void wait_for_frame(std::uint64_t frame, double wait_s) {
    std::vector<std::pair<std::shared_ptr<TopicRecorder>, std::shared_ptr<std::atomic<std::int64_t>>>> topics;
    {
      std::lock_guard lock(mutex_);
      topics = newest_frames_;
    }
    const auto short_of = [&] {
      std::vector<std::string> names;
      for (const auto& [recorder, newest] : topics) {
        if (recorder->matched_writers() > 0 && newest->load() < static_cast<std::int64_t>(frame)) {
          names.push_back(recorder->topic());
        }
      }
      return names;
    };
    const auto until = std::chrono::steady_clock::now() + to_ms(wait_s);
    while (!short_of().empty() && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    for (const auto& name : short_of()) {
      err_ << "fedsim record: " << name << ": the sample of the last frame (" << frame
           << ") did not arrive within " << wait_s << " s\n";
    }
  }

  /// Stops every reader (and any later attach); the queues still hold what was received.
  void close_all() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    for (const auto& r : recorders()) r->close();
  }

  void print_progress() {
    std::string line = "recorded:";
    for (const auto& r : recorders()) {
      line += " " + r->topic() + "=" + std::to_string(r->written());
    }
    for (const auto& name : pending_topics()) line += " " + name + "=(no writer yet)";
    out_ << line << "\n";
    out_.flush();
  }

  void print_summary() {
    for (const auto& r : recorders()) {
      out_ << r->topic() << ": " << r->written() << " samples -> " << r->file().string() << "\n";
    }
    for (const auto& name : pending_topics()) {
      out_ << name << ": never had a writer, not recorded\n";
    }
    out_.flush();
  }

  std::vector<std::string> pending_topics() {
    std::lock_guard lock(mutex_);
    return pending_;
  }

 private:
  std::vector<std::shared_ptr<TopicRecorder>> recorders() {
    std::lock_guard lock(mutex_);
    return recorders_;
  }

  fdds::DataReaderQos reader_qos(const TopicInfo& topic) {
    if (options_.reader_profile.empty()) return reader_qos_matching(topic.writers, 256);
    fdds::DataReaderQos qos;
    if (dds_->subscriber()->get_datareader_qos_from_profile(options_.reader_profile, qos) !=
        ReturnCode_t::RETCODE_OK) {
      throw runtime::DdsError("data_reader profile '" + options_.reader_profile +
                              "' is not defined in " + dds_->options().qos_file);
    }
    // Recording keeps a deeper history than a model's "latest sample" profile.
    if (qos.history().kind == fdds::KEEP_LAST_HISTORY_QOS && qos.history().depth < 256) {
      qos.history().depth = 256;
      qos.resource_limits().max_samples_per_instance = 256;
      qos.resource_limits().max_samples =
          std::max(qos.resource_limits().max_samples, 256 * qos.resource_limits().max_instances);
    }
    return qos;
  }

  void attach(const TopicInfo& topic) {
    const ftypes::DynamicType_ptr type = dynamic_type_for(topic);
    const auto path = std::filesystem::path(options_.out_dir) / csv_file_name(topic.name);
    auto recorder = std::make_shared<TopicRecorder>(topic.name, type, path);
    std::function<void(std::uint64_t)> on_frame;
    if (federate_) {
      if (recorder->layout().has_frame()) {
        TopicRecorder* r = recorder.get();
        auto input = federate_->add_lockstep_input(topic.name, [r] { return r->matched_writers(); });
        auto newest = std::make_shared<std::atomic<std::int64_t>>(-1);
        {
          std::lock_guard lock(mutex_);
          newest_frames_.emplace_back(recorder, newest);
        }
        on_frame = [input = std::move(input), newest](std::uint64_t frame) {
          std::int64_t seen = newest->load();
          while (static_cast<std::int64_t>(frame) > seen && !newest->compare_exchange_weak(seen, frame)) {
          }
          input(frame);
        };
      } else {
        err_ << "fedsim record: " << topic.name
             << " has no frame stamp: recorded, but not as a lockstep input\n";
      }
    }
    recorder->subscribe(dds_, reader_qos(topic), std::move(on_frame));
    std::string qos_text;
    for (const auto& w : topic.writers) {
      qos_text = w.reliability_name() + " " + w.durability_name();
    }
    out_ << "recording " << topic.name << " [" << *topic.type_names.begin() << "] ("
         << topic.writers.size() << " writer" << (topic.writers.size() == 1 ? "" : "s") << ", "
         << qos_text << ") -> " << path.string() << "\n";
    out_.flush();
    std::lock_guard lock(mutex_);
    recorders_.push_back(std::move(recorder));
  }

  const RecordOptions& options_;
  std::ostream& out_;
  std::ostream& err_;
  TopicMonitor* monitor_ = nullptr;
  std::shared_ptr<runtime::DdsParticipant> dds_;
  runtime::Federate* federate_ = nullptr;
  std::mutex mutex_;
  bool stopping_ = false;
  std::vector<std::string> pending_;
  std::vector<std::shared_ptr<TopicRecorder>> recorders_;
  // Lockstep topics: the newest frame each one delivered.
  std::vector<std::pair<std::shared_ptr<TopicRecorder>, std::shared_ptr<std::atomic<std::int64_t>>>> newest_frames_;
};

/// Waits until every topic has a writer (or the time is up), then a little for the rest of
/// their writers.
void wait_for_writers(TopicMonitor& monitor, const std::vector<std::string>& topics,
                      double wait_s) {
  const auto until = std::chrono::steady_clock::now() + to_ms(wait_s);
  for (;;) {
    const auto all = monitor.topics();
    const bool complete = std::all_of(topics.begin(), topics.end(), [&](const std::string& t) {
      auto it = all.find(t);
      return it != all.end() && !it->second.writers.empty();
    });
    if (complete) {
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
      return;
    }
    if (std::chrono::steady_clock::now() >= until || runtime::shutdown_requested()) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

int record_plain(const RecordOptions& options, Recording& recording, std::ostream& out) {
  const auto start = std::chrono::steady_clock::now();
  auto next_progress = start + to_ms(options.progress_period_s);
  const auto tick = std::chrono::milliseconds(100);
  std::string reason;
  for (;;) {
    if (runtime::wait_for_shutdown(tick)) {
      reason = runtime::shutdown_signal() ? "signal " + std::to_string(runtime::shutdown_signal())
                                          : "shutdown requested";
      break;
    }
    if (options.duration_s > 0 &&
        std::chrono::steady_clock::now() - start >= to_ms(options.duration_s)) {
      reason = "duration reached";
      break;
    }
    recording.attach_ready();
    recording.drain_all();
    if (options.progress_period_s > 0 && std::chrono::steady_clock::now() >= next_progress) {
      next_progress += to_ms(options.progress_period_s);
      recording.flush_all();
      recording.print_progress();
    }
  }
  recording.close_all();
  recording.drain_all();
  recording.flush_all();
  out << "stopped (" << reason << ")\n";
  return 0;
}

int record_lockstep(const RecordOptions& options, Recording& recording,
                    runtime::Federate& federate) {
  std::atomic<std::int64_t> last_frame{-1};
  federate.on_stop([&] {
    if (last_frame.load() >= 0) recording.wait_for_frame(static_cast<std::uint64_t>(last_frame.load()), 2.0);
    recording.close_all();
    recording.drain_all();
    recording.flush_all();
  });
  std::atomic<bool> running{true};
  std::thread housekeeping([&] {
    auto next_progress = std::chrono::steady_clock::now() + to_ms(options.progress_period_s);
    while (running.load()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      try {
        recording.attach_ready();
      } catch (const std::exception& e) {
        federate.fail(e.what());
      }
      if (options.progress_period_s > 0 && std::chrono::steady_clock::now() >= next_progress) {
        next_progress += to_ms(options.progress_period_s);
        recording.flush_all();
        recording.print_progress();
      }
    }
  });
  const int rc = federate.run([&](const runtime::FrameContext& frame) {
    last_frame.store(static_cast<std::int64_t>(frame.frame));
    recording.drain_all();
  });
  running.store(false);
  housekeeping.join();
  return rc;
}

int record(const RecordOptions& options, std::ostream& out, std::ostream& err) {
  try {
    if (options.topics.empty()) {
      err << "fedsim record: no topics given (--topics t1,t2)\n";
      return 1;
    }
    if (options.out_dir.empty()) {
      err << "fedsim record: no output directory given (--out DIR)\n";
      return 1;
    }
    std::filesystem::create_directories(options.out_dir);
    runtime::install_shutdown_handler();

    Recording recording(options, out, err);
    auto monitor_options = options.dds;
    // The readers live on this participant in both modes: never on the federate's, where the
    // runtime registered the compiled type supports of frame_tick, federate_status... under the
    // same type names (a reader there would get the compiled type, not the dynamic one).
    monitor_options.name = options.lockstep_member ? options.name + "-data" : options.name;
    auto monitor = TopicMonitor::create(monitor_options);
    recording.set_monitor(monitor.get());
    wait_for_writers(*monitor, options.topics, options.wait_s);
    for (const auto& name : options.topics) {
      const auto topic = monitor->topic(name);
      if (!topic || topic->writers.empty()) {
        err << "fedsim record: " << name << " has no writer yet: recording starts when one "
            << "appears\n";
      }
    }

    recording.set_data_participant(monitor->dds());
    if (!options.lockstep_member) {
      recording.attach_ready();
      const int rc = record_plain(options, recording, out);
      recording.print_summary();
      return rc;
    }

    runtime::FederateOptions federate_options;
    federate_options.name = options.name;
    federate_options.dds = options.dds;
    federate_options.log_level = options.log_level;
    federate_options.duration_s = options.duration_s;
    federate_options.max_frames = options.max_frames;
    federate_options.input_timeout_s = options.input_timeout_s;
    federate_options.sync_qos_suffix = options.sync_qos_suffix;
    runtime::Federate federate(federate_options);
    // Readers stop before the federate goes, however this scope is left.
    struct CloseReaders {
      Recording& recording;
      ~CloseReaders() { recording.close_all(); }
    } close_readers{recording};
    recording.set_federate(&federate);
    recording.attach_ready();
    const int rc = record_lockstep(options, recording, federate);
    recording.print_summary();
    return rc;
  } catch (const std::exception& e) {
    err << "fedsim record: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace

std::string csv_file_name(const std::string& topic) {
  std::string name = topic;
  std::replace(name.begin(), name.end(), '/', '_');
  return name + ".csv";
}

int run_record(const RecordOptions& options, std::ostream& out, std::ostream& err) {
  try {
    RecordOptions opts = options;
    opts.topics.clear();
    for (auto topic : options.topics) {  // trimmed, each once
      topic.erase(0, topic.find_first_not_of(" \t"));
      topic.erase(topic.find_last_not_of(" \t") + 1);
      if (!topic.empty() &&
          std::find(opts.topics.begin(), opts.topics.end(), topic) == opts.topics.end()) {
        opts.topics.push_back(topic);
      }
    }
    return record(opts, out, err);
  } catch (const std::exception& e) {
    err << "fedsim record: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fedsim::tools
