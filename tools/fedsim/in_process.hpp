// The component programs fedsim can compose in one process (fedsim run --in-process, the
// byte-identity test), by binary name.
#pragma once

#include "common/runtime/federate_main.hpp"

#include <map>
#include <string>

namespace fedsim::launcher {

/// binary name (e.g. "fedsim-flight") -> its program (options and component).
const std::map<std::string, runtime::FederateProgram (*)()>& component_programs();

}  // namespace fedsim::launcher
