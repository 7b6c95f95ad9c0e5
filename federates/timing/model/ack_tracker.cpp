#include "timing/model/ack_tracker.hpp"

#include <stdexcept>

namespace fedsim::timing {

AckTracker::AckTracker(std::vector<std::string> expected) {
  for (auto& name : expected) {
    if (index_.count(name)) throw std::invalid_argument("federate listed twice: " + name);
    index_[name] = members_.size();
    members_.push_back({std::move(name), true, false});
  }
}

void AckTracker::start_frame(std::uint64_t frame) {
  frame_ = frame;
  outstanding_ = 0;
  for (auto& m : members_) {
    m.acked = false;
    if (m.readmitted) m.active = true;
    m.readmitted = false;
    if (m.active) ++outstanding_;
  }
}

bool AckTracker::acknowledge(const std::string& federate, std::uint64_t frame) {
  if (frame != frame_) return false;
  const auto it = index_.find(federate);
  if (it == index_.end()) return false;
  Member& m = members_[it->second];
  if (!m.active || m.acked) return false;
  m.acked = true;
  return --outstanding_ == 0;
}

bool AckTracker::remove(const std::string& federate) {
  const auto it = index_.find(federate);
  if (it == index_.end()) return false;
  Member& m = members_[it->second];
  m.readmitted = false;
  if (!m.active) return false;
  m.active = false;
  if (m.acked) return false;
  return --outstanding_ == 0;
}

bool AckTracker::readmit(const std::string& federate) {
  const auto it = index_.find(federate);
  if (it == index_.end()) return false;
  Member& m = members_[it->second];
  if (m.active || m.readmitted) return false;
  m.readmitted = true;
  return true;
}

bool AckTracker::expects(const std::string& federate) const {
  const auto it = index_.find(federate);
  return it != index_.end() && members_[it->second].active;
}

std::vector<std::string> AckTracker::missing() const {
  std::vector<std::string> out;
  for (const auto& m : members_) {
    if (m.active && !m.acked) out.push_back(m.name);
  }
  return out;
}

std::vector<std::string> AckTracker::expected() const {
  std::vector<std::string> out;
  for (const auto& m : members_) {
    if (m.active) out.push_back(m.name);
  }
  return out;
}

std::size_t AckTracker::expected_count() const { return expected().size(); }

}  // namespace fedsim::timing
