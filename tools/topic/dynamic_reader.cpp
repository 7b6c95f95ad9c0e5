#include "tools/topic/dynamic_reader.hpp"
#include "tools/topic/raw_type.hpp"

#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastrtps/types/DynamicPubSubType.h>

namespace fedsim::tools {

namespace {

/// Both the tools' DynamicPubSubType, or both their RawPubSubType (never a compiled one).
bool same_tool_type_kind(const fdds::TopicDataType* a, const fdds::TopicDataType* b) {
  using eprosima::fastrtps::types::DynamicPubSubType;
  const bool both_dynamic = dynamic_cast<const DynamicPubSubType*>(a) != nullptr &&
                            dynamic_cast<const DynamicPubSubType*>(b) != nullptr;
  const bool both_raw = dynamic_cast<const RawPubSubType*>(a) != nullptr &&
                        dynamic_cast<const RawPubSubType*>(b) != nullptr;
  return both_dynamic || both_raw;
}

}  // namespace

DynamicReader::DynamicReader(std::shared_ptr<runtime::DdsParticipant> dds, const std::string& topic,
                             fdds::TypeSupport type, const fdds::DataReaderQos& qos,
                             Handler handler)
    : dds_(std::move(dds)), topic_(topic), type_(type), handler_(std::move(handler)) {
  // Two topics of one type (fedsim/pilot_controls and fedsim/applied_controls) read on one
  // participant: the second reader shares the first one's type support when both are of the
  // same kind (dynamic or raw: built alike from the type name), so its handler gets the
  // objects it expects.
  if (auto registered = dds_->participant()->find_type(type_.get_type_name());
      registered.get() != nullptr && registered.get() != type_.get() &&
      same_tool_type_kind(registered.get(), type_.get())) {
    type_ = registered;
  }
  auto* dds_topic = dds_->topic_for(topic, type_);
  // A participant keeps the first type support registered under a name: if compiled code got
  // there first, a reader here would deserialize into the wrong object.
  if (dds_->participant()->find_type(type_.get_type_name()).get() != type_.get()) {
    throw runtime::DdsError("participant '" + dds_->options().name + "' already has a compiled "
                            "type support for " + type_.get_type_name() +
                            ": the topic tools need a participant of their own");
  }
  scratch_ = type_->createData();
  reader_ = dds_->subscriber()->create_datareader(dds_topic, qos, this, fdds::StatusMask::all());
  if (!reader_) {
    type_->deleteData(scratch_);
    scratch_ = nullptr;
    throw runtime::DdsError("cannot create a reader for " + topic + " (type " +
                            type_.get_type_name() + ")");
  }
}

DynamicReader::~DynamicReader() {
  close();
}

void DynamicReader::close() {
  fdds::DataReader* reader = nullptr;
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
    reader = reader_;
    reader_ = nullptr;
  }
  if (reader) {
    reader->set_listener(nullptr);
    dds_->subscriber()->delete_datareader(reader);
  }
  std::lock_guard lock(mutex_);  // a delivery in progress finishes before the scratch goes
  if (scratch_) {
    type_->deleteData(scratch_);
    scratch_ = nullptr;
  }
}

void DynamicReader::on_data_available(fdds::DataReader* reader) {
  // Not reader_: a transient-local sample can arrive before create_datareader() returns.
  std::lock_guard lock(mutex_);
  if (closed_ || !scratch_) return;
  fdds::SampleInfo info;
  while (reader->take_next_sample(scratch_, &info) == ReturnCode_t::RETCODE_OK) {
    if (!info.valid_data) continue;
    received_.fetch_add(1);
    if (handler_) handler_(scratch_, info);
  }
}

void DynamicReader::on_subscription_matched(fdds::DataReader*,
                                            const fdds::SubscriptionMatchedStatus& status) {
  matched_.store(status.current_count);
}

fdds::TypeSupport dynamic_type_support(const ftypes::DynamicType_ptr& type) {
  auto* pst = new ftypes::DynamicPubSubType(type);
  pst->auto_fill_type_object(false);
  pst->auto_fill_type_information(false);
  return fdds::TypeSupport(pst);
}

}  // namespace fedsim::tools
