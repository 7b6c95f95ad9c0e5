#include "common/runtime/log.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace fedsim::runtime {

std::shared_ptr<spdlog::logger> make_logger(const std::string& name, const std::string& level) {
  if (auto existing = spdlog::get(name)) {
    if (!level.empty()) existing->set_level(spdlog::level::from_str(level));
    return existing;
  }
  auto logger = spdlog::stderr_color_mt(name);
  logger->set_pattern("%H:%M:%S.%e %^%-5l%$ [%n] %v");
  logger->set_level(spdlog::level::from_str(level.empty() ? "info" : level));
  logger->flush_on(spdlog::level::info);
  spdlog::set_default_logger(logger);
  return logger;
}

}  // namespace fedsim::runtime
