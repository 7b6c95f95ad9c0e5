#include "common/runtime/dds_participant.hpp"

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/log/Log.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <regex>
#include <set>

namespace fedsim::runtime {

namespace {
// Fast DDS 2.9 builds a DynamicType from every complete TypeObject a remote endpoint announces
// and, for the keyed types fastddsgen 2.3 generates, logs "DYN_TYPES Error ... MemberId not
// found" while applying the @key annotation. Nothing fails (keys travel in the key hash and
// fedsim's own dynamic readers build their types locally), so that one category is silenced in
// every fedsim process; every other Fast DDS error still shows.
void silence_spurious_dynamic_type_errors() {
  static std::once_flag once;
  std::call_once(once, [] { fdds::Log::SetCategoryFilter(std::regex("^(?!DYN_TYPES$)")); });
}

// DDS Security (docs/security.md). With FEDSIM_SECURITY_DIR set, the participant authenticates
// with its own certificate (builtin.PKI-DH), obeys the signed governance and permissions
// (builtin.Access-Permissions) and encrypts what the governance says (builtin.AES-GCM-GMAC).
// The folder is made by deploy/security/make-security.sh; the identity (a sub-folder) is
// FEDSIM_SECURITY_IDENTITY or else the participant name (--name). A missing file is an error
// naming it: a participant asked to be secure never starts unsecured. True if it is secured.
bool add_security_properties(fdds::DomainParticipantQos& qos, const std::string& participant_name) {
  namespace fs = std::filesystem;
  const char* dir_env = std::getenv("FEDSIM_SECURITY_DIR");
  if (!dir_env || !*dir_env) return false;
  const char* identity_env = std::getenv("FEDSIM_SECURITY_IDENTITY");
  const std::string identity = identity_env && *identity_env ? identity_env : participant_name;
  static const std::regex plain_name("[A-Za-z0-9_][A-Za-z0-9_.-]*");
  if (!std::regex_match(identity, plain_name)) {
    throw DdsError("DDS Security identity '" + identity +
                   "' (FEDSIM_SECURITY_IDENTITY or --name) is not a plain name: letters, digits, "
                   "'_', '-', '.'");
  }
  const fs::path dir = fs::absolute(dir_env);
  auto file_uri = [&](const fs::path& path) {
    if (!fs::is_regular_file(path)) {
      throw DdsError("DDS Security file missing: " + path.string() + " (FEDSIM_SECURITY_DIR=" +
                     dir_env + ", identity '" + identity +
                     "'; make it with deploy/security/make-security.sh)");
    }
    return "file://" + path.string();
  };
  const std::string pki = "dds.sec.auth.builtin.PKI-DH.";
  const std::string access = "dds.sec.access.builtin.Access-Permissions.";
  auto& properties = qos.properties().properties();
  properties.emplace_back("dds.sec.auth.plugin", "builtin.PKI-DH");
  properties.emplace_back(pki + "identity_ca", file_uri(dir / "identity_ca.pem"));
  properties.emplace_back(pki + "identity_certificate", file_uri(dir / identity / "cert.pem"));
  properties.emplace_back(pki + "private_key", file_uri(dir / identity / "key.pem"));
  properties.emplace_back("dds.sec.access.plugin", "builtin.Access-Permissions");
  properties.emplace_back(access + "permissions_ca", file_uri(dir / "permissions_ca.pem"));
  properties.emplace_back(access + "governance", file_uri(dir / "governance.p7s"));
  properties.emplace_back(access + "permissions", file_uri(dir / identity / "permissions.p7s"));
  properties.emplace_back("dds.sec.crypto.plugin", "builtin.AES-GCM-GMAC");
  return true;
}

// A secured participant reports each remote participant it refuses (no certificate, another
// CA's, an invalid one): otherwise an intruder's attempts would leave no trace. Once per remote
// participant (Fast DDS retries the handshake); the remote is known only by its GUID prefix.
class AuthenticationReporter : public fdds::DomainParticipantListener {
 public:
  void onParticipantAuthentication(
      fdds::DomainParticipant* participant,
      eprosima::fastrtps::rtps::ParticipantAuthenticationInfo&& info) override {
    if (info.status != eprosima::fastrtps::rtps::ParticipantAuthenticationInfo::UNAUTHORIZED_PARTICIPANT) {
      return;
    }
    std::ostringstream prefix;
    prefix << info.guid.guidPrefix;
    {
      std::lock_guard lock(mutex_);
      if (!reported_.insert(prefix.str()).second) return;
    }
    std::ostringstream line;
    line << "fedsim: DDS Security: participant '" << participant->get_qos().name().to_string()
         << "' refused remote participant " << prefix.str()
         << " (authentication failed: no certificate, another CA's, or an invalid one)\n";
    std::cerr << line.str() << std::flush;
  }

 private:
  std::mutex mutex_;
  std::set<std::string> reported_;
};

AuthenticationReporter& authentication_reporter() {
  static AuthenticationReporter reporter;  // outlives every participant of the process
  return reporter;
}
}  // namespace

// Every participant's listener: refused remote participants (DDS Security) and the reliable
// writers discovered, by topic.
class DdsParticipant::Listener : public fdds::DomainParticipantListener {
 public:
  void onParticipantAuthentication(
      fdds::DomainParticipant* participant,
      eprosima::fastrtps::rtps::ParticipantAuthenticationInfo&& info) override {
    authentication_reporter().onParticipantAuthentication(participant, std::move(info));
  }
  void on_publisher_discovery(fdds::DomainParticipant*,
                              eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override {
    using Status = eprosima::fastrtps::rtps::WriterDiscoveryInfo::DISCOVERY_STATUS;
    const auto& data = info.info;
    std::ostringstream guid;
    guid << data.guid();
    const std::string topic = data.topicName().to_string();
    const bool gone = info.status == Status::REMOVED_WRITER;
    const bool reliable = data.m_qos.m_reliability.kind == fdds::RELIABLE_RELIABILITY_QOS;
    std::lock_guard lock(mutex_);
    if (!gone && reliable) {
      reliable_writers_[topic].insert(guid.str());
    } else if (auto it = reliable_writers_.find(topic); it != reliable_writers_.end()) {
      it->second.erase(guid.str());
    }
  }
  bool has_reliable_writer(const std::string& topic) const {
    std::lock_guard lock(mutex_);
    const auto it = reliable_writers_.find(topic);
    return it != reliable_writers_.end() && !it->second.empty();
  }

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::set<std::string>> reliable_writers_;  // topic -> writer GUIDs
};

bool DdsParticipant::has_reliable_writer(const std::string& topic) const {
  return listener_->has_reliable_writer(topic);
}

void load_qos_profiles(const std::string& qos_file) {
  silence_spurious_dynamic_type_errors();
  static std::mutex mutex;
  static std::set<std::string> loaded;
  std::lock_guard lock(mutex);
  if (loaded.count(qos_file)) return;
  if (!std::filesystem::exists(qos_file)) {
    throw DdsError("QoS profiles file not found: " + qos_file +
                   " (set --qos-file or FEDSIM_QOS_FILE)");
  }
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  if (factory->load_XML_profiles_file(qos_file) != ReturnCode_t::RETCODE_OK) {
    throw DdsError("cannot load QoS profiles from " + qos_file + " (XML error, see above)");
  }
  loaded.insert(qos_file);
}

std::shared_ptr<DdsParticipant> DdsParticipant::create(const ParticipantOptions& options) {
  return std::shared_ptr<DdsParticipant>(new DdsParticipant(options));
}

DdsParticipant::DdsParticipant(const ParticipantOptions& options) : options_(options) {
  load_qos_profiles(options_.qos_file);
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipantQos qos;
  if (factory->get_participant_qos_from_profile(options_.participant_profile, qos) !=
      ReturnCode_t::RETCODE_OK) {
    throw DdsError("participant profile '" + options_.participant_profile + "' is not defined in " +
                   options_.qos_file);
  }
  qos.name(options_.name);
  add_security_properties(qos, options_.name);
  listener_ = std::make_unique<Listener>();
  participant_ = factory->create_participant(options_.domain_id, qos, listener_.get(),
                                             fdds::StatusMask::none());
  if (!participant_) {
    const char* security = std::getenv("FEDSIM_SECURITY_DIR");
    throw DdsError("cannot create a DDS participant on domain " +
                   std::to_string(options_.domain_id) + " with profile '" +
                   options_.participant_profile + "'" +
                   (security && *security ? std::string(" and DDS Security from ") + security +
                                                " (certificate, signatures and grant: see the "
                                                "SECURITY errors above)"
                                          : std::string()));
  }
  publisher_ = participant_->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (!publisher_ || !subscriber_) throw DdsError("cannot create DDS publisher/subscriber");
}

DdsParticipant::~DdsParticipant() {
  if (!participant_) return;
  participant_->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

fdds::Topic* DdsParticipant::topic_for(const std::string& name, fdds::TypeSupport type) {
  std::lock_guard lock(topics_mutex_);
  if (auto it = topics_.find(name); it != topics_.end()) {
    if (it->second->get_type_name() != type.get_type_name()) {
      throw DdsError("topic '" + name + "' is already used with type " +
                     it->second->get_type_name());
    }
    return it->second;
  }
  const std::string type_name = type.get_type_name();
  // Announce type names only, not TypeObjects: Fast DDS 2.9 rebuilds a DynamicType from every
  // remote reader's TypeObject during discovery and crashes (TypeObjectFactory::
  // get_array_identifier) on an array of structs it has not registered itself, e.g. a process
  // without AircraftState discovering a reader of it (GearContact gear[8]). Cyclone DDS also
  // rejects the type-information parameter. fedsim's tools build types from local TypeObjects.
  type->auto_fill_type_object(false);
  type->auto_fill_type_information(false);
  if (type.register_type(participant_) != ReturnCode_t::RETCODE_OK &&
      !participant_->find_type(type_name).get()) {
    throw DdsError("cannot register type " + type_name);
  }
  auto* topic = participant_->create_topic(name, type_name, fdds::TOPIC_QOS_DEFAULT);
  if (!topic) throw DdsError("cannot create topic " + name + " of type " + type_name);
  topics_[name] = topic;
  return topic;
}

}  // namespace fedsim::runtime
