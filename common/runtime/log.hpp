// Structured logging for federates and tools: one line per event, "time level [name] message
// key=value ...", on stderr (the launcher prefixes and keeps it).
#pragma once

#include <spdlog/spdlog.h>

#include <memory>
#include <string>

namespace fedsim::runtime {

/// Creates (or returns) the logger named after the federate; level is one of trace, debug,
/// info, warn, error, critical, off, or empty: keep the logger's level (info for a new one).
std::shared_ptr<spdlog::logger> make_logger(const std::string& name,
                                            const std::string& level = "");

}  // namespace fedsim::runtime
