// A typed DataWriter on a catalogue topic, with the topic's default QoS profile
// (qos/fedsim_qos.xml) or another one named.
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/qos_mismatch.hpp"
#include "common/runtime/topic_catalogue.hpp"

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>

#include <atomic>
#include <chrono>
#include <thread>

namespace fedsim::runtime {

template <class T>
class Publisher : public fdds::DataWriterListener {
 public:
  Publisher(std::shared_ptr<DdsParticipant> dds, const Topic<T>& catalogue_topic,
            std::string_view qos = {})
      : dds_(std::move(dds)), topic_name_(catalogue_topic.name()) {
    const std::string qos_profile = qos.empty() ? catalogue_topic.info.default_qos : std::string(qos);
    qos_profile_ = qos_profile;
    const std::string& topic_name = topic_name_;
    auto* topic = dds_->template topic<T>(topic_name);
    writer_ = dds_->publisher()->create_datawriter_with_profile(topic, qos_profile, this,
                                                                fdds::StatusMask::all());
    if (!writer_) {
      throw DdsError("cannot create a writer for " + topic_name + " with QoS profile '" +
                     qos_profile + "' (is it defined in " + dds_->options().qos_file +
                     "? with FEDSIM_SECURITY_DIR: does the identity's DDS Security grant allow it?)");
    }
  }
  ~Publisher() override {
    writer_->set_listener(nullptr);
    dds_->publisher()->delete_datawriter(writer_);
  }
  Publisher(const Publisher&) = delete;
  Publisher& operator=(const Publisher&) = delete;

  /// Writes one sample; false if the middleware refused it (logged by the caller).
  bool publish(const T& sample) { return writer_->write(const_cast<T*>(&sample)); }

  int matched_readers() const { return matched_.load(); }
  bool wait_for_readers(int count, std::chrono::milliseconds timeout) const {
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (matched_.load() < count) {
      if (std::chrono::steady_clock::now() > until) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
  }
  /// Blocks until every reliable reader acknowledged what was written (clean shutdown).
  bool wait_for_acknowledgments(std::chrono::milliseconds timeout) {
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(timeout).count();
    return writer_->wait_for_acknowledgments(
               eprosima::fastrtps::Duration_t(static_cast<int32_t>(ns / 1'000'000'000),
                                              static_cast<uint32_t>(ns % 1'000'000'000))) ==
           ReturnCode_t::RETCODE_OK;
  }
  const std::string& topic_name() const { return topic_name_; }
  fdds::DataWriter* writer() const { return writer_; }

  void on_publication_matched(fdds::DataWriter*,
                              const fdds::PublicationMatchedStatus& status) override {
    matched_.store(status.current_count);
  }
  void on_offered_incompatible_qos(fdds::DataWriter*,
                                   const fdds::OfferedIncompatibleQosStatus& status) override {
    qos_mismatch_.report(topic_name_, qos_profile_, status);
  }
  /// Readers found with QoS incompatible with this writer's (each logged: qos_mismatch.hpp).
  std::uint32_t incompatible_readers() const { return qos_mismatch_.count(); }

 private:
  std::shared_ptr<DdsParticipant> dds_;
  std::string topic_name_;
  std::string qos_profile_;
  QosMismatchLog qos_mismatch_{"writer", "reader"};
  fdds::DataWriter* writer_ = nullptr;
  std::atomic<int> matched_{0};
};

}  // namespace fedsim::runtime
