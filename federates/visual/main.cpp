#include "visual/visual_component.hpp"

int main(int argc, char** argv) { return fedsim::runtime::federate_main(argc, argv, fedsim::visual::program()); }
