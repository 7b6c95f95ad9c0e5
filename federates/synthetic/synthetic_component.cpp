#include "synthetic/synthetic_component.hpp"
#include "common/util/cli_checks.hpp"

#include "common/util/monotonic_clock.hpp"

#include <fstream>

namespace fedsim::synthetic {

namespace {

void busy_wait_us(double us) {
  const std::uint64_t until = util::monotonic_ns() + static_cast<std::uint64_t>(us * 1000.0);
  while (util::monotonic_ns() < until) {
  }
}

struct SyntheticOptions {
  double work_us = 0.0;
  bool publish = false;
  std::string publish_qos;  // "" = the catalogue's
  bool input = false;
  std::string trace_file;
};

class SyntheticComponent final : public runtime::Component {
 public:
  SyntheticComponent(std::string name, SyntheticOptions options)
      : Component(std::move(name)),
        // ---- Ports (optional) ----
        navigation_state_(options.publish ? &writes(runtime::topics::navigation_state, options.publish_qos) : nullptr),
        pilot_controls_(options.input ? &reads(runtime::topics::pilot_controls) : nullptr),
        options_(std::move(options)) {}

  void step(const runtime::FrameContext& ctx) override {
    if (options_.work_us > 0) busy_wait_us(options_.work_us);
    if (navigation_state_) {
      nav_.stamp(ctx.stamp());
      navigation_state_->write(nav_);
    }
    if (options_.trace_file.empty()) return;
    if (!trace_.is_open()) open_trace();  // at the first frame: building the component writes nothing
    long long input_frame = -1;
    float elevator = 0.0f;
    if (const msg::PilotControls* controls = pilot_controls_ ? pilot_controls_->latest() : nullptr) {
      input_frame = static_cast<long long>(controls->stamp().frame());
      elevator = controls->elevator();
    }
    trace_ << ctx.frame << ',' << ctx.sim_frame << ',' << ctx.sim_time_s << ','
           << static_cast<int>(ctx.run_state) << ',' << ctx.reset_count << ',' << input_frame
           << ',' << elevator << '\n';
    trace_.flush();  // tests watch the file grow
  }
  void on_stop() override { trace_.flush(); }

 private:
  void open_trace() {
    trace_.open(options_.trace_file);
    if (!trace_) throw std::runtime_error("cannot write " + options_.trace_file);
    trace_ << "frame,sim_frame,sim_time_s,state,reset_count,input_frame,elevator\n";
  }


  runtime::Output<msg::NavigationState>* navigation_state_;
  runtime::Input<msg::PilotControls>* pilot_controls_;
  SyntheticOptions options_;
  std::ofstream trace_;
  msg::NavigationState nav_;
};

}  // namespace

runtime::FederateProgram program() {
  auto options = std::make_shared<SyntheticOptions>();
  runtime::FederateProgram program;
  program.program = "fedsim-synthetic";
  program.default_name = "synthetic";
  program.description = "a load-generating federate for benchmarks and tests";
  program.add_options = [options](CLI::App& app) {
    app.add_option("--work-us", options->work_us, "busy work per frame [us]")
        ->check(fedsim::util::FiniteRange(0.0, 1.0e6));
    app.add_flag("--publish", options->publish, "publish a navigation-state sample every frame");
    app.add_option("--publish-qos", options->publish_qos,
                   "QoS profile of the navigation-state writer (default: the catalogue's)");
    app.add_flag("--input", options->input, "take fedsim/pilot_controls as a lockstep input");
    app.add_option("--trace", options->trace_file,
                   "write one CSV line per frame: frame,sim_frame,sim_time_s,state,reset_count,"
                   "input_frame,elevator");
  };
  program.make_component = [options](const runtime::FederateOptions& common) {
    return std::unique_ptr<runtime::Component>(
        std::make_unique<SyntheticComponent>(common.name, *options));
  };
  return program;
}

}  // namespace fedsim::synthetic
