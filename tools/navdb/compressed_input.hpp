// Reads a whole source file into memory, gunzipping it when it is gzip-compressed (zlib reads a
// plain file unchanged), for the CSV reader (common/csv) to read from a std::istringstream.
#pragma once

#include <string>

namespace fedsim::tools {

/// The file's (decompressed) bytes. Throws std::runtime_error "path: problem" when it does not
/// exist, cannot be opened or is a damaged gzip stream.
std::string read_maybe_gzip(const std::string& path);

}  // namespace fedsim::tools
