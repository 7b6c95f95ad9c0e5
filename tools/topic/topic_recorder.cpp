#include "tools/topic/topic_recorder.hpp"

#include <fastrtps/types/DynamicData.h>
#include <fastrtps/types/DynamicType.h>

#include <chrono>
#include <cstdlib>

namespace fedsim::tools {

namespace {
/// The time cell (first column) of a recorded line as simulation time; nullopt when unreadable.
std::optional<double> leading_number(const std::string& line) {
  char* end = nullptr;
  const double t = std::strtod(line.c_str(), &end);
  if (end == line.c_str() || (*end != ',' && *end != '\n')) return std::nullopt;
  return t;
}
}  // namespace

std::optional<double> TopicRecorder::row_sim_time(const std::string& line) const {
  return layout_.has_sim_time() ? leading_number(line) : std::nullopt;
}

TopicRecorder::TopicRecorder(const std::string& topic, ftypes::DynamicType_ptr type,
                             const std::filesystem::path& file)
    : topic_(topic), type_(std::move(type)), layout_(type_), path_(file) {
  file_.open(path_, std::ios::out | std::ios::trunc);
  if (!file_) throw std::runtime_error("cannot write " + path_.string());
  const std::string header = layout_.header() + '\n';
  file_ << header;
  header_bytes_ = bytes_ = header.size();
  flush();
}

TopicRecorder::~TopicRecorder() {
  try {
    close();
    drain();
    flush();
  } catch (const std::exception&) {
    // Nothing more can be done while destroying; flush() reports errors when called directly.
  }
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
  for (const auto& line : lines) {
    index_.add_row(row_sim_time(line), bytes_);
    file_ << line;
    bytes_ += line.size();
  }
  written_.fetch_add(lines.size());
  return lines.size();
}

void TopicRecorder::flush() {
  std::lock_guard lock(file_mutex_);
  file_.flush();
  // Written whole each time (small: one seek entry a second), so a recording cut short by a
  // crash still has an index that matches its flushed rows.
  const auto index_path = index_file_for(path_);
  std::ofstream index(index_path, std::ios::out | std::ios::trunc);
  index << index_.to_json(topic_, type_->get_name(), path_.filename().string(), header_bytes_,
                          layout_.columns());
  if (!index) throw std::runtime_error("cannot write " + index_path.string());
}

}  // namespace fedsim::tools
