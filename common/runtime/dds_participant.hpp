// One DDS DomainParticipant per process, created from a named XML profile, with typed
// publishers and subscriptions. The only place that talks to Fast DDS's entity factories.
#pragma once

#include "common/runtime/topic_types.hpp"

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>

namespace fedsim::runtime {

namespace fdds = eprosima::fastdds::dds;

/// A DDS set-up problem (bad profile name, unreadable QoS file...), with a message for humans.
class DdsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ParticipantOptions {
  std::string name = "fedsim";                       // participant name (shown by discovery tools)
  int domain_id = 0;                                 // DDS domain
  std::string qos_file;                              // Fast DDS XML profiles file
  std::string participant_profile = "fedsim_loopback";  // participant profile in qos_file
};

/// Loads the XML profiles once per process (later calls with another file load it too).
void load_qos_profiles(const std::string& qos_file);

class DdsParticipant : public std::enable_shared_from_this<DdsParticipant> {
 public:
  static std::shared_ptr<DdsParticipant> create(const ParticipantOptions& options);
  ~DdsParticipant();
  DdsParticipant(const DdsParticipant&) = delete;
  DdsParticipant& operator=(const DdsParticipant&) = delete;

  fdds::DomainParticipant* participant() const { return participant_; }
  fdds::Publisher* publisher() const { return publisher_; }
  fdds::Subscriber* subscriber() const { return subscriber_; }
  const ParticipantOptions& options() const { return options_; }

  /// The topic of that name and message type (registered and created on first use).
  template <class T>
  fdds::Topic* topic(const std::string& name) {
    return topic_for(name, fdds::TypeSupport(new typename TopicType<T>::PubSubType()));
  }
  /// Same, for a type support built elsewhere (dynamic types in the topic tools).
  fdds::Topic* topic_for(const std::string& name, fdds::TypeSupport type);

  /// True while a RELIABLE DataWriter of `topic` in another participant is known (from
  /// discovery; Fast DDS 2.9 cannot tell a reader its matched writers' QoS). The runtime reads a
  /// lockstep input reliably where its writer offers it (Subscription::read_reliably_too).
  /// Not updated while a tool has replaced the participant's listener (topic_monitor.cpp).
  bool has_reliable_writer(const std::string& topic) const;

  class Listener;

 private:
  explicit DdsParticipant(const ParticipantOptions& options);

  std::unique_ptr<Listener> listener_;  // outlives participant_ (deleted in the destructor body)

  ParticipantOptions options_;
  fdds::DomainParticipant* participant_ = nullptr;
  fdds::Publisher* publisher_ = nullptr;
  fdds::Subscriber* subscriber_ = nullptr;
  std::mutex topics_mutex_;
  std::map<std::string, fdds::Topic*> topics_;
};

}  // namespace fedsim::runtime
