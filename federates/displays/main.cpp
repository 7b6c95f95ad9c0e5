#include "displays/displays_component.hpp"

int main(int argc, char** argv) { return fedsim::runtime::federate_main(argc, argv, fedsim::displays::program()); }
