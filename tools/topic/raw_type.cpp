#include "tools/topic/raw_type.hpp"

#include <algorithm>
#include <cstring>

namespace fedsim::tools {

RawPubSubType::RawPubSubType(const std::string& type_name, bool keyed, std::uint32_t max_size) {
  setName(type_name.c_str());
  m_typeSize = std::max<std::uint32_t>(max_size, 64) + 4;
  m_isGetKeyDefined = keyed;
  auto_fill_type_object(false);
  auto_fill_type_information(false);
}

bool RawPubSubType::serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) {
  const auto& bytes = static_cast<RawSample*>(data)->bytes;
  if (bytes.size() > payload->max_size) return false;
  std::memcpy(payload->data, bytes.data(), bytes.size());
  payload->length = static_cast<std::uint32_t>(bytes.size());
  return true;
}

bool RawPubSubType::deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload,
                                void* data) {
  auto& bytes = static_cast<RawSample*>(data)->bytes;
  bytes.assign(payload->data, payload->data + payload->length);
  return true;
}

std::function<uint32_t()> RawPubSubType::getSerializedSizeProvider(void* data) {
  return [data] { return static_cast<uint32_t>(static_cast<RawSample*>(data)->bytes.size()); };
}

void* RawPubSubType::createData() { return new RawSample(); }

void RawPubSubType::deleteData(void* data) { delete static_cast<RawSample*>(data); }

bool RawPubSubType::getKey(void*, eprosima::fastrtps::rtps::InstanceHandle_t*, bool) {
  return false;
}

}  // namespace fedsim::tools
