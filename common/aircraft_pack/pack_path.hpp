// Where an aircraft pack is: what every program that takes --aircraft accepts (fedsim-flight,
// fedsim-fly, fedsim-visual, fedsim-control-loading).
#pragma once

#include <string>

namespace fedsim::aircraft_pack {

/// A pack path as given, or a bare name ("c172", "c172.yaml") looked up in the data folder.
/// Throws std::invalid_argument naming both places when neither exists.
std::string resolve_pack_path(const std::string& aircraft);

}  // namespace fedsim::aircraft_pack
