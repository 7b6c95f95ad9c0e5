// fedsim topic list: every topic seen during the discovery time, with its type and the number of
// writers and readers; -v adds each endpoint's participant and QoS.
#include "tools/topic/topic_monitor.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/shutdown.hpp"

#include <algorithm>
#include <ostream>

namespace fedsim::tools {

namespace {

std::string join_types(const TopicInfo& topic) {
  std::string types;
  for (const auto& t : topic.type_names) types += (types.empty() ? "" : " | ") + t;
  return types;
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

void print_endpoint(const EndpointInfo& e, bool with_type, std::ostream& out) {
  out << "    - " << (e.participant.empty() ? "(unknown participant)" : e.participant) << "  "
      << e.reliability_name() << " " << e.durability_name();
  if (e.exclusive_ownership) out << " EXCLUSIVE";
  if (e.keyed) out << " keyed";
  if (!e.partitions.empty()) {
    out << " partitions=";
    for (std::size_t i = 0; i < e.partitions.size(); ++i) out << (i ? "," : "") << e.partitions[i];
  }
  if (with_type) out << " type=" << e.type_name;
  out << "  guid=" << e.guid << "\n";
}

}  // namespace

int run_topic_list(const ListOptions& options, std::ostream& out, std::ostream& err) {
  try {
    runtime::install_shutdown_handler();
    auto dds_options = options.dds;
    if (dds_options.name == "fedsim") dds_options.name = "fedsim-topic-list";
    auto monitor = TopicMonitor::create(dds_options);
    runtime::wait_for_shutdown(
        std::chrono::milliseconds(static_cast<long long>(options.wait_s * 1000.0)));
    const auto topics = monitor->topics();
    if (topics.empty()) {
      err << "no topics discovered on domain " << options.dds.domain_id << " in " << options.wait_s
          << " s\n";
      return 0;
    }
    std::size_t name_width = 0;
    for (const auto& [name, topic] : topics) name_width = std::max(name_width, name.size());
    for (const auto& [name, topic] : topics) {
      if (!options.verbose) {
        out << name << std::string(name_width - name.size() + 2, ' ') << "[" << join_types(topic)
            << "]  " << plural(topic.writers.size(), "writer") << ", "
            << plural(topic.readers.size(), "reader") << "\n";
        continue;
      }
      out << name << " [" << join_types(topic) << "]\n";
      out << "  " << plural(topic.writers.size(), "writer") << (topic.writers.empty() ? "" : ":")
          << "\n";
      for (const auto& w : topic.writers) print_endpoint(w, topic.type_names.size() > 1, out);
      out << "  " << plural(topic.readers.size(), "reader") << (topic.readers.empty() ? "" : ":")
          << "\n";
      for (const auto& r : topic.readers) print_endpoint(r, topic.type_names.size() > 1, out);
    }
    out.flush();
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim topic list: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace fedsim::tools
