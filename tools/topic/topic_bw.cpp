// fedsim topic bw: the bandwidth a topic uses (bytes/s, samples/s, sample sizes) over a sliding
// window, once a second, like `ros2 topic bw`. Sizes are the serialized payloads as received
// (raw bytes, encapsulation header included), so any type works, fedsim's or another vendor's.
#include "tools/topic/dynamic_reader.hpp"
#include "tools/topic/raw_type.hpp"
#include "tools/topic/topic_monitor.hpp"
#include "tools/topic/topic_stats.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/shutdown.hpp"

#include <algorithm>
#include <mutex>
#include <ostream>

namespace fedsim::tools {

namespace {

std::chrono::milliseconds to_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

int run_topic_bw(const BwOptions& options, std::ostream& out, std::ostream& err) {
  try {
    runtime::install_shutdown_handler();
    auto dds_options = options.dds;
    if (dds_options.name == "fedsim") dds_options.name = "fedsim-topic-bw";
    auto monitor = TopicMonitor::create(dds_options);
    const auto shape = discover_raw_topic(*monitor, "bw", options.topic, to_ms(options.wait_s),
                                          options.dds.domain_id, err);
    if (!shape) return 1;
    const TopicInfo* topic = &shape->topic;
    const bool keyed = shape->keyed;
    const std::uint32_t max_size = shape->max_size;
    fdds::TypeSupport support(new RawPubSubType(*topic->type_names.begin(), keyed,
                                                max_size > 0 ? max_size : 65000));
    std::mutex mutex;
    BandwidthWindow window(options.window);
    DynamicReader reader(monitor->dds(), options.topic, support,
                         reader_qos_matching(topic->writers, 64),
                         [&](void* sample, const fdds::SampleInfo&) {
                           const auto bytes = static_cast<RawSample*>(sample)->bytes.size();
                           std::lock_guard lock(mutex);
                           window.add(now_ns(), bytes);
                         });

    std::uint64_t reported_total = 0;
    report_periodically(options.report_period_s, options.duration_s, [&] {
      std::lock_guard lock(mutex);
      std::string report = window.total_samples() == reported_total ? std::string("no new messages\n")
                                                                    : format_bandwidth(window.stats(now_ns()));
      reported_total = window.total_samples();
      return report;
    }, out);
    reader.close();
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim topic bw: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fedsim::tools
