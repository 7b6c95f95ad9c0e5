// Incompatible QoS between a fedsim endpoint and a remote one (DDS "requested/offered
// incompatible QoS"): the two never match and no data flows, which without this is silent on
// the fedsim side (issue 11: an outside writer with the wrong reliability, deadline or
// ownership). Every Subscription and Publisher of the runtime reports it here: a warning on the
// process's logger naming the topic, the side, the policy and the local profile, once per
// policy per endpoint (a remote that keeps rediscovering does not flood the log), and a count.
#pragma once

#include <fastdds/dds/core/policy/QosPolicies.hpp>
#include <fastdds/dds/core/status/IncompatibleQosStatus.hpp>
#include <spdlog/spdlog.h>

#include <atomic>
#include <bitset>
#include <cstdint>
#include <mutex>
#include <string>

namespace fedsim::runtime {

/// The DDS name of a QoS policy (DDS 1.4 section 2.2.3), e.g. "RELIABILITY".
inline const char* qos_policy_name(eprosima::fastdds::dds::QosPolicyId_t id) {
  namespace p = eprosima::fastdds::dds;
  switch (id) {
    case p::USERDATA_QOS_POLICY_ID: return "USER_DATA";
    case p::DURABILITY_QOS_POLICY_ID: return "DURABILITY";
    case p::PRESENTATION_QOS_POLICY_ID: return "PRESENTATION";
    case p::DEADLINE_QOS_POLICY_ID: return "DEADLINE";
    case p::LATENCYBUDGET_QOS_POLICY_ID: return "LATENCY_BUDGET";
    case p::OWNERSHIP_QOS_POLICY_ID: return "OWNERSHIP";
    case p::OWNERSHIPSTRENGTH_QOS_POLICY_ID: return "OWNERSHIP_STRENGTH";
    case p::LIVELINESS_QOS_POLICY_ID: return "LIVELINESS";
    case p::TIMEBASEDFILTER_QOS_POLICY_ID: return "TIME_BASED_FILTER";
    case p::PARTITION_QOS_POLICY_ID: return "PARTITION";
    case p::RELIABILITY_QOS_POLICY_ID: return "RELIABILITY";
    case p::DESTINATIONORDER_QOS_POLICY_ID: return "DESTINATION_ORDER";
    case p::HISTORY_QOS_POLICY_ID: return "HISTORY";
    case p::RESOURCELIMITS_QOS_POLICY_ID: return "RESOURCE_LIMITS";
    case p::LIFESPAN_QOS_POLICY_ID: return "LIFESPAN";
    case p::DURABILITYSERVICE_QOS_POLICY_ID: return "DURABILITY_SERVICE";
    case p::DATAREPRESENTATION_QOS_POLICY_ID: return "DATA_REPRESENTATION";
    case p::TYPECONSISTENCYENFORCEMENT_QOS_POLICY_ID: return "TYPE_CONSISTENCY_ENFORCEMENT";
    case p::DISABLEPOSITIVEACKS_QOS_POLICY_ID: return "DISABLE_POSITIVE_ACKS";
    default: return "UNKNOWN";
  }
}

/// The incompatible-QoS record of one endpoint (listener thread writes, anyone reads the count).
class QosMismatchLog {
 public:
  /// `side`: "reader" or "writer"; `remote`: what the other end is ("writer" or "reader").
  QosMismatchLog(const char* side, const char* remote) : side_(side), remote_(remote) {}

  void report(const std::string& topic, const std::string& profile,
              const eprosima::fastdds::dds::IncompatibleQosStatus& status) {
    count_.store(status.total_count);
    const auto policy = status.last_policy_id;
    {
      std::lock_guard lock(mutex_);
      if (policy < logged_.size() && logged_.test(policy)) return;
      if (policy < logged_.size()) logged_.set(policy);
    }
    spdlog::default_logger_raw()->warn(
        "topic={}: a remote {} has QoS incompatible with this {} (profile '{}'): policy {} does "
        "not match, so nothing flows between them (incompatible {} so far: {})",
        topic, remote_, side_, profile, qos_policy_name(policy), remote_, status.total_count);
  }
  /// Remote endpoints found incompatible so far.
  std::uint32_t count() const { return count_.load(); }

 private:
  const char* side_;
  const char* remote_;
  std::mutex mutex_;
  std::bitset<64> logged_;  // policies already logged
  std::atomic<std::uint32_t> count_{0};
};

}  // namespace fedsim::runtime
