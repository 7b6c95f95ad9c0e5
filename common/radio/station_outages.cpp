#include "common/radio/station_outages.hpp"

#include <stdexcept>

namespace fedsim::radio {

std::uint8_t StationOutages::bit(StationComponent component) {
  return static_cast<std::uint8_t>(1u << static_cast<unsigned>(component));
}

void StationOutages::set_off_air(std::string_view ident, StationComponent component,
                                 bool off_air) {
  if (ident.empty()) throw std::invalid_argument("StationOutages: empty station ident");
  auto it = components_.find(ident);
  if (off_air) {
    if (it == components_.end()) it = components_.emplace(std::string(ident), 0).first;
    it->second |= bit(component);
  } else if (it != components_.end()) {
    it->second &= static_cast<std::uint8_t>(~bit(component));
    if (it->second == 0) components_.erase(it);
  }
}

bool StationOutages::off_air(std::string_view ident, StationComponent component) const {
  if (components_.empty()) return false;
  const auto it = components_.find(ident);
  if (it == components_.end()) return false;
  return (it->second & (bit(StationComponent::kAll) | bit(component))) != 0;
}

}  // namespace fedsim::radio
