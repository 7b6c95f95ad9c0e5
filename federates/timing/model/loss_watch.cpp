#include "timing/model/loss_watch.hpp"

namespace fedsim::timing {

void LossWatch::tick_published(const std::vector<std::string>& expected, std::uint64_t now_ns) {
  for (const auto& name : expected) outstanding_since_ns_.try_emplace(name, now_ns);
}

void LossWatch::acknowledged(const std::string& federate) { outstanding_since_ns_.erase(federate); }

std::vector<std::string> LossWatch::overdue(std::uint64_t now_ns) const {
  std::vector<std::string> out;
  for (const auto& [name, since] : outstanding_since_ns_) {
    if (!is_lost(name) && now_ns >= since && now_ns - since >= timeout_ns_) out.push_back(name);
  }
  return out;
}

std::uint64_t LossWatch::age_ns(const std::string& federate, std::uint64_t now_ns) const {
  const auto it = outstanding_since_ns_.find(federate);
  return it == outstanding_since_ns_.end() || now_ns < it->second ? 0 : now_ns - it->second;
}

bool LossWatch::process_replaced(const std::string& federate, std::uint32_t pid) {
  if (pid == 0) return false;
  auto [it, inserted] = pids_.try_emplace(federate, pid);
  if (inserted || it->second == pid) return false;
  it->second = pid;
  return true;
}

std::uint32_t LossWatch::pid_of(const std::string& federate) const {
  const auto it = pids_.find(federate);
  return it == pids_.end() ? 0 : it->second;
}

void LossWatch::record_lost(const std::string& federate, std::uint64_t frame, double t_s,
                            std::string why) {
  outstanding_since_ns_.erase(federate);
  lost_now_[federate] = true;
  events_.push_back({MembershipEvent::Kind::kLost, federate, frame, t_s, std::move(why)});
}

bool LossWatch::record_rejoined(const std::string& federate, std::uint64_t frame, double t_s) {
  if (!is_lost(federate)) return false;
  lost_now_[federate] = false;
  outstanding_since_ns_.erase(federate);  // its clock starts with its first tick back
  events_.push_back({MembershipEvent::Kind::kRejoined, federate, frame, t_s, ""});
  return true;
}

bool LossWatch::is_lost(const std::string& federate) const {
  const auto it = lost_now_.find(federate);
  return it != lost_now_.end() && it->second;
}

std::vector<std::string> LossWatch::lost() const {
  std::vector<std::string> out;
  for (const auto& e : events_) {
    if (e.kind == MembershipEvent::Kind::kLost) out.push_back(e.federate);
  }
  return out;
}

std::vector<std::string> LossWatch::rejoined() const {
  std::vector<std::string> out;
  for (const auto& e : events_) {
    if (e.kind == MembershipEvent::Kind::kRejoined) out.push_back(e.federate);
  }
  return out;
}

std::vector<std::string> LossWatch::still_lost() const {
  std::vector<std::string> out;
  for (const auto& [name, lost] : lost_now_) {
    if (lost) out.push_back(name);
  }
  return out;
}

}  // namespace fedsim::timing
