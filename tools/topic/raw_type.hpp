// A type support that keeps each sample's serialized bytes as they are, under any type name:
// lets `topic hz` subscribe to a topic whose type this build does not know.
#pragma once

#include <fastdds/dds/topic/TopicDataType.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace fedsim::tools {

struct RawSample {
  std::vector<std::uint8_t> bytes;  // serialized payload, encapsulation header included
};

class RawPubSubType : public eprosima::fastdds::dds::TopicDataType {
 public:
  /// `keyed` must match the writers' topic kind (discovery tells it); `max_size` is the largest
  /// serialized sample expected (the writers announce theirs).
  RawPubSubType(const std::string& type_name, bool keyed, std::uint32_t max_size);

  bool serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) override;
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override;
  std::function<uint32_t()> getSerializedSizeProvider(void* data) override;
  void* createData() override;
  void deleteData(void* data) override;
  /// The key of a raw sample cannot be computed: keyed writers usually send its hash with each
  /// sample; for one that did not, this gives unknown_key_instance() (never fails: see .cpp).
  bool getKey(void* data, eprosima::fastrtps::rtps::InstanceHandle_t* handle,
              bool force_md5 = false) override;
  /// The one instance every keyed sample without a key hash is filed under.
  static eprosima::fastrtps::rtps::InstanceHandle_t unknown_key_instance();
};

}  // namespace fedsim::tools
