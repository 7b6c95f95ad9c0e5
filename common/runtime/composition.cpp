#include "common/runtime/composition.hpp"

#include "common/runtime/frame_tick.hpp"
#include "common/runtime/sim_command_codec.hpp"

#include <cmath>
#include <stdexcept>

namespace fedsim::runtime {

namespace {
double checked_period_s(double rate_hz) {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0 || rate_hz > 100000.0) {
    throw std::invalid_argument("composition: frame rate " + std::to_string(rate_hz) +
                                " Hz is outside (0, 100000]");
  }
  return 1.0 / rate_hz;
}
}  // namespace

Composition::Composition(Options options)
    : options_(options),
      period_s_(checked_period_s(options.rate_hz)),
      clock_(period_s_, options.start_frozen ? timing::RunState::kFreeze : timing::RunState::kRun) {
  context_.frame_period_s = period_s_;
  context_.mode = msg::TIMING_MODE_LOCKSTEP;
}

Composition::~Composition() {
  try {
    stop();
  } catch (...) {
    // A component's on_stop failed while unwinding: nothing more to do here.
  }
}

void Composition::add(Component& component) {
  if (dynamic_cast<Driver*>(&component)) {
    throw std::invalid_argument("composition: " + component.name() +
                                " makes frames (a driver); the composition is its own frame clock");
  }
  component.on_start(HostServices{});
  members_.push_back(Member{&component, {}});
  bound_ = &members_.back();
  for (const auto& port : component.ports()) port->bind(*this);
  bound_ = nullptr;
}

void Composition::command(const msg::SimCommand& command) {
  if (command.kind() == msg::COMMAND_SHUTDOWN) {
    shutdown_ = true;
    return;
  }
  if (command.kind() == msg::COMMAND_RUN_STATE) clock_.request(from_msg(command.run_state()));
  commands_.push_back(command);
}

const FrameContext& Composition::step_frame() {
  context_ = context_of(tick_of(clock_.next_tick(), period_s_, msg::TIMING_MODE_LOCKSTEP));
  commands_now_.swap(commands_);
  commands_.clear();
  for (Member& member : members_) {
    for (const auto& refresh : member.refreshers) refresh();
    for (const auto& command : commands_now_) member.component->on_command(command);
    member.component->step(context_);
  }
  for (auto& [name, channel] : channels_) channel->end_frame();
  return context_;
}

std::uint64_t Composition::run(std::uint64_t frames,
                               const std::function<void(const FrameContext&)>& progress) {
  std::uint64_t done = 0;
  while (done < frames && !shutdown_) {
    const FrameContext& frame = step_frame();
    ++done;
    if (progress) progress(frame);
  }
  return done;
}

void Composition::stop() {
  if (stopped_) return;
  stopped_ = true;
  for (Member& member : members_) member.component->on_stop();
}

std::uint64_t Composition::fault_count() const {
  std::uint64_t total = 0;
  for (const Member& member : members_) total += member.component->fault_count();
  return total;
}

std::vector<std::string> Composition::unread_topics() const {
  std::vector<std::string> out;
  for (const auto& [name, channel] : channels_) {
    if (channel->readers == 0 && channel->writers > 0) out.push_back(name);
  }
  return out;
}

std::vector<std::string> Composition::unwritten_topics() const {
  std::vector<std::string> out;
  for (const auto& [name, channel] : channels_) {
    if (channel->writers == 0 && channel->readers > channel->monitors) out.push_back(name);
  }
  return out;
}

std::vector<std::string> Composition::unwritten_monitored_topics() const {
  std::vector<std::string> out;
  for (const auto& [name, channel] : channels_) {
    if (channel->writers == 0 && channel->readers > 0 && channel->readers == channel->monitors) {
      out.push_back(name);
    }
  }
  return out;
}

}  // namespace fedsim::runtime
