// Where this build's source tree, data and outputs are: the paths a fresh build runs from
// without any environment set-up. They are compiled into one generated source file
// (build_paths.cpp.in) rather than into a -D flag on every target, so that every other object
// file is the same in any checkout of the tree (ccache then serves a fresh clone from the cache
// of another one).
#pragma once

#include <string>

namespace fedsim::util {

/// The source tree the build was configured from.
const std::string& source_dir();
/// The shipped data (aircraft packs, profiles, scenarios...): source_dir()/data.
const std::string& data_dir();
/// The test data: source_dir()/tests/data.
const std::string& test_data_dir();
/// The build tree.
const std::string& binary_dir();
/// The built programs: binary_dir()/bin.
const std::string& bin_dir();
/// The QoS profiles the build ships (qos/fedsim_qos.xml).
const std::string& qos_file();
/// The navigation database the build makes (binary_dir()/data/nav.sqlite).
const std::string& navdb_file();

}  // namespace fedsim::util
