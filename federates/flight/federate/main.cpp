// fedsim-flight: the flight federate (options: flight_program.hpp; adapter: flight_component.hpp).
#include "flight/federate/flight_program.hpp"

int main(int argc, char** argv) {
  return fedsim::runtime::federate_main(argc, argv, fedsim::flight::program());
}
