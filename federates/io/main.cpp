// fedsim-io: the I/O federate. Options: --profile (scripted input, CSV), --aircraft-id,
// --controls-qos; the adapter is io_component.hpp.
#include "common/runtime/federate_main.hpp"
#include "io/io_component.hpp"
#include "io/model/input_profile.hpp"

using namespace fedsim;

int main(int argc, char** argv) {
  std::string profile_path;
  int aircraft_id = 0;
  std::string controls_qos(runtime::topics::pilot_controls.info.default_qos);
  runtime::FederateProgram program;
  program.program = "fedsim-io";
  program.default_name = "io";
  program.description = "publishes pilot controls every frame from an input source";
  program.add_options = [&](CLI::App& app) {
    app.add_option("--profile", profile_path, "scripted input profile (CSV: time_s + channels)")
        ->required();
    app.add_option("--aircraft-id", aircraft_id, "aircraft the controls fly")
        ->check(CLI::Range(0, 65535))
        ->capture_default_str();
    app.add_option("--controls-qos", controls_qos, "QoS profile of fedsim/pilot_controls")
        ->capture_default_str();
  };
  program.make_component = [&](const runtime::FederateOptions& common) {
    auto source = std::make_unique<io::InputProfile>(io::InputProfile::load_file(profile_path));
    return std::make_unique<io::IoComponent>(common.name, std::move(source), aircraft_id,
                                             controls_qos);
  };
  return runtime::federate_main(argc, argv, program);
}
