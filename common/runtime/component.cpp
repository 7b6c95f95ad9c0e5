#include "common/runtime/component.hpp"

#include "common/runtime/log.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace fedsim::runtime {

Component::Component(std::string name) : name_(std::move(name)), log_(make_logger(name_)) {}

Component::~Component() = default;

std::uint64_t Component::fault_count() const {
  std::uint64_t total = 0;
  for (const auto& f : faults_) total += f.count;
  return total;
}

void Component::report_fault(const std::string& kind, const std::string& message) {
  auto it = std::find_if(faults_.begin(), faults_.end(),
                         [&](const FaultReport& f) { return f.kind == kind; });
  if (it == faults_.end()) {
    faults_.push_back({kind, 0, ""});
    it = faults_.end() - 1;
  }
  ++it->count;
  it->last = message;
  if (it->count == 1 || it->count % 100 == 0) {
    log_->error("fault={} count={}: {}", kind, it->count, message);
  }
}

std::vector<std::string> Driver::take_notes() {
  std::lock_guard lock(notes_mutex_);
  std::vector<std::string> out;
  out.swap(notes_);
  return out;
}

void Driver::note(std::string line) {
  std::lock_guard lock(notes_mutex_);
  notes_.push_back(std::move(line));
}

std::string ports_json(const Component& component) {
  nlohmann::json ports = nlohmann::json::array();
  for (const auto& port : component.ports()) {
    const PortInfo& p = port->info();
    ports.push_back({{"topic", p.topic->name},
                     {"type", p.topic->type_name},
                     {"direction", p.direction == PortDirection::kRead ? "read" : "write"},
                     {"qos", p.qos},
                     {"lockstep_input", p.lockstep_input}});
  }
  return nlohmann::json{{"federate", component.name()}, {"ports", ports}}.dump(2);
}

}  // namespace fedsim::runtime
