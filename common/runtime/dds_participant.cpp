#include "common/runtime/dds_participant.hpp"

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/log/Log.hpp>

#include <filesystem>
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
}  // namespace

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
  participant_ = factory->create_participant(options_.domain_id, qos);
  if (!participant_) {
    throw DdsError("cannot create a DDS participant on domain " +
                   std::to_string(options_.domain_id) + " with profile '" +
                   options_.participant_profile + "'");
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
