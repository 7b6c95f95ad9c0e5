#include "tools/topic/topic_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace fedsim::tools {

BandwidthWindow::BandwidthWindow(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

void BandwidthWindow::add(std::int64_t arrival_ns, std::uint64_t bytes) {
  entries_.push_back({arrival_ns, bytes});
  if (entries_.size() > capacity_) entries_.pop_front();
  ++total_;
}

BandwidthStats BandwidthWindow::stats(std::int64_t now_ns) const {
  BandwidthStats s;
  s.samples = entries_.size();
  if (entries_.empty()) return s;
  std::uint64_t sum = 0;
  s.min_bytes = entries_.front().bytes;
  for (const auto& e : entries_) {
    sum += e.bytes;
    s.min_bytes = std::min(s.min_bytes, e.bytes);
    s.max_bytes = std::max(s.max_bytes, e.bytes);
  }
  s.mean_bytes = static_cast<double>(sum) / static_cast<double>(s.samples);
  s.span_s = std::max(0.0, (now_ns - entries_.front().arrival_ns) * 1e-9);
  if (s.span_s > 0.0) {
    s.bytes_per_s = static_cast<double>(sum) / s.span_s;
    s.samples_per_s = static_cast<double>(s.samples) / s.span_s;
  }
  return s;
}

std::string format_bytes(double bytes) {
  char text[64];
  if (bytes < 1000.0) {
    std::snprintf(text, sizeof(text), "%.0f B", bytes);
  } else if (bytes < 1e6) {
    std::snprintf(text, sizeof(text), "%.2f KB", bytes / 1e3);
  } else {
    std::snprintf(text, sizeof(text), "%.2f MB", bytes / 1e6);
  }
  return text;
}

std::string format_bandwidth(const BandwidthStats& s) {
  char rate[64];
  std::snprintf(rate, sizeof(rate), "%.2f", s.samples_per_s);
  char mean[32];
  std::snprintf(mean, sizeof(mean), "%.1f B", s.mean_bytes);
  return format_bytes(s.bytes_per_s) + "/s from " + std::to_string(s.samples) + " samples (" +
         rate + " samples/s)\n\tsample size mean: " +
         (s.mean_bytes < 1000.0 ? std::string(mean) : format_bytes(s.mean_bytes)) +
         " min: " + format_bytes(static_cast<double>(s.min_bytes)) +
         " max: " + format_bytes(static_cast<double>(s.max_bytes)) + "\n";
}

namespace {

std::string seconds_text(double s) {
  if (std::isinf(s)) return "infinite";
  char text[32];
  std::snprintf(text, sizeof(text), "%g s", s);
  return text;
}

std::string join(const std::vector<std::string>& items, const char* none) {
  if (items.empty()) return none;
  std::string text;
  for (const auto& i : items) text += (text.empty() ? "" : ", ") + i;
  return text;
}

int liveliness_rank(const std::string& kind) {
  if (kind == "MANUAL_BY_TOPIC") return 2;
  if (kind == "MANUAL_BY_PARTICIPANT") return 1;
  return 0;
}

std::string endpoint_name(const EndpointInfo& e) {
  return e.participant.empty() ? e.guid : e.participant;
}

void print_endpoint(const EndpointInfo& e, std::ostringstream& out) {
  out << "  - participant: " << (e.participant.empty() ? "(unknown)" : e.participant) << "\n"
      << "    guid: " << e.guid << "\n"
      << "    type: " << e.type_name << (e.keyed ? " (keyed)" : " (no key)") << "\n"
      << "    reliability: " << e.reliability_name() << "\n"
      << "    durability: " << e.durability_name() << "\n"
      << "    deadline: " << seconds_text(e.deadline_s) << "\n"
      << "    liveliness: " << e.liveliness << ", lease " << seconds_text(e.liveliness_lease_s)
      << "\n"
      << "    ownership: " << (e.exclusive_ownership ? "EXCLUSIVE" : "SHARED");
  if (e.writer && e.exclusive_ownership) out << ", strength " << e.ownership_strength;
  out << "\n";
  if (e.writer) out << "    lifespan: " << seconds_text(e.lifespan_s) << "\n";
  out << "    destination order: "
      << (e.by_source_timestamp ? "BY_SOURCE_TIMESTAMP" : "BY_RECEPTION_TIMESTAMP") << "\n"
      << "    data representation: " << join(e.representations, "not announced (XCDR)") << "\n";
  if (!e.partitions.empty()) out << "    partitions: " << join(e.partitions, "") << "\n";
  if (e.writer && e.max_serialized_size > 0) {
    out << "    max serialized size: " << e.max_serialized_size << " B\n";
  }
  out << "    unicast locators: " << join(e.unicast_locators, "(participant's)") << "\n";
  if (!e.multicast_locators.empty()) {
    out << "    multicast locators: " << join(e.multicast_locators, "") << "\n";
  }
}

}  // namespace

std::vector<std::string> qos_incompatibilities(const EndpointInfo& w, const EndpointInfo& r) {
  std::vector<std::string> why;
  if (w.type_name != r.type_name) why.push_back("type " + w.type_name + " vs " + r.type_name);
  if (r.reliable && !w.reliable) why.push_back("reliability: reader RELIABLE, writer BEST_EFFORT");
  if (r.durability > w.durability) {
    why.push_back("durability: reader " + r.durability_name() + ", writer " + w.durability_name());
  }
  if (r.exclusive_ownership != w.exclusive_ownership) {
    why.push_back(std::string("ownership: reader ") +
                  (r.exclusive_ownership ? "EXCLUSIVE" : "SHARED") + ", writer " +
                  (w.exclusive_ownership ? "EXCLUSIVE" : "SHARED"));
  }
  if (w.deadline_s > r.deadline_s) {
    why.push_back("deadline: reader requests " + seconds_text(r.deadline_s) + ", writer offers " +
                  seconds_text(w.deadline_s));
  }
  if (liveliness_rank(w.liveliness) < liveliness_rank(r.liveliness) ||
      w.liveliness_lease_s > r.liveliness_lease_s) {
    why.push_back("liveliness: reader requests " + r.liveliness + " lease " +
                  seconds_text(r.liveliness_lease_s) + ", writer offers " + w.liveliness +
                  " lease " + seconds_text(w.liveliness_lease_s));
  }
  // No representation announced means XCDR (DDS-XTypes 1.3, 7.6.3.1.1); a writer uses its first.
  const auto offered = w.representations.empty() ? std::vector<std::string>{"XCDR"}
                                                  : w.representations;
  const auto accepted = r.representations.empty() ? std::vector<std::string>{"XCDR"}
                                                  : r.representations;
  if (std::find(accepted.begin(), accepted.end(), offered.front()) == accepted.end()) {
    why.push_back("data representation: writer " + offered.front() + ", reader accepts " +
                  join(accepted, ""));
  }
  if (w.partitions != r.partitions) why.push_back("partitions differ");
  return why;
}

std::string format_topic_info(const TopicInfo& topic) {
  std::ostringstream out;
  out << "topic: " << topic.name << "\n"
      << "type: " << join({topic.type_names.begin(), topic.type_names.end()}, "(unknown)") << "\n"
      << "writers: " << topic.writers.size() << "\n";
  for (const auto& w : topic.writers) print_endpoint(w, out);
  out << "readers: " << topic.readers.size() << "\n";
  for (const auto& r : topic.readers) {
    print_endpoint(r, out);
    for (const auto& w : topic.writers) {
      const auto why = qos_incompatibilities(w, r);
      if (why.empty()) continue;
      out << "    DOES NOT MATCH writer " << endpoint_name(w) << ": " << join(why, "") << "\n";
    }
  }
  out << "(history depth is not announced in RTPS discovery; it is each endpoint's own)\n";
  return out.str();
}

}  // namespace fedsim::tools
