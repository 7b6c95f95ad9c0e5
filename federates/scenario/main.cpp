// fedsim-scenario: runs an instructor scenario file. See scenario_component.hpp.
#include "scenario/scenario_component.hpp"

int main(int argc, char** argv) { return fedsim::runtime::federate_main(argc, argv, fedsim::scenario::program()); }
