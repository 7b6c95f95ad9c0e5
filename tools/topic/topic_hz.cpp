// fedsim topic hz: the receive rate of a topic over a sliding window, once a second, like
// `ros2 topic hz`. Samples are not decoded (raw bytes), so any type works.
#include "tools/topic/dynamic_reader.hpp"
#include "tools/topic/dynamic_types.hpp"
#include "tools/topic/raw_type.hpp"
#include "tools/topic/topic_monitor.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/shutdown.hpp"

#include <cmath>
#include <cstdio>
#include <deque>
#include <mutex>
#include <ostream>

namespace fedsim::tools {

namespace {

std::chrono::milliseconds to_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

std::string format_report(const std::deque<std::int64_t>& stamps_ns) {
  const std::size_t n = stamps_ns.size();
  double sum = 0.0, sum_sq = 0.0, min_p = 1e300, max_p = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    const double p = (stamps_ns[i] - stamps_ns[i - 1]) * 1e-9;
    sum += p;
    sum_sq += p * p;
    min_p = std::min(min_p, p);
    max_p = std::max(max_p, p);
  }
  const double periods = static_cast<double>(n - 1);
  const double mean = sum / periods;
  const double std_dev = std::sqrt(std::max(0.0, sum_sq / periods - mean * mean));
  char buf[256];
  std::snprintf(buf, sizeof(buf),
                "average rate: %.3f\n\tmin: %.3fs max: %.3fs std dev: %.5fs window: %zu\n",
                mean > 0 ? 1.0 / mean : 0.0, min_p, max_p, std_dev, n);
  return buf;
}

}  // namespace

int run_topic_hz(const HzOptions& options, std::ostream& out, std::ostream& err) {
  try {
    runtime::install_shutdown_handler();
    auto dds_options = options.dds;
    if (dds_options.name == "fedsim") dds_options.name = "fedsim-topic-hz";
    auto monitor = TopicMonitor::create(dds_options);
    const auto shape = discover_raw_topic(*monitor, "hz", options.topic, to_ms(options.wait_s),
                                          options.dds.domain_id, err);
    if (!shape) return 1;
    const TopicInfo* topic = &shape->topic;
    const bool keyed = shape->keyed;
    const std::uint32_t max_size = shape->max_size;
    // A fedsim type is read through its DynamicType, which computes instance keys; raw bytes
    // are the fallback for foreign types (keyed ones then rely on the writer's key hash).
    const std::string& type_name = shape->type_name;
    const auto dynamic_type = dynamic_type_by_name(type_name);
    fdds::TypeSupport support =
        dynamic_type ? dynamic_type_support(dynamic_type)
                     : fdds::TypeSupport(new RawPubSubType(type_name, keyed,
                                                           max_size > 0 ? max_size : 65000));

    const std::size_t window = std::max<std::size_t>(options.window, 2);
    std::mutex mutex;
    std::deque<std::int64_t> stamps_ns;
    std::uint64_t total = 0;
    DynamicReader reader(monitor->dds(), options.topic, support,
                         reader_qos_matching(topic->writers, 64),
                         [&](void*, const fdds::SampleInfo&) {
                           const auto now = std::chrono::steady_clock::now().time_since_epoch();
                           std::lock_guard lock(mutex);
                           stamps_ns.push_back(
                               std::chrono::duration_cast<std::chrono::nanoseconds>(now).count());
                           if (stamps_ns.size() > window) stamps_ns.pop_front();
                           ++total;
                         });

    std::uint64_t reported_total = 0;
    report_periodically(options.report_period_s, options.duration_s, [&] {
      std::lock_guard lock(mutex);
      std::string report;
      if (total == reported_total) {
        report = "no new messages\n";
      } else if (stamps_ns.size() >= 2) {
        report = format_report(stamps_ns);
      }
      reported_total = total;
      return report;
    }, out);
    reader.close();
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim topic hz: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fedsim::tools
