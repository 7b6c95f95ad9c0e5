// fedsim topic echo: subscribes to a topic through a DynamicType built from its TypeObject (the
// C++ type is not needed) and prints every sample, YAML-like ("---" after each) or as JSON lines.
#include "tools/topic/dynamic_reader.hpp"
#include "tools/topic/sample_tree.hpp"
#include "tools/topic/topic_monitor.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/shutdown.hpp"

#include <fastrtps/types/DynamicDataFactory.h>

#include <condition_variable>
#include <mutex>
#include <ostream>

namespace fedsim::tools {

namespace {

std::chrono::milliseconds to_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

}  // namespace

int run_topic_echo(const EchoOptions& options, std::ostream& out, std::ostream& err) {
  try {
    runtime::install_shutdown_handler();
    auto dds_options = options.dds;
    if (dds_options.name == "fedsim") dds_options.name = "fedsim-topic-echo";
    auto monitor = TopicMonitor::create(dds_options);
    const auto topic = discover_topic(*monitor, options.topic, to_ms(options.wait_s));
    if (!topic) {
      err << "fedsim topic echo: topic '" << options.topic << "' not found on domain "
          << options.dds.domain_id << " after " << options.wait_s
          << " s (`fedsim topic list` shows the live topics)\n";
      return 1;
    }
    const ftypes::DynamicType_ptr type = dynamic_type_for(*topic);
    if (!options.field.empty()) {
      // Check the field path on an empty sample before waiting for data.
      auto* probe = ftypes::DynamicDataFactory::get_instance()->create_data(type);
      const SampleNode empty = read_sample(*probe, type);
      ftypes::DynamicDataFactory::get_instance()->delete_data(probe);
      std::string error;
      if (!select_field(empty, options.field, error)) {
        err << "fedsim topic echo: " << error << "\n";
        return 1;
      }
    }
    if (topic->writers.empty()) {
      err << "fedsim topic echo: '" << options.topic << "' has no writer yet; waiting for one\n";
    }

    std::mutex mutex;
    std::condition_variable done_cv;
    std::uint64_t printed = 0;
    bool done = false;
    DynamicReader reader(
        monitor->dds(), options.topic, dynamic_type_support(type),
        reader_qos_matching(topic->writers, 64), [&](void* sample, const fdds::SampleInfo&) {
          const SampleNode tree = read_sample(*static_cast<ftypes::DynamicData*>(sample), type);
          std::string text;
          const SampleNode* node = &tree;
          std::optional<SampleNode> selected;
          if (!options.field.empty()) {
            std::string error;
            selected = select_field(tree, options.field, error);
            if (!selected) {
              text = "<" + error + ">";
            } else {
              node = &*selected;
            }
          }
          if (text.empty()) text = options.json ? to_json(*node) : to_yaml(*node);
          if (options.json) {
            text += "\n";
          } else {
            if (text.empty() || text.back() != '\n') text += "\n";
            text += "---\n";
          }
          std::lock_guard lock(mutex);
          if (done) return;
          out << text;
          out.flush();
          ++printed;
          if (options.count != 0 && printed >= options.count) {
            done = true;
            done_cv.notify_all();
          }
        });

    const auto deadline = options.timeout_s > 0
                              ? std::chrono::steady_clock::now() + to_ms(options.timeout_s)
                              : std::chrono::steady_clock::time_point::max();
    bool timed_out = false;
    {
      std::unique_lock lock(mutex);
      while (!done && !runtime::shutdown_requested()) {
        if (std::chrono::steady_clock::now() >= deadline) {
          timed_out = true;
          break;
        }
        done_cv.wait_for(lock, std::chrono::milliseconds(50));
      }
      done = true;  // nothing more is printed while the reader closes
    }
    reader.close();
    if (timed_out) {
      err << "fedsim topic echo: received " << printed << " of " << options.count
          << " samples of '" << options.topic << "' in " << options.timeout_s << " s ("
          << reader.matched_writers() << " of " << topic->writers.size()
          << " writers matched)\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim topic echo: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fedsim::tools
