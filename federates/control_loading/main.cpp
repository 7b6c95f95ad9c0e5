// fedsim-control-loading: the control-loading federate (options and adapter: control_loading_component.hpp).
#include "control_loading/control_loading_component.hpp"

int main(int argc, char** argv) {
  return fedsim::runtime::federate_main(argc, argv, fedsim::control_loading::program());
}
