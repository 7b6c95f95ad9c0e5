#include "tools/topic/topic_recorder.hpp"

#include <fastrtps/types/DynamicData.h>

#include <chrono>

namespace fedsim::tools {

TopicRecorder::TopicRecorder(const std::string& topic, ftypes::DynamicType_ptr type,
                             const std::filesystem::path& file)
    : topic_(topic), type_(std::move(type)), layout_(type_), path_(file) {
  file_.open(path_, std::ios::out | std::ios::trunc);
  if (!file_) throw std::runtime_error("cannot write " + path_.string());
  file_ << layout_.header() << '\n';
  file_.flush();
}

TopicRecorder::~TopicRecorder() {
  close();
  drain();
  flush();
}

void TopicRecorder::subscribe(std::shared_ptr<runtime::DdsParticipant> dds,
                              const fdds::DataReaderQos& qos,
                              std::function<void(std::uint64_t)> on_frame) {
  reader_ = std::make_unique<DynamicReader>(
      std::move(dds), topic_, dynamic_type_support(type_), qos,
      [this, on_frame = std::move(on_frame)](void* sample, const fdds::SampleInfo& info) {
        std::int64_t ns = info.reception_timestamp.to_ns();
        if (ns <= 0) {
          ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                   std::chrono::system_clock::now().time_since_epoch())
                   .count();
        }
        const auto frame = on_sample(*static_cast<ftypes::DynamicData*>(sample), ns * 1e-9);
        if (frame && on_frame) on_frame(*frame);  // no lock held: this may run a frame's step
      });
  reader_ptr_.store(reader_.get());
}

void TopicRecorder::close() {
  if (reader_) reader_->close();
}

std::optional<std::uint64_t> TopicRecorder::on_sample(ftypes::DynamicData& sample,
                                                      double receive_time_s) {
  const SampleNode tree = read_sample(sample, type_);
  std::string line = layout_.row(tree, receive_time_s);
  line += '\n';
  {
    std::lock_guard lock(queue_mutex_);
    queue_.push_back(std::move(line));
  }
  return layout_.frame_of(tree);
}

std::size_t TopicRecorder::drain() {
  std::lock_guard file_lock(file_mutex_);  // held across the swap: lines stay in order
  std::vector<std::string> lines;
  {
    std::lock_guard lock(queue_mutex_);
    lines.swap(queue_);
  }
  if (lines.empty()) return 0;
  for (const auto& line : lines) file_ << line;
  written_.fetch_add(lines.size());
  return lines.size();
}

void TopicRecorder::flush() {
  std::lock_guard lock(file_mutex_);
  file_.flush();
}

}  // namespace fedsim::tools
