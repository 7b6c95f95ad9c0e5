// Live topic discovery for the topic tools: a participant (from the runtime's XML profiles, so
// loopback-only by default) with a DomainParticipantListener that collects every remote
// participant, writer and reader: topic and type names, participant names, reliability and
// durability. Works for topics of any type, fedsim's or not.
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "tools/topic/dynamic_types.hpp"

#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastrtps/types/TypeObject.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fedsim::tools {

namespace fdds = eprosima::fastdds::dds;

/// One discovered writer or reader.
struct EndpointInfo {
  std::string guid;              // "01.0f.xx...|0.0.1.3"
  std::string participant;       // participant name ("" until the participant is known)
  std::string topic;
  std::string type_name;
  bool writer = true;
  bool keyed = false;            // topic kind WITH_KEY
  bool reliable = false;         // RELIABLE (else BEST_EFFORT)
  int durability = 0;            // 0 volatile, 1 transient-local, 2 transient, 3 persistent
  bool exclusive_ownership = false;
  std::vector<std::string> partitions;
  std::uint32_t max_serialized_size = 0;  // writers: as announced (0 if unknown)
  // More of the QoS discovery announces (`fedsim topic info`); infinite periods are +inf.
  // HISTORY is not part of RTPS discovery data: no tool can show a remote endpoint's history.
  double deadline_s = 0.0;
  std::string liveliness = "AUTOMATIC";  // AUTOMATIC | MANUAL_BY_PARTICIPANT | MANUAL_BY_TOPIC
  double liveliness_lease_s = 0.0;
  std::uint32_t ownership_strength = 0;  // writers
  double lifespan_s = 0.0;               // writers
  bool by_source_timestamp = false;      // DESTINATION_ORDER
  std::vector<std::string> representations;  // XCDR / XCDR2 / XML (empty = not announced)
  std::vector<std::string> unicast_locators;    // "UDPv4:[127.0.0.1]:7411"
  std::vector<std::string> multicast_locators;
  // The TypeObject a writer sent in discovery (only writers configured to send one).
  std::shared_ptr<eprosima::fastrtps::types::TypeObject> type_object;
  std::shared_ptr<eprosima::fastrtps::types::TypeIdentifier> type_identifier;

  std::string reliability_name() const { return reliable ? "RELIABLE" : "BEST_EFFORT"; }
  std::string durability_name() const;
};

struct TopicInfo {
  std::string name;
  std::set<std::string> type_names;
  std::vector<EndpointInfo> writers;
  std::vector<EndpointInfo> readers;
};

class TopicMonitor : public fdds::DomainParticipantListener {
 public:
  /// Creates the participant with this listener installed before it is enabled, so no
  /// discovery event is missed. The participant can carry the tool's own readers too.
  static std::unique_ptr<TopicMonitor> create(const runtime::ParticipantOptions& options);
  ~TopicMonitor() override;

  const std::shared_ptr<runtime::DdsParticipant>& dds() const { return dds_; }

  /// Every topic seen so far (other participants only), by name.
  std::map<std::string, TopicInfo> topics() const;
  /// The topic if seen so far.
  std::optional<TopicInfo> topic(const std::string& name) const;
  /// Waits until `predicate(topic)` holds for the named topic, or the timeout passes or
  /// shutdown is requested; returns the topic as last seen.
  std::optional<TopicInfo> wait_for_topic(const std::string& name, std::chrono::milliseconds timeout,
                                          const std::function<bool(const TopicInfo&)>& predicate);

  void on_participant_discovery(fdds::DomainParticipant*,
                                eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override;
  void on_publisher_discovery(fdds::DomainParticipant*,
                              eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override;
  void on_subscriber_discovery(fdds::DomainParticipant*,
                               eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override;

 private:
  TopicMonitor() = default;
  void update(EndpointInfo info, bool removed);

  std::shared_ptr<runtime::DdsParticipant> dds_;
  std::string own_prefix_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::string, std::string> participant_names_;  // guid prefix -> name
  std::map<std::string, EndpointInfo> endpoints_;         // guid -> endpoint
};

/// Reader QoS that matches what the writers offer: RELIABLE only if every writer is reliable,
/// TRANSIENT_LOCAL only if every writer keeps history for late joiners (so the last command or
/// status shows), their ownership kind, KEEP_LAST `depth` per instance, room for many instances,
/// data-sharing off. Without writers: best effort, volatile.
fdds::DataReaderQos reader_qos_matching(const std::vector<EndpointInfo>& writers, int depth);

/// Waits up to `wait` for a writer of `topic`, then briefly for more writers of it (so the reader
/// QoS can match them all); returns what is known (maybe readers only), nullopt if nothing.
std::optional<TopicInfo> discover_topic(TopicMonitor& monitor, const std::string& topic,
                                        std::chrono::milliseconds wait);

/// What a raw reader (`fedsim topic hz|bw`, any type) needs of a discovered topic.
struct RawTopicShape {
  TopicInfo topic;
  std::string type_name;
  bool keyed = false;           // any writer (or, without writers, reader) says WITH_KEY
  std::uint32_t max_size = 0;   // the largest serialized size a writer announced (0: unknown)
};
/// discover_topic for the command `command` ("hz", "bw"): nullopt, with the reason on `err`
/// ("fedsim topic <command>: ..."), if the topic is not found or has several types; a note on
/// `err` if it has no writer yet.
std::optional<RawTopicShape> discover_raw_topic(TopicMonitor& monitor, const std::string& command,
                                                const std::string& topic, std::chrono::milliseconds wait,
                                                int domain_id, std::ostream& err);

/// Prints `report()` every `period_s` seconds (1 s if not positive) until Ctrl-C/SIGTERM or, with
/// `duration_s` > 0, until that many seconds have passed (`fedsim topic hz|bw`).
void report_periodically(double period_s, double duration_s, const std::function<std::string()>& report,
                         std::ostream& out);

/// The DynamicType of a discovered topic: from fedsim's registered TypeObjects by type name,
/// else from a complete TypeObject a writer sent. Throws runtime::DdsError with a clear message
/// if neither is available or the topic's endpoints disagree on the type.
ftypes::DynamicType_ptr dynamic_type_for(const TopicInfo& topic);

}  // namespace fedsim::tools
