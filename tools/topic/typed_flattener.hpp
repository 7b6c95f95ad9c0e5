// A typed catalogue sample flattened exactly as the recorder writes it (the same column names and
// cell text, see csv_layout.hpp): serialized with its compiled type support and read back as the
// IDL's DynamicData. For those who need "any field by name" of a typed sample at a modest rate:
// the instructor station's field registry, scenario conditions. Not thread-safe: one per thread.
#pragma once

#include "common/runtime/topic_catalogue.hpp"
#include "common/runtime/topic_types.hpp"
#include "tools/topic/csv_layout.hpp"
#include "tools/topic/dynamic_types.hpp"
#include "tools/topic/sample_tree.hpp"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::tools {

template <class T>
class TypedFlattener {
 public:
  explicit TypedFlattener(const runtime::Topic<T>& topic) : topic_(topic.name()) {
    type_ = dynamic_type_by_name(topic.info.type_name);
    if (!type_) throw std::runtime_error("no type object for " + topic.info.type_name);
    names_ = flattened_field_names(type_);
    dynamic_ = std::make_unique<ftypes::DynamicPubSubType>(type_);
    scratch_ = ftypes::DynamicDataFactory::get_instance()->create_data(type_);
  }
  ~TypedFlattener() { ftypes::DynamicDataFactory::get_instance()->delete_data(scratch_); }
  TypedFlattener(const TypedFlattener&) = delete;
  TypedFlattener& operator=(const TypedFlattener&) = delete;

  /// Column names, in IDL order (no time column).
  const std::vector<std::string>& names() const { return names_; }

  /// The cells of `sample`, in names() order. Throws if the sample cannot be converted.
  std::vector<std::string> cells(const T& sample) {
    typename runtime::TopicType<T>::PubSubType support;
    const std::uint32_t size = support.getSerializedSizeProvider(const_cast<T*>(&sample))();
    if (payload_.max_size < size) payload_.reserve(size);
    payload_.length = 0;
    payload_.pos = 0;
    if (!support.serialize(const_cast<T*>(&sample), &payload_) || !dynamic_->deserialize(&payload_, scratch_)) {
      throw std::runtime_error("cannot flatten a sample of " + topic_);
    }
    return flattened_cells(read_sample(*scratch_, type_));
  }

 private:
  std::string topic_;
  ftypes::DynamicType_ptr type_;
  std::vector<std::string> names_;
  std::unique_ptr<ftypes::DynamicPubSubType> dynamic_;
  ftypes::DynamicData* scratch_ = nullptr;
  eprosima::fastrtps::rtps::SerializedPayload_t payload_;
};

}  // namespace fedsim::tools
