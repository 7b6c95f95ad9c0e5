#include "common/aircraft_pack/pack_path.hpp"

#include "common/util/build_paths.hpp"

#include <filesystem>
#include <stdexcept>

namespace fedsim::aircraft_pack {

std::string resolve_pack_path(const std::string& aircraft) {
  namespace fs = std::filesystem;
  if (fs::is_regular_file(aircraft)) return aircraft;
  const fs::path folder = fs::path(fedsim::util::data_dir()) / "aircraft";
  for (const fs::path& candidate : {folder / aircraft, folder / (aircraft + ".yaml")}) {
    if (fs::is_regular_file(candidate)) return candidate.string();
  }
  throw std::invalid_argument("unknown aircraft pack '" + aircraft + "': no such file, and no " +
                              aircraft + "(.yaml) in " + folder.string());
}

}  // namespace fedsim::aircraft_pack
