// What the topic tools' tests share: a participant on the loopback profile.
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/federate_options.hpp"

#include <string>

namespace fedsim::tools::test {

/// Participant options for `domain` on the default loopback-only profile.
inline runtime::ParticipantOptions loopback(int domain, const std::string& name) {
  runtime::ParticipantOptions options;
  options.domain_id = domain;
  options.name = name;
  options.qos_file = runtime::default_qos_file();
  options.participant_profile = "fedsim_loopback";
  return options;
}

}  // namespace fedsim::tools::test
