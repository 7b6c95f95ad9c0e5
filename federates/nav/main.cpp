// fedsim-nav: the navigation and avionics federate (options and adapter: nav_component.hpp).
#include "nav/nav_component.hpp"

int main(int argc, char** argv) {
  return fedsim::runtime::federate_main(argc, argv, fedsim::nav::program());
}
