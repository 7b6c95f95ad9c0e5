#include "common/runtime/command_settings.hpp"

namespace fedsim::runtime {

namespace {
std::pair<int, std::string> instance_of(const msg::SimCommand& command) {
  return {static_cast<int>(command.kind()), command.target().to_string()};
}
}  // namespace

bool is_setting(const msg::SimCommand& command) {
  switch (command.kind()) {
    case msg::COMMAND_WEATHER:
    case msg::COMMAND_FAILURE:
    case msg::COMMAND_RADIO_TUNING:
    case msg::COMMAND_TIME_OF_DAY:
      return true;
    default:  // run state, reposition, snapshot, shutdown, and kinds this build does not know
      return false;
  }
}

bool SettingHolder::offer(const msg::SimCommand& command) {
  if (!is_setting(command)) return false;
  auto [it, inserted] = held_.try_emplace(instance_of(command), command);
  if (inserted) return true;
  if (it->second == command) return false;
  it->second = command;
  return true;
}

std::vector<msg::SimCommand> SettingHolder::held() const {
  std::vector<msg::SimCommand> out;
  for (const auto& [key, command] : held_) out.push_back(command);
  return out;
}

bool RedeliveryFilter::first_delivery(const msg::SimCommand& command) {
  if (!is_setting(command)) return true;
  auto [it, inserted] = last_.try_emplace(instance_of(command), command);
  if (inserted) return true;
  if (it->second == command) {
    ++dropped_;
    return false;
  }
  it->second = command;
  return true;
}

}  // namespace fedsim::runtime
