// A typed DataReader on a catalogue topic, from its default or a named QoS profile. Keeps the latest sample and can call a
// handler for every sample, on the middleware's listener thread (no hand-off: the frame loop
// runs its step right there, which measured 15-40% faster than a waitset thread here).
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/qos_mismatch.hpp"
#include "common/runtime/topic_catalogue.hpp"

#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fedsim::runtime {

template <class T>
class Subscription : public fdds::DataReaderListener {
 public:
  using SampleHandler = std::function<void(const T&, const fdds::SampleInfo&)>;
  using LivelinessHandler = std::function<void(const fdds::LivelinessChangedStatus&)>;

  /// A reader on a catalogue topic with its default QoS profile or the one named.
  Subscription(std::shared_ptr<DdsParticipant> dds, const Topic<T>& catalogue_topic,
               std::string_view qos = {}, SampleHandler on_sample = {})
      : dds_(std::move(dds)), topic_name_(catalogue_topic.name()), on_sample_(std::move(on_sample)) {
    const std::string qos_profile = qos.empty() ? catalogue_topic.info.default_qos : std::string(qos);
    qos_profile_ = qos_profile;
    const std::string& topic_name = topic_name_;
    auto* topic = dds_->template topic<T>(topic_name);
    reader_ = dds_->subscriber()->create_datareader_with_profile(topic, qos_profile, this,
                                                                 fdds::StatusMask::all());
    if (!reader_) {
      throw DdsError("cannot create a reader for " + topic_name + " with QoS profile '" +
                     qos_profile + "' (is it defined in " + dds_->options().qos_file +
                     "? with FEDSIM_SECURITY_DIR: does the identity's DDS Security grant allow it?)");
    }
    best_effort_ = reader_->get_qos().reliability().kind == fdds::BEST_EFFORT_RELIABILITY_QOS;
  }
  ~Subscription() override { close(); }
  Subscription(const Subscription&) = delete;
  Subscription& operator=(const Subscription&) = delete;

  /// Stops delivery (no handler runs after this returns) and deletes the reader.
  void close() {
    std::lock_guard lock(close_mutex_);
    if (fdds::DataReader* reliable = reliable_reader_.exchange(nullptr)) {
      reliable->set_listener(nullptr);
      dds_->subscriber()->delete_datareader(reliable);
    }
    if (!reader_) return;
    reader_->set_listener(nullptr);
    dds_->subscriber()->delete_datareader(reader_);
    reader_ = nullptr;
  }

  /// A best-effort reader of a reliable writer gets a lost sample never: for lockstep inputs the
  /// runtime adds a second, reliable reader (profile `reliable_profile`) on the same topic once
  /// a reliable writer is known (DdsParticipant::has_reliable_writer; a reliable reader of a
  /// best-effort writer would not match, and that writer would log the mismatch). Both readers
  /// feed this one subscription: whichever copy of a sample arrives first is kept, the other
  /// is dropped by its writer sequence number, so the best-effort path stays as fast as before
  /// and the reliable one repairs what it lost. True if the reader was added now.
  bool read_reliably_too(std::string_view reliable_profile)
    requires Stamped<T>
  {
    std::lock_guard lock(close_mutex_);
    if (!reader_ || !best_effort_ || reliable_reader_.load()) return false;
    auto* topic = dds_->template topic<T>(topic_name_);
    fdds::DataReader* reliable = dds_->subscriber()->create_datareader_with_profile(
        topic, std::string(reliable_profile), this, fdds::StatusMask::all());
    if (!reliable) {
      throw DdsError("cannot create a reliable reader for " + topic_name_ + " with QoS profile '" +
                     std::string(reliable_profile) + "'");
    }
    reliable_reader_.store(reliable);
    return true;
  }
  /// True once the reliable reader of read_reliably_too() has matched a writer.
  bool reads_reliably() const { return reliable_matched_.load() > 0; }
  bool has_reliable_reader() const { return reliable_reader_.load() != nullptr; }

  /// Copies the latest valid sample into `out`; false if none has arrived yet.
  bool latest(T& out) const {
    std::lock_guard lock(latest_mutex_);
    if (!has_latest_) return false;
    out = latest_;
    return true;
  }
  /// Lockstep reads: the newest sample stamped with a frame before `frame` (the sample of frame
  /// N-1 while stepping frame N, even if frame N's sample has already arrived). Only for
  /// messages with a FrameStamp.
  bool latest_before(std::uint64_t frame, T& out) const
    requires Stamped<T>
  {
    std::lock_guard lock(latest_mutex_);
    const T* best = nullptr;
    for (std::size_t i = 0; i < ring_count_; ++i) {
      const T& s = ring_[i];
      if (s.stamp().frame() < frame && (!best || s.stamp().frame() > best->stamp().frame())) {
        best = &s;
      }
    }
    if (!best) return false;
    out = *best;
    return true;
  }
  /// True while a sample is known to be missing (lost on the way, not yet repaired), so that a
  /// newer sample does not show that the writer wrote nothing in between. Read reliably (the
  /// reader, or its reliable second reader matched): a writer's newest sequence number seen is
  /// ahead of what the reliable reader, which delivers in order, has delivered. Read best effort
  /// only: a hole among a writer's last 16 sequence numbers (one lost before the first sample
  /// seen cannot be known). Only for stamped messages.
  bool missing_samples() const {
    const bool reliable = !best_effort_ || reliable_matched_.load() > 0;
    std::lock_guard lock(latest_mutex_);
    return std::any_of(sequences_.begin(), sequences_.end(), [&](const WriterSequence& w) {
      return reliable ? w.reliable_highest < w.highest
                      : (w.received & kSequenceWindow) != kSequenceWindow;
    });
  }
  bool has_sample() const { return received_.load() > 0; }
  std::uint64_t received_count() const { return received_.load(); }
  int matched_writers() const { return std::max(matched_.load(), reliable_matched_.load()); }
  std::uint64_t deadline_misses() const { return deadline_misses_.load(); }
  /// Writers found with QoS incompatible with this reader's (each logged: qos_mismatch.hpp).
  std::uint32_t incompatible_writers() const { return qos_mismatch_.count(); }
  const std::string& topic_name() const { return topic_name_; }

  bool wait_for_writers(int count, std::chrono::milliseconds timeout) const {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (matched_.load() < count) {
      if (std::chrono::steady_clock::now() > until) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  }
  void set_liveliness_handler(LivelinessHandler handler) { on_liveliness_ = std::move(handler); }
  /// Only samples `accept` returns true for are kept, counted and handed on (Input::accept_only).
  void set_filter(std::function<bool(const T&)> accept) {
    std::lock_guard lock(latest_mutex_);
    accept_ = std::move(accept);
  }

  void on_data_available(fdds::DataReader* reader) override {
    fdds::SampleInfo info;
    // The two readers of read_reliably_too() may deliver concurrently: one scratch each.
    const bool second = is_second_reader(reader);
    T& sample = second ? reliable_scratch_ : scratch_;
    // A stamped best-effort subscription may get a second copy from its reliable reader (also
    // of samples taken before that reader existed: it replays the writer's history).
    const bool may_repeat = Stamped<T> && best_effort_;
    while (reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data) continue;
      {
        std::lock_guard lock(latest_mutex_);
        if constexpr (Stamped<T>) {
          note_sequence_locked(info.sample_identity, second || !best_effort_);
        }
        if (may_repeat && !first_copy_locked(info.sample_identity)) continue;
        if (accept_ && !accept_(sample)) continue;
        latest_ = sample;
        has_latest_ = true;
        if constexpr (Stamped<T>) {
          ring_[ring_next_] = sample;
          ring_next_ = (ring_next_ + 1) % ring_.size();
          ring_count_ = std::min(ring_count_ + 1, ring_.size());
        }
      }
      received_.fetch_add(1);
      if (on_sample_) on_sample_(sample, info);
    }
  }
  void on_subscription_matched(fdds::DataReader* reader,
                               const fdds::SubscriptionMatchedStatus& status) override {
    (is_second_reader(reader) ? reliable_matched_ : matched_).store(status.current_count);
    if (status.current_count_change < 0) {
      // A writer gone (a crashed federate): nothing of it is missing any more; a restarted
      // one is a new writer (new GUID).
      const auto gone = eprosima::fastrtps::rtps::iHandle2GUID(status.last_publication_handle);
      std::lock_guard lock(latest_mutex_);
      std::erase_if(sequences_, [&](const WriterSequence& w) { return w.writer == gone; });
    }
  }
  // The events below are the first reader's only: the reliable one is a repair path.
  void on_requested_deadline_missed(fdds::DataReader* reader,
                                    const fdds::RequestedDeadlineMissedStatus&) override {
    if (!is_second_reader(reader)) deadline_misses_.fetch_add(1);
  }
  void on_liveliness_changed(fdds::DataReader* reader,
                             const fdds::LivelinessChangedStatus& status) override {
    if (!is_second_reader(reader) && on_liveliness_) on_liveliness_(status);
  }
  void on_requested_incompatible_qos(fdds::DataReader* reader,
                                     const fdds::RequestedIncompatibleQosStatus& status) override {
    // The reliable reader is expected not to match a best-effort writer of the topic.
    if (!is_second_reader(reader)) qos_mismatch_.report(topic_name_, qos_profile_, status);
  }

 private:
  std::shared_ptr<DdsParticipant> dds_;
  std::string topic_name_;
  std::string qos_profile_;
  QosMismatchLog qos_mismatch_{"reader", "writer"};
  SampleHandler on_sample_;
  LivelinessHandler on_liveliness_;
  std::function<bool(const T&)> accept_;  // guarded by latest_mutex_
  fdds::DataReader* reader_ = nullptr;
  std::mutex close_mutex_;
  T scratch_;  // reused for every take: bounded types never allocate here
  T reliable_scratch_;  // the same for the reliable reader
  std::atomic<bool> best_effort_{false};  // the first reader is best effort
  std::atomic<fdds::DataReader*> reliable_reader_{nullptr};  // read_reliably_too()
  std::atomic<int> reliable_matched_{0};
  // The last samples kept (writer and sequence number), to drop the second reader's copy.
  std::array<eprosima::fastrtps::rtps::SampleIdentity, 32> seen_{};
  std::size_t seen_next_ = 0;
  mutable std::mutex latest_mutex_;
  T latest_;
  bool has_latest_ = false;
  std::array<T, 4> ring_{};  // last few stamped samples, for latest_before()
  std::size_t ring_next_ = 0;
  std::size_t ring_count_ = 0;
  std::atomic<std::uint64_t> received_{0};

  /// A writer's sequence numbers as they arrived: the newest, the newest the reliable path
  /// delivered, and which of the latest arrived (bit i: `highest - i`; numbers before the first
  /// one seen count as arrived).
  struct WriterSequence {
    eprosima::fastrtps::rtps::GUID_t writer;
    std::int64_t highest = 0;
    std::int64_t reliable_highest = 0;
    std::uint64_t received = ~0ull;
  };
  static constexpr std::uint64_t kSequenceWindow = 0xFFFF;  // a hole older than 16 samples is
                                                            // forgotten (never to be repaired)
  void note_sequence_locked(const eprosima::fastrtps::rtps::SampleIdentity& id, bool reliable_path) {
    const std::int64_t seq = static_cast<std::int64_t>(id.sequence_number().to64long());
    auto it = std::find_if(sequences_.begin(), sequences_.end(),
                           [&](const WriterSequence& w) { return w.writer == id.writer_guid(); });
    if (it == sequences_.end()) {
      sequences_.push_back(WriterSequence{id.writer_guid(), seq, reliable_path ? seq : 0, ~0ull});
      return;
    }
    if (reliable_path) it->reliable_highest = std::max(it->reliable_highest, seq);
    if (seq > it->highest) {
      const std::int64_t shift = seq - it->highest;
      it->received = shift >= 64 ? 0 : it->received << shift;
      it->received |= 1;
      it->highest = seq;
    } else if (it->highest - seq < 64) {
      it->received |= 1ull << (it->highest - seq);
    }
  }
  std::vector<WriterSequence> sequences_;  // guarded by latest_mutex_

  /// The reliable reader of read_reliably_too(), told apart by its QoS: Fast DDS calls a
  /// listener while it creates the reader (local matches), before create_datareader returns.
  bool is_second_reader(fdds::DataReader* reader) const {
    return best_effort_ && reader->get_qos().reliability().kind == fdds::RELIABLE_RELIABILITY_QOS;
  }

  /// True the first time a sample (its writer and sequence number) is seen; latest_mutex_ held.
  bool first_copy_locked(const eprosima::fastrtps::rtps::SampleIdentity& id) {
    if (std::find(seen_.begin(), seen_.end(), id) != seen_.end()) return false;
    seen_[seen_next_] = id;
    seen_next_ = (seen_next_ + 1) % seen_.size();
    return true;
  }
  std::atomic<int> matched_{0};
  std::atomic<std::uint64_t> deadline_misses_{0};
};

}  // namespace fedsim::runtime
