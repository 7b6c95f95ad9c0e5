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

bool RawPubSubType::getKey(void*, eprosima::fastrtps::rtps::InstanceHandle_t* handle, bool) {
  // Fast DDS 2.9 asks for the key only of a keyed sample that came without a key hash (Cyclone
  // DDS sends none by default). Returning false there is not survivable: DataReaderHistory then
  // keeps the sample without an instance and asserts in update_instance_nts (abort). The key
  // fields of an unknown type cannot be found in its bytes, so every such sample goes to one
  // pseudo-instance: the raw tools count and size samples, they do not tell instances apart.
  *handle = unknown_key_instance();
  return true;
}

eprosima::fastrtps::rtps::InstanceHandle_t RawPubSubType::unknown_key_instance() {
  eprosima::fastrtps::rtps::InstanceHandle_t handle;
  // Not a valid MD5 of any serialized key in practice, and not the undefined (all-zero) handle.
  static constexpr char kTag[] = "fedsim:raw:nokey";
  static_assert(sizeof(kTag) - 1 == 16);
  std::memcpy(handle.value, kTag, 16);
  return handle;
}

}  // namespace fedsim::tools
