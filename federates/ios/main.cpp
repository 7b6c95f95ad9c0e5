// fedsim-ios: the instructor station. See ios_station.hpp.
#include "ios/ios_station.hpp"

int main(int argc, char** argv) { return fedsim::runtime::federate_main(argc, argv, fedsim::ios::program()); }
