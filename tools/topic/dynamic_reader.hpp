// A DataReader for a type support built at run time (DynamicPubSubType or RawPubSubType): calls
// a handler with every valid sample on the middleware's listener thread and counts matched
// writers. The handler gets the type support's own data object (DynamicData* or RawSample*).
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "tools/topic/dynamic_types.hpp"

#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace fedsim::tools {

namespace fdds = eprosima::fastdds::dds;

class DynamicReader : public fdds::DataReaderListener {
 public:
  using Handler = std::function<void(void* sample, const fdds::SampleInfo& info)>;

  DynamicReader(std::shared_ptr<runtime::DdsParticipant> dds, const std::string& topic,
                fdds::TypeSupport type, const fdds::DataReaderQos& qos, Handler handler);
  ~DynamicReader() override;
  DynamicReader(const DynamicReader&) = delete;
  DynamicReader& operator=(const DynamicReader&) = delete;

  /// Stops delivery (no handler runs after this returns) and deletes the reader. Idempotent.
  void close();

  int matched_writers() const { return matched_.load(); }
  std::uint64_t received() const { return received_.load(); }
  const std::string& topic() const { return topic_; }

  void on_data_available(fdds::DataReader* reader) override;
  void on_subscription_matched(fdds::DataReader*,
                               const fdds::SubscriptionMatchedStatus& status) override;

 private:
  std::shared_ptr<runtime::DdsParticipant> dds_;
  std::string topic_;
  fdds::TypeSupport type_;
  Handler handler_;
  fdds::DataReader* reader_ = nullptr;
  std::mutex mutex_;  // guards reader_, closed_ and scratch_ (delivery vs close)
  bool closed_ = false;
  void* scratch_ = nullptr;
  std::atomic<int> matched_{0};
  std::atomic<std::uint64_t> received_{0};
};

/// A DynamicPubSubType for `type` that announces no type information of its own: it matches the
/// writers by type name (their TypeObject is the one it was built from).
fdds::TypeSupport dynamic_type_support(const ftypes::DynamicType_ptr& type);

}  // namespace fedsim::tools
