// Shared helpers of the navigation database tests: fixture paths and building a database from
// CSV text into the test's temporary folder.
#pragma once

#include "common/navdb/nav_database_builder.hpp"
#include "common/util/build_paths.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <unistd.h>
#include <optional>
#include <sstream>
#include <string>

namespace fedsim::nav::test {

inline std::string fixture(const std::string& name) {
  return fedsim::util::source_dir() + "/common/navdb/test/data/" + name;
}

/// A file in the test temporary folder, private to this process: ctest runs each test of a
/// suite as its own process, in parallel, and a shared name let them overwrite each other.
inline std::string temp_path(const std::string& name) {
  return testing::TempDir() + std::to_string(getpid()) + "_" + name;
}

inline std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline const std::string kNavaidHeader =
    "id,filename,ident,name,type,frequency_khz,latitude_deg,longitude_deg,elevation_ft,"
    "iso_country,dme_frequency_khz,dme_channel,dme_latitude_deg,dme_longitude_deg,"
    "dme_elevation_ft,slaved_variation_deg,magnetic_variation_deg,usageType,power,"
    "associated_airport\n";
inline const std::string kRunwayHeader =
    "id,airport_ref,airport_ident,length_ft,width_ft,surface,lighted,closed,le_ident,"
    "le_latitude_deg,le_longitude_deg,le_elevation_ft,le_heading_degT,le_displaced_threshold_ft,"
    "he_ident,he_latitude_deg,he_longitude_deg,he_elevation_ft,he_heading_degT,"
    "he_displaced_threshold_ft\n";

/// Builds a database at `path` from CSV text (origins "navaids.csv", "runways.csv", "ils.csv").
inline BuildReport build_database(const std::string& path, const std::string& navaids,
                                  const std::string& runways,
                                  const std::optional<std::string>& ils = std::nullopt) {
  NavDatabaseBuilder builder;
  std::istringstream navaid_in(navaids), runway_in(runways);
  builder.read_navaids(navaid_in, "navaids.csv");
  builder.read_runways(runway_in, "runways.csv");
  if (ils) {
    std::istringstream ils_in(*ils);
    builder.read_ils(ils_in, "ils.csv");
  }
  builder.write(path, {{"navaids_source", "test"}});
  return builder.report();
}

/// Builds the database of the three fixture files.
inline BuildReport build_fixture_database(const std::string& path) {
  return build_database(path, file_text(fixture("navaids_fixture.csv")),
                        file_text(fixture("runways_fixture.csv")),
                        file_text(fixture("ils_fixture.csv")));
}

}  // namespace fedsim::nav::test
