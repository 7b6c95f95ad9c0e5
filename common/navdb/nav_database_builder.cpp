#include "common/navdb/nav_database_builder.hpp"

#include "common/csv/csv_reader.hpp"
#include "common/navdb/ils_row.hpp"
#include "common/navdb/nav_schema.hpp"
#include "common/navdb/nav_types.hpp"
#include "common/navdb/runway_row.hpp"
#include "common/navdb/sqlite_connection.hpp"
#include "common/units/units.hpp"

#include <filesystem>
#include <stdexcept>

namespace fedsim::nav {

namespace {

std::string runway_key(const std::string& airport, const std::string& runway) {
  return upper_ascii(airport) + "/" + upper_ascii(runway);
}

std::string line_prefix(const std::string& origin, int line) {
  return origin + ":" + std::to_string(line) + ": ";
}

/// The OurAirports files carry no comments ('#' may appear in names); the ILS table does.
csv::CsvReader reader_for(std::istream& in, const std::string& origin, bool comments,
                          const std::vector<std::string>& columns) {
  if (!in) throw std::runtime_error(origin + ": cannot read");
  csv::CsvReader reader(in, origin, csv::CsvOptions{true, comments});
  reader.require_columns(columns);
  return reader;
}

/// Reads every row, handing it to `use`; a row the reader itself rejects (field count) is
/// reported through `reject` and reading goes on.
template <typename Use, typename Reject>
void for_each_row(csv::CsvReader& reader, Use use, Reject reject) {
  csv::CsvRow row;
  for (;;) {
    try {
      if (!reader.next(row)) return;
    } catch (const csv::CsvError& e) {
      reject(e);
      continue;
    }
    use(row);
  }
}

double deg(double rad) { return rad * units::kRadToDeg; }

void bind_optional(SqliteStatement& s, int index, bool known, double value) {
  if (known) {
    s.bind(index, value);
  } else {
    s.bind_null(index);
  }
}

void bind_optional(SqliteStatement& s, int index, const std::optional<double>& value) {
  bind_optional(s, index, value.has_value(), value.value_or(0.0));
}

}  // namespace

std::size_t BuildReport::navaids_kept() const {
  std::size_t n = 0;
  for (const auto& [type, count] : navaids_by_type) n += count;
  return n;
}

std::size_t BuildReport::errors() const {
  std::size_t n = 0;
  for (const auto& p : problems) n += p.warning ? 0 : 1;
  return n;
}

std::size_t BuildReport::warnings() const { return problems.size() - errors(); }

void NavDatabaseBuilder::add_problem(const std::string& origin, int line, const std::string& text,
                                     bool warning) {
  report_.problems.push_back(BuildProblem{origin, line, text, warning});
  if (sink_) sink_(report_.problems.back());
}

void NavDatabaseBuilder::add_warning(const std::string& origin, int line,
                                     const std::string& message) {
  add_problem(origin, line, line_prefix(origin, line) + "warning: " + message, true);
}

// ---- navaids ----------------------------------------------------------------------------------

void NavDatabaseBuilder::add_navaid(NavaidRow parsed, const std::string& origin, int line) {
  const auto [it, inserted] = navaid_id_lines_.emplace(parsed.navaid.id, line);
  if (!inserted) {
    ++report_.navaids_skipped;
    add_problem(origin, line,
                line_prefix(origin, line) + "column 'id': " + std::to_string(parsed.navaid.id) +
                    " already read on line " + std::to_string(it->second),
                false);
    return;
  }
  for (const auto& w : parsed.warnings) add_warning(origin, line, w);
  ++report_.navaids_by_type[parsed.navaid.type];
  navaids_.push_back(NavaidEntry{std::move(parsed.navaid), parsed.dme_elevation_known});
}

void NavDatabaseBuilder::read_navaids(std::istream& in, const std::string& origin) {
  csv::CsvReader reader = reader_for(in, origin, false, navaid_columns());
  for_each_row(
      reader,
      [&](const csv::CsvRow& row) {
        ++report_.navaid_rows;
        try {
          add_navaid(parse_navaid_row(row), origin, row.line());
        } catch (const csv::CsvError& e) {
          ++report_.navaids_skipped;
          add_problem(origin, row.line(), e.what(), false);
        }
      },
      [&](const csv::CsvError& e) {
        ++report_.navaid_rows;
        ++report_.navaids_skipped;
        add_problem(origin, e.line(), e.what(), false);
      });
}

// ---- runways ----------------------------------------------------------------------------------

void NavDatabaseBuilder::add_runway_end(const RunwayEndRecord& end, const std::string& origin,
                                        int line) {
  const std::string key = runway_key(end.airport, end.runway);
  const auto [it, inserted] = runway_end_lines_.emplace(key, line);
  if (!inserted) {
    ++report_.runway_ends_skipped;
    add_problem(origin, line,
                line_prefix(origin, line) + "runway end " + end.airport + " " + end.runway +
                    " already read on line " + std::to_string(it->second),
                false);
    return;
  }
  runway_ends_.emplace(key, end);
  ++report_.runway_ends;
}

void NavDatabaseBuilder::read_runways(std::istream& in, const std::string& origin) {
  csv::CsvReader reader = reader_for(in, origin, false, runway_columns());
  auto reject_row = [&](const csv::CsvError& e) {
    ++report_.runway_rows_skipped;
    report_.runway_ends_skipped += 2;
    add_problem(origin, e.line(), e.what(), false);
  };
  for_each_row(
      reader,
      [&](const csv::CsvRow& row) {
        ++report_.runway_rows;
        RunwayRow parsed;
        try {
          parsed = parse_runway_row(row);
        } catch (const csv::CsvError& e) {
          reject_row(e);
          return;
        }
        report_.runway_ends_unpositioned += static_cast<std::size_t>(parsed.unpositioned_ends);
        for (const auto& p : parsed.end_problems) {
          ++report_.runway_ends_skipped;
          add_problem(origin, row.line(), p, false);
        }
        for (const auto& w : parsed.warnings) add_warning(origin, row.line(), w);
        for (const auto& end : parsed.ends) add_runway_end(end, origin, row.line());
      },
      [&](const csv::CsvError& e) {
        ++report_.runway_rows;
        reject_row(e);
      });
}

// ---- ILS --------------------------------------------------------------------------------------

void NavDatabaseBuilder::read_ils(std::istream& in, const std::string& origin) {
  csv::CsvReader reader = reader_for(in, origin, true, ils_columns());
  report_.ils_read = true;
  const RunwayEndLookup lookup = [this](const std::string& airport, const std::string& runway) {
    const auto it = runway_ends_.find(runway_key(airport, runway));
    return it == runway_ends_.end() ? nullptr : &it->second;
  };
  std::map<std::string, int> lines;  // one ILS per runway end
  auto skip = [&](int line, const std::string& text) {
    ++report_.ils_skipped;
    add_problem(origin, line, text, false);
  };
  for_each_row(
      reader,
      [&](const csv::CsvRow& row) {
        ++report_.ils_rows;
        IlsRow parsed;
        try {
          parsed = parse_ils_row(row, lookup);
        } catch (const csv::CsvError& e) {
          skip(row.line(), e.what());
          return;
        }
        const auto [it, inserted] =
            lines.emplace(runway_key(parsed.ils.airport, parsed.ils.runway), row.line());
        if (!inserted) {
          skip(row.line(), line_prefix(origin, row.line()) + "a second ILS for " +
                               parsed.ils.airport + " " + parsed.ils.runway + " (first on line " +
                               std::to_string(it->second) + ")");
          return;
        }
        for (const auto& w : parsed.warnings) add_warning(origin, row.line(), w);
        ils_.push_back(std::move(parsed.ils));
        ++report_.ils_kept;
      },
      [&](const csv::CsvError& e) {
        ++report_.ils_rows;
        skip(e.line(), e.what());
      });
}

// ---- writing ----------------------------------------------------------------------------------

namespace {

void write_navaids(const SqliteConnection& db, const std::vector<Navaid>& navaids,
                   const std::vector<bool>& dme_elevation_known) {
  SqliteStatement insert(db,
                         "INSERT INTO navaids VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, "
                         "?12, ?13, ?14, ?15, ?16, ?17, ?18)");
  SqliteStatement index(db, "INSERT INTO navaids_rtree VALUES (?1, ?2, ?2, ?3, ?3)");
  for (std::size_t i = 0; i < navaids.size(); ++i) {
    const Navaid& n = navaids[i];
    insert.bind(1, n.id);
    insert.bind(2, n.ident);
    insert.bind(3, n.name);
    insert.bind(4, navaid_type_name(n.type));
    insert.bind(5, static_cast<std::int64_t>(n.frequency_khz));
    insert.bind(6, deg(n.position.lat_rad));
    insert.bind(7, deg(n.position.lon_rad));
    bind_optional(insert, 8, n.elevation_known, n.position.elevation_m);
    bind_optional(insert, 9, n.dme.has_value(), n.dme ? deg(n.dme->lat_rad) : 0.0);
    bind_optional(insert, 10, n.dme.has_value(), n.dme ? deg(n.dme->lon_rad) : 0.0);
    bind_optional(insert, 11, n.dme.has_value() && dme_elevation_known[i],
                  n.dme ? n.dme->elevation_m : 0.0);
    insert.bind(12, n.dme_channel);
    insert.bind(13, deg(n.magnetic_variation_rad));
    bind_optional(insert, 14, n.slaved_variation_known, deg(n.slaved_variation_rad));
    insert.bind(15, power_class_name(n.power));
    insert.bind(16, usage_type_name(n.usage));
    insert.bind(17, n.country);
    insert.bind(18, n.airport);
    insert.run();
    index.bind(1, n.id);
    index.bind(2, deg(n.position.lat_rad));
    index.bind(3, deg(n.position.lon_rad));
    index.run();
  }
}

void write_runway_ends(const SqliteConnection& db,
                       const std::map<std::string, RunwayEndRecord>& ends) {
  SqliteStatement insert(db,
                         "INSERT INTO runway_ends VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, "
                         "?11, ?12, ?13, ?14)");
  for (const auto& [key, r] : ends) {
    insert.bind(1, r.airport);
    insert.bind(2, r.runway);
    insert.bind(3, deg(r.threshold.lat_rad));
    insert.bind(4, deg(r.threshold.lon_rad));
    bind_optional(insert, 5, r.elevation_known, r.end.elevation_m);
    insert.bind(6, deg(r.end.lat_rad));
    insert.bind(7, deg(r.end.lon_rad));
    insert.bind(8, deg(r.heading_true_rad));
    insert.bind(9, r.length_m);
    insert.bind(10, r.width_m);
    insert.bind(11, r.displaced_threshold_m);
    insert.bind(12, r.surface);
    insert.bind(13, static_cast<std::int64_t>(r.lighted));
    insert.bind(14, static_cast<std::int64_t>(r.closed));
    insert.run();
  }
}

void write_ils(const SqliteConnection& db, const std::vector<IlsApproach>& approaches) {
  SqliteStatement insert(db,
                         "INSERT INTO ils VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, "
                         "?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19, ?20, ?21, ?22, ?23)");
  for (const auto& a : approaches) {
    insert.bind(1, a.airport);
    insert.bind(2, a.runway);
    insert.bind(3, a.ident);
    insert.bind(4, static_cast<std::int64_t>(a.frequency_khz));
    insert.bind(5, deg(a.course_magnetic_rad));
    insert.bind(6, deg(a.magnetic_variation_rad));
    insert.bind(7, deg(a.course_true_rad));
    insert.bind(8, deg(a.glide_path_angle_rad));
    insert.bind(9, a.threshold_crossing_height_m);
    bind_optional(insert, 10, a.course_width_rad > 0.0, deg(a.course_width_rad));
    insert.bind(11, deg(a.localizer.lat_rad));
    insert.bind(12, deg(a.localizer.lon_rad));
    insert.bind(13, a.localizer.elevation_m);
    insert.bind(14, deg(a.glide_slope.lat_rad));
    insert.bind(15, deg(a.glide_slope.lon_rad));
    insert.bind(16, a.glide_slope.elevation_m);
    bind_optional(insert, 17, a.outer_marker_distance_m);
    bind_optional(insert, 18, a.middle_marker_distance_m);
    bind_optional(insert, 19, a.inner_marker_distance_m);
    insert.bind(20, static_cast<std::int64_t>(a.has_dme));
    insert.bind(21, a.category);
    insert.bind(22, a.derived);
    insert.bind(23, a.source);
    insert.run();
  }
}

void write_meta(const SqliteConnection& db, const std::map<std::string, std::string>& entries) {
  SqliteStatement insert(db, "INSERT INTO meta VALUES (?1, ?2)");
  for (const auto& [key, value] : entries) {
    insert.bind(1, key);
    insert.bind(2, value);
    insert.run();
  }
}

}  // namespace

void NavDatabaseBuilder::write(const std::string& path,
                               const std::map<std::string, std::string>& sources) const {
  namespace fs = std::filesystem;
  const std::string partial = path + ".partial";
  std::error_code ignored;
  fs::remove(partial, ignored);
  {
    SqliteConnection db = SqliteConnection::create(partial);
    // The file is renamed into place only when complete: no journal is needed while writing.
    db.exec("PRAGMA journal_mode = OFF; PRAGMA synchronous = OFF; PRAGMA foreign_keys = ON;");
    db.exec(kSchemaSql);
    db.exec("BEGIN");
    std::vector<Navaid> navaids;
    std::vector<bool> dme_elevation_known;
    navaids.reserve(navaids_.size());
    for (const auto& e : navaids_) {
      navaids.push_back(e.navaid);
      dme_elevation_known.push_back(e.dme_elevation_known);
    }
    write_navaids(db, navaids, dme_elevation_known);
    write_runway_ends(db, runway_ends_);
    write_ils(db, ils_);
    std::map<std::string, std::string> meta = sources;
    meta["schema_version"] = std::to_string(kSchemaVersion);
    meta["navaids"] = std::to_string(navaids_.size());
    meta["runway_ends"] = std::to_string(runway_ends_.size());
    meta["ils"] = std::to_string(ils_.size());
    write_meta(db, meta);
    db.exec("COMMIT");
    db.exec("PRAGMA foreign_key_check; ANALYZE;");
  }
  fs::rename(partial, path);  // atomic on POSIX within one file system
}

}  // namespace fedsim::nav
