// fedsim-timing: the federation's frame clock. See timing_component.hpp.
#include "timing/timing_component.hpp"

int main(int argc, char** argv) { return fedsim::runtime::federate_main(argc, argv, fedsim::timing::program()); }
