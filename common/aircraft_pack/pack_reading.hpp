// Helpers for reading an aircraft pack's YAML (data/aircraft/README.md): 3-vectors, strictly
// increasing lists, unique names. The pack's common sections here and the flight model's own
// sections (federates/flight/model/aircraft) read their figures through them.
#pragma once

#include "common/util/config_node.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace fedsim::aircraft_pack {

using util::ConfigNode;

/// A required [x, y, z] list of three numbers.
Eigen::Vector3d read_vector3(const ConfigNode& parent, const std::string& key);

/// A strictly increasing list of finite numbers; errors point at the offending entry.
std::vector<double> read_breakpoints(const ConfigNode& parent, const std::string& key);

/// Fails at the first duplicate name (the node of each item is given for its line).
void require_unique_names(const std::vector<ConfigNode>& items, const std::string& key);

}  // namespace fedsim::aircraft_pack
