#include "navdb/compressed_input.hpp"

#include <zlib.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

namespace fedsim::tools {

std::string read_maybe_gzip(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw std::runtime_error(path + ": cannot read (no such file)");
  }
  const std::unique_ptr<gzFile_s, int (*)(gzFile)> file(gzopen(path.c_str(), "rb"), gzclose);
  if (!file) throw std::runtime_error(path + ": cannot open");
  std::string contents;
  char buffer[1 << 16];
  for (;;) {
    const int n = gzread(file.get(), buffer, sizeof buffer);
    if (n < 0) {
      int code = 0;
      throw std::runtime_error(path + ": cannot read: " + gzerror(file.get(), &code));
    }
    if (n == 0) break;
    contents.append(buffer, static_cast<std::size_t>(n));
  }
  int code = Z_OK;
  const char* message = gzerror(file.get(), &code);
  if (code != Z_OK && code != Z_STREAM_END) throw std::runtime_error(path + ": " + message);
  return contents;
}

}  // namespace fedsim::tools
