// fedsim-synthetic: a load-generating federate for benchmarks and tests
// (synthetic_component.hpp).
#include "synthetic/synthetic_component.hpp"

int main(int argc, char** argv) {
  return fedsim::runtime::federate_main(argc, argv, fedsim::synthetic::program());
}
