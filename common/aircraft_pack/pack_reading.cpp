#include "common/aircraft_pack/pack_reading.hpp"

#include <set>
#include <sstream>

namespace fedsim::aircraft_pack {

Eigen::Vector3d read_vector3(const ConfigNode& parent, const std::string& key) {
  const auto v = parent.numbers(key, 3);
  return {v[0], v[1], v[2]};
}

std::vector<double> read_breakpoints(const ConfigNode& parent, const std::string& key) {
  const ConfigNode list = parent.child(key);
  const auto items = list.items();
  if (items.empty()) list.fail("a table axis needs at least one breakpoint");
  std::vector<double> out;
  out.reserve(items.size());
  for (const auto& item : items) {
    const double x = item.as_number();
    if (!out.empty() && !(x > out.back())) {
      std::ostringstream why;
      why << "breakpoints must be strictly increasing (" << x << " does not exceed "
          << out.back() << ")";
      item.fail(why.str());
    }
    out.push_back(x);
  }
  return out;
}

void require_unique_names(const std::vector<ConfigNode>& items, const std::string& key) {
  std::set<std::string> seen;
  for (const auto& item : items) {
    const std::string name = item.string(key);
    if (!seen.insert(name).second) item.fail_at(key, "duplicate name '" + name + "'");
  }
}

}  // namespace fedsim::aircraft_pack
