// fedsim-navdb: builds the navigation database (SQLite) from OurAirports' navaids.csv and
// runways.csv (plain or .gz) and the project's ILS table data/nav/ils.csv.
//
//   fedsim-navdb --navaids navaids.csv.gz --runways runways.csv.gz [--ils ils.csv] --out nav.sqlite
//
// Bad rows are reported on stderr as "file:line: problem" and skipped; the summary counts them.
// Exit 0 when the database was written, 2 when a source cannot be read (or lacks a column) or
// the output cannot be written.
#include "common/navdb/nav_database_builder.hpp"
#include "common/navdb/nav_types.hpp"
#include "navdb/compressed_input.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

namespace {

using fedsim::nav::BuildReport;
using fedsim::nav::NavDatabaseBuilder;

constexpr int kExitSourceError = 2;

struct Options {
  std::string navaids;
  std::string runways;
  std::string ils;
  std::string out;
  bool verbose = false;
};

void read_source(const std::string& path, NavDatabaseBuilder& builder,
                 void (NavDatabaseBuilder::*read)(std::istream&, const std::string&)) {
  std::istringstream in(fedsim::tools::read_maybe_gzip(path));
  (builder.*read)(in, path);
}

void print_summary(const BuildReport& r, const Options& options) {
  std::printf("fedsim-navdb: %s: %zu rows, %zu navaids kept, %zu skipped\n",
              options.navaids.c_str(), r.navaid_rows, r.navaids_kept(), r.navaids_skipped);
  std::printf("  ");
  for (const auto& [type, count] : r.navaids_by_type) {
    std::printf(" %s %zu", std::string(fedsim::nav::navaid_type_name(type)).c_str(), count);
  }
  std::printf("\n");
  std::printf("fedsim-navdb: %s: %zu rows, %zu runway ends kept, %zu skipped (%zu whole rows), "
              "%zu ends without a position (not stored)\n",
              options.runways.c_str(), r.runway_rows, r.runway_ends, r.runway_ends_skipped,
              r.runway_rows_skipped, r.runway_ends_unpositioned);
  if (r.ils_read) {
    std::printf("fedsim-navdb: %s: %zu rows, %zu ILS approaches kept, %zu skipped\n",
                options.ils.c_str(), r.ils_rows, r.ils_kept, r.ils_skipped);
  } else {
    std::printf("fedsim-navdb: no ILS table given (--ils): the database holds no ILS approaches\n");
  }
  std::printf("fedsim-navdb: %zu problems (rows or runway ends skipped, listed above), %zu "
              "warnings (rows kept%s)\n",
              r.errors(), r.warnings(), options.verbose ? ", listed above" : "; --verbose lists them");
}

int build(const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  NavDatabaseBuilder builder;
  builder.on_problem([&](const fedsim::nav::BuildProblem& p) {
    if (!p.warning || options.verbose) std::cerr << p.text << '\n';
  });
  read_source(options.navaids, builder, &NavDatabaseBuilder::read_navaids);
  read_source(options.runways, builder, &NavDatabaseBuilder::read_runways);
  if (!options.ils.empty()) read_source(options.ils, builder, &NavDatabaseBuilder::read_ils);
  const auto name = [](const std::string& p) { return std::filesystem::path(p).filename().string(); };
  std::map<std::string, std::string> sources{{"navaids_source", name(options.navaids)},
                                             {"runways_source", name(options.runways)},
                                             {"built_by", "fedsim-navdb"}};
  if (!options.ils.empty()) sources["ils_source"] = name(options.ils);
  builder.write(options.out, sources);
  print_summary(builder.report(), options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("fedsim-navdb: wrote %s (%.1f MB) in %.2f s\n", options.out.c_str(),
              static_cast<double>(std::filesystem::file_size(options.out)) / 1e6, seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fedsim-navdb: builds the navigation database (SQLite) from OurAirports' "
               "navaids.csv and runways.csv and the ILS table"};
  Options options;
  app.add_option("--navaids", options.navaids, "OurAirports navaids.csv (or .csv.gz)")->required();
  app.add_option("--runways", options.runways, "OurAirports runways.csv (or .csv.gz)")->required();
  app.add_option("--ils", options.ils, "ILS table (data/nav/ils.csv); without it, no ILS");
  app.add_option("--out", options.out, "the database file to write (atomically)")->required();
  app.add_flag("--verbose", options.verbose, "also list the warnings (rows kept with a remark)");
  CLI11_PARSE(app, argc, argv);
  try {
    return build(options);
  } catch (const std::exception& e) {
    std::cerr << "fedsim-navdb: " << e.what() << '\n';
    return kExitSourceError;
  }
}
