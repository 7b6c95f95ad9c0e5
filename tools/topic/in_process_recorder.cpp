#include "tools/topic/in_process_recorder.hpp"

#include "tools/topic/dynamic_types.hpp"
#include "tools/topic/topic_tools.hpp"

#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicPubSubType.h>

#include <functional>
#include <stdexcept>

namespace fedsim::tools {

struct InProcessRecorder::Stream {
  std::string topic;
  ftypes::DynamicType_ptr type;
  std::unique_ptr<TopicRecorder> recorder;
  std::unique_ptr<ftypes::DynamicPubSubType> dynamic_support;
  ftypes::DynamicData* scratch = nullptr;  // reused for every sample
  eprosima::fastrtps::rtps::SerializedPayload_t payload;
  std::uint64_t samples = 0;
  // With every_n_frames > 1: the samples of the newest frame skipped, recorded at close if no
  // later frame was recorded (the last frame is always kept).
  std::vector<std::function<void()>> skipped_last_frame;
  std::uint64_t skipped_frame = 0;

  ~Stream() {
    if (scratch) ftypes::DynamicDataFactory::get_instance()->delete_data(scratch);
  }

  template <class T>
  void record(const T& sample) {
    typename runtime::TopicType<T>::PubSubType support;
    const std::uint32_t size = support.getSerializedSizeProvider(const_cast<T*>(&sample))();
    if (payload.max_size < size) payload.reserve(size);
    payload.length = 0;
    payload.pos = 0;
    if (!support.serialize(const_cast<T*>(&sample), &payload) ||
        !dynamic_support->deserialize(&payload, scratch)) {
      throw std::runtime_error("in-process recorder: cannot convert a sample of " + topic);
    }
    recorder->on_sample(*scratch, 0.0);
    ++samples;
  }
};

InProcessRecorder::InProcessRecorder(runtime::Composition& composition,
                                     const std::vector<std::string>& topics,
                                     const std::filesystem::path& out_dir,
                                     std::uint64_t every_n_frames) {
  if (every_n_frames == 0) throw std::invalid_argument("in-process recorder: every 0 frames");
  std::filesystem::create_directories(out_dir);
  for (const std::string& name : topics) {
    auto stream = std::make_unique<Stream>();
    Stream* s = stream.get();
    const bool known = runtime::topics::visit(name, [&](const auto& topic) {
      using T = typename std::decay_t<decltype(topic)>::Message;
      s->topic = name;
      s->type = dynamic_type_by_name(topic.info.type_name);
      if (!s->type) throw std::runtime_error("no type object for " + topic.info.type_name);
      s->recorder = std::make_unique<TopicRecorder>(name, s->type, out_dir / csv_file_name(name));
      s->dynamic_support = std::make_unique<ftypes::DynamicPubSubType>(s->type);
      s->scratch = ftypes::DynamicDataFactory::get_instance()->create_data(s->type);
      composition.on_written(topic, std::function<void(const T&)>([s, every_n_frames](const T& sample) {
        if constexpr (runtime::Stamped<T>) {
          const std::uint64_t frame = sample.stamp().frame();
          if (frame % every_n_frames != 0) {
            if (frame != s->skipped_frame) s->skipped_last_frame.clear();
            s->skipped_frame = frame;
            s->skipped_last_frame.push_back([s, sample] { s->record(sample); });
            return;
          }
        }
        s->skipped_last_frame.clear();
        s->record(sample);
      }));
    });
    if (!known) throw std::invalid_argument("in-process recorder: unknown topic '" + name + "'");
    streams_.push_back(std::move(stream));
  }
}

InProcessRecorder::~InProcessRecorder() {
  try {
    close();
  } catch (...) {
    // Nothing more can be done while unwinding; close() reports errors when called directly.
  }
}

void InProcessRecorder::drain() {
  for (auto& s : streams_) s->recorder->drain();
}

void InProcessRecorder::close() {
  for (auto& s : streams_) {
    for (const auto& record : s->skipped_last_frame) record();
    s->skipped_last_frame.clear();
    s->recorder->drain();
    s->recorder->flush();
  }
}

std::vector<InProcessRecorder::Recorded> InProcessRecorder::recorded() const {
  std::vector<Recorded> out;
  for (const auto& s : streams_) out.push_back({s->topic, s->recorder->file(), s->samples});
  return out;
}

}  // namespace fedsim::tools
