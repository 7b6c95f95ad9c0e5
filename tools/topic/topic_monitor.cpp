#include "tools/topic/topic_monitor.hpp"

#include "common/runtime/shutdown.hpp"

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantFactoryQos.hpp>
#include <fastdds/dds/log/Log.hpp>

#include <limits>
#include <mutex>
#include <ostream>
#include <regex>
#include <sstream>
#include <thread>

namespace fedsim::tools {

namespace rtps = eprosima::fastrtps::rtps;

namespace {

template <class T>
std::string to_text(const T& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

double seconds_of(const eprosima::fastrtps::Duration_t& d) {
  if (d == eprosima::fastrtps::c_TimeInfinite) return std::numeric_limits<double>::infinity();
  return static_cast<double>(d.seconds) + static_cast<double>(d.nanosec) * 1e-9;
}

std::string liveliness_name(fdds::LivelinessQosPolicyKind kind) {
  switch (kind) {
    case fdds::MANUAL_BY_PARTICIPANT_LIVELINESS_QOS: return "MANUAL_BY_PARTICIPANT";
    case fdds::MANUAL_BY_TOPIC_LIVELINESS_QOS: return "MANUAL_BY_TOPIC";
    default: return "AUTOMATIC";
  }
}

std::string representation_name(fdds::DataRepresentationId_t id) {
  switch (id) {
    case fdds::XCDR_DATA_REPRESENTATION: return "XCDR";
    case fdds::XCDR2_DATA_REPRESENTATION: return "XCDR2";
    case fdds::XML_DATA_REPRESENTATION: return "XML";
  }
  return "unknown(" + std::to_string(static_cast<int>(id)) + ")";
}

void fill_locators(EndpointInfo& e, const rtps::RemoteLocatorList& locators) {
  for (const auto& l : locators.unicast) e.unicast_locators.push_back(to_text(l));
  for (const auto& l : locators.multicast) e.multicast_locators.push_back(to_text(l));
}

template <class Qos>
void fill_qos(EndpointInfo& e, const Qos& qos) {
  e.deadline_s = seconds_of(qos.m_deadline.period);
  e.liveliness = liveliness_name(qos.m_liveliness.kind);
  e.liveliness_lease_s = seconds_of(qos.m_liveliness.lease_duration);
  e.by_source_timestamp =
      qos.m_destinationOrder.kind == fdds::BY_SOURCE_TIMESTAMP_DESTINATIONORDER_QOS;
  for (const auto id : qos.representation.m_value) {
    e.representations.push_back(representation_name(id));
  }
  e.reliable = qos.m_reliability.kind == fdds::RELIABLE_RELIABILITY_QOS;
  switch (qos.m_durability.kind) {
    case fdds::VOLATILE_DURABILITY_QOS: e.durability = 0; break;
    case fdds::TRANSIENT_LOCAL_DURABILITY_QOS: e.durability = 1; break;
    case fdds::TRANSIENT_DURABILITY_QOS: e.durability = 2; break;
    case fdds::PERSISTENT_DURABILITY_QOS: e.durability = 3; break;
  }
  e.exclusive_ownership = qos.m_ownership.kind == fdds::EXCLUSIVE_OWNERSHIP_QOS;
  for (auto it = qos.m_partition.begin(); it != qos.m_partition.end(); ++it) {
    e.partitions.emplace_back(it->name());
  }
}

/// Restores the factory's autoenable setting however create() leaves.
class DisabledCreation {
 public:
  DisabledCreation() {
    auto* factory = fdds::DomainParticipantFactory::get_instance();
    factory->get_qos(saved_);
    fdds::DomainParticipantFactoryQos qos = saved_;
    qos.entity_factory().autoenable_created_entities = false;
    factory->set_qos(qos);
  }
  ~DisabledCreation() { fdds::DomainParticipantFactory::get_instance()->set_qos(saved_); }

 private:
  fdds::DomainParticipantFactoryQos saved_;
};

}  // namespace

std::string EndpointInfo::durability_name() const {
  switch (durability) {
    case 1: return "TRANSIENT_LOCAL";
    case 2: return "TRANSIENT";
    case 3: return "PERSISTENT";
    default: return "VOLATILE";
  }
}

std::unique_ptr<TopicMonitor> TopicMonitor::create(const runtime::ParticipantOptions& options) {
  // (The spurious "DYN_TYPES ... MemberId not found" log of remote keyed TypeObjects is silenced
  // for every fedsim process in runtime::load_qos_profiles.)
  std::unique_ptr<TopicMonitor> monitor(new TopicMonitor());
  {
    DisabledCreation disabled;
    monitor->dds_ = runtime::DdsParticipant::create(options);
  }
  auto* participant = monitor->dds_->participant();
  monitor->own_prefix_ = to_text(participant->guid().guidPrefix);
  // Discovery callbacks do not depend on the status mask; none of the data statuses is wanted
  // here (each reader has its own listener).
  participant->set_listener(monitor.get(), fdds::StatusMask::none());
  if (participant->enable() != ReturnCode_t::RETCODE_OK) {
    participant->set_listener(nullptr);
    throw runtime::DdsError("cannot enable the DDS participant of the topic tools");
  }
  return monitor;
}

TopicMonitor::~TopicMonitor() {
  if (dds_ && dds_->participant()) dds_->participant()->set_listener(nullptr);
  dds_.reset();  // last owner: deletes the participant (its threads) while `this` is alive
}

void TopicMonitor::on_participant_discovery(fdds::DomainParticipant*,
                                            rtps::ParticipantDiscoveryInfo&& info) {
  const std::string prefix = to_text(info.info.m_guid.guidPrefix);
  std::lock_guard lock(mutex_);
  switch (info.status) {
    case rtps::ParticipantDiscoveryInfo::DISCOVERED_PARTICIPANT:
    case rtps::ParticipantDiscoveryInfo::CHANGED_QOS_PARTICIPANT:
      participant_names_[prefix] = info.info.m_participantName.to_string();
      break;
    default:  // removed or dropped: its endpoints go too
      participant_names_.erase(prefix);
      for (auto it = endpoints_.begin(); it != endpoints_.end();) {
        it = it->first.rfind(prefix, 0) == 0 ? endpoints_.erase(it) : std::next(it);
      }
      break;
  }
  changed_.notify_all();
}

void TopicMonitor::on_publisher_discovery(fdds::DomainParticipant*,
                                          rtps::WriterDiscoveryInfo&& info) {
  const auto& data = info.info;
  EndpointInfo e;
  e.guid = to_text(data.guid());
  e.topic = data.topicName().to_string();
  e.type_name = data.typeName().to_string();
  e.writer = true;
  e.keyed = data.topicKind() == rtps::WITH_KEY;
  e.max_serialized_size = data.typeMaxSerialized();
  fill_qos(e, data.m_qos);
  e.ownership_strength = data.m_qos.m_ownershipStrength.value;
  e.lifespan_s = seconds_of(data.m_qos.m_lifespan.duration);
  fill_locators(e, data.remote_locators());
  if (data.has_type() && data.has_type_id() && data.type().m_type_object._d() != 0) {
    e.type_object = std::make_shared<eprosima::fastrtps::types::TypeObject>(
        data.type().m_type_object);
    e.type_identifier = std::make_shared<eprosima::fastrtps::types::TypeIdentifier>(
        data.type_id().m_type_identifier);
  }
  update(std::move(e), info.status == rtps::WriterDiscoveryInfo::REMOVED_WRITER);
}

void TopicMonitor::on_subscriber_discovery(fdds::DomainParticipant*,
                                           rtps::ReaderDiscoveryInfo&& info) {
  const auto& data = info.info;
  EndpointInfo e;
  e.guid = to_text(data.guid());
  e.topic = data.topicName().to_string();
  e.type_name = data.typeName().to_string();
  e.writer = false;
  e.keyed = data.topicKind() == rtps::WITH_KEY;
  fill_qos(e, data.m_qos);
  fill_locators(e, data.remote_locators());
  update(std::move(e), info.status == rtps::ReaderDiscoveryInfo::REMOVED_READER);
}

void TopicMonitor::update(EndpointInfo info, bool removed) {
  if (info.guid.rfind(own_prefix_, 0) == 0) return;  // the tool's own endpoints
  std::lock_guard lock(mutex_);
  if (removed) {
    endpoints_.erase(info.guid);
  } else {
    endpoints_[info.guid] = std::move(info);
  }
  changed_.notify_all();
}

std::map<std::string, TopicInfo> TopicMonitor::topics() const {
  std::lock_guard lock(mutex_);
  std::map<std::string, TopicInfo> result;
  for (const auto& [guid, endpoint] : endpoints_) {
    EndpointInfo e = endpoint;
    const std::string prefix = guid.substr(0, guid.find('|'));
    if (auto it = participant_names_.find(prefix); it != participant_names_.end()) {
      e.participant = it->second;
    }
    TopicInfo& topic = result[e.topic];
    topic.name = e.topic;
    topic.type_names.insert(e.type_name);
    (e.writer ? topic.writers : topic.readers).push_back(std::move(e));
  }
  return result;
}

std::optional<TopicInfo> TopicMonitor::topic(const std::string& name) const {
  auto all = topics();
  auto it = all.find(name);
  if (it == all.end()) return std::nullopt;
  return it->second;
}

std::optional<TopicInfo> TopicMonitor::wait_for_topic(
    const std::string& name, std::chrono::milliseconds timeout,
    const std::function<bool(const TopicInfo&)>& predicate) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    auto found = topic(name);
    if (found && predicate(*found)) return found;
    if (std::chrono::steady_clock::now() >= until || runtime::shutdown_requested()) return found;
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, std::chrono::milliseconds(20));
  }
}

fdds::DataReaderQos reader_qos_matching(const std::vector<EndpointInfo>& writers, int depth) {
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  bool reliable = !writers.empty();
  bool transient_local = !writers.empty();
  bool exclusive = !writers.empty();
  for (const auto& w : writers) {
    reliable = reliable && w.reliable;
    transient_local = transient_local && w.durability >= 1;
    exclusive = exclusive && w.exclusive_ownership;
  }
  qos.reliability().kind =
      reliable ? fdds::RELIABLE_RELIABILITY_QOS : fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.durability().kind =
      transient_local ? fdds::TRANSIENT_LOCAL_DURABILITY_QOS : fdds::VOLATILE_DURABILITY_QOS;
  qos.ownership().kind = exclusive ? fdds::EXCLUSIVE_OWNERSHIP_QOS : fdds::SHARED_OWNERSHIP_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = depth;
  constexpr int kMaxInstances = 1024;
  qos.resource_limits().max_instances = kMaxInstances;
  qos.resource_limits().max_samples_per_instance = depth;
  qos.resource_limits().max_samples = kMaxInstances * depth;
  qos.resource_limits().allocated_samples = std::min(100, kMaxInstances * depth);
  qos.data_sharing().off();
  return qos;
}

std::optional<TopicInfo> discover_topic(TopicMonitor& monitor, const std::string& topic,
                                        std::chrono::milliseconds wait) {
  auto found = monitor.wait_for_topic(topic, wait,
                                      [](const TopicInfo& t) { return !t.writers.empty(); });
  if (found && !found->writers.empty()) {
    constexpr auto kSettle = std::chrono::milliseconds(250);
    std::this_thread::sleep_for(kSettle);
    found = monitor.topic(topic);
  }
  return found;
}

std::optional<RawTopicShape> discover_raw_topic(TopicMonitor& monitor, const std::string& command,
                                                const std::string& topic, std::chrono::milliseconds wait,
                                                int domain_id, std::ostream& err) {
  const auto found = discover_topic(monitor, topic, wait);
  if (!found) {
    err << "fedsim topic " << command << ": topic '" << topic << "' not found on domain " << domain_id
        << " after " << wait.count() / 1000.0 << " s (`fedsim topic list` shows the live topics)\n";
    return std::nullopt;
  }
  if (found->type_names.size() != 1) {
    err << "fedsim topic " << command << ": topic '" << topic << "' is used with several types\n";
    return std::nullopt;
  }
  RawTopicShape shape{*found, *found->type_names.begin()};
  for (const auto& e : found->writers) {
    shape.keyed = shape.keyed || e.keyed;
    shape.max_size = std::max(shape.max_size, e.max_serialized_size);
  }
  if (found->writers.empty()) {
    for (const auto& e : found->readers) shape.keyed = shape.keyed || e.keyed;
    err << "fedsim topic " << command << ": '" << topic << "' has no writer yet; waiting for one\n";
  }
  return shape;
}

void report_periodically(double period_s, double duration_s, const std::function<std::string()>& report,
                         std::ostream& out) {
  const auto ms = [](double s) { return std::chrono::milliseconds(static_cast<long long>(s * 1000.0)); };
  const auto start = std::chrono::steady_clock::now();
  const auto period = ms(period_s > 0 ? period_s : 1.0);
  while (!runtime::wait_for_shutdown(period)) {
    out << report();
    out.flush();
    if (duration_s > 0 && std::chrono::steady_clock::now() - start >= ms(duration_s)) break;
  }
}

ftypes::DynamicType_ptr dynamic_type_for(const TopicInfo& topic) {
  if (topic.type_names.size() != 1) {
    std::string names;
    for (const auto& n : topic.type_names) names += (names.empty() ? "" : ", ") + n;
    throw runtime::DdsError("topic '" + topic.name + "' is used with several types (" + names +
                            ")");
  }
  const std::string& type_name = *topic.type_names.begin();
  if (auto type = dynamic_type_by_name(type_name)) return type;
  for (const auto& w : topic.writers) {
    if (w.type_object && w.type_identifier) {
      if (auto type = dynamic_type_from_object(type_name, *w.type_identifier, *w.type_object)) {
        return type;
      }
    }
  }
  throw runtime::DdsError("type '" + type_name + "' of topic '" + topic.name +
                          "' is unknown: it is not in fedsim's IDL and its writers sent no "
                          "complete TypeObject");
}

}  // namespace fedsim::tools
