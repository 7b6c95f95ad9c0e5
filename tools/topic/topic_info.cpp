// fedsim topic info: one topic's type and every writer and reader discovered on it, with the QoS
// each announces and its locators (what an outside team needs to match fedsim's QoS).
#include "tools/topic/topic_monitor.hpp"
#include "tools/topic/topic_stats.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/shutdown.hpp"

#include <ostream>
#include <thread>

namespace fedsim::tools {

int run_topic_info(const InfoOptions& options, std::ostream& out, std::ostream& err) {
  try {
    runtime::install_shutdown_handler();
    auto dds_options = options.dds;
    if (dds_options.name == "fedsim") dds_options.name = "fedsim-topic-info";
    auto monitor = TopicMonitor::create(dds_options);
    // Every endpoint of the topic, not only the first one: wait the whole discovery time.
    runtime::wait_for_shutdown(
        std::chrono::milliseconds(static_cast<long long>(options.wait_s * 1000.0)));
    const auto topic = monitor->topic(options.topic);
    if (!topic) {
      err << "fedsim topic info: topic '" << options.topic << "' not found on domain "
          << options.dds.domain_id << " after " << options.wait_s
          << " s (`fedsim topic list` shows the live topics)\n";
      return 1;
    }
    out << format_topic_info(*topic);
    out.flush();
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim topic info: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fedsim::tools
