// fedsim-io: the I/O federate (options and adapter: io_component.hpp).
#include "io/io_component.hpp"

int main(int argc, char** argv) {
  return fedsim::runtime::federate_main(argc, argv, fedsim::io::program());
}
