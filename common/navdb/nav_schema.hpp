// The schema of the navigation database file (SQLite), written by NavDatabaseBuilder and read by
// NavDatabase. docs/navdb.md describes every column.
//
// Units in the file: positions and angles in degrees (as published: WGS-84 latitude north
// positive, longitude east positive, variation east positive), heights and lengths in metres,
// frequencies in kHz. NULL where a fact is unknown. The library converts to SI (radians) on
// reading.
#pragma once

#include <string_view>

namespace fedsim::nav {

/// The schema version this code writes and reads (meta key "schema_version"). Bump it with
/// every change of a table; a database of another version is refused (rebuild it).
inline constexpr int kSchemaVersion = 1;

/// The tables NavDatabase::open requires.
inline constexpr std::string_view kRequiredTables[] = {"meta", "navaids", "navaids_rtree",
                                                       "runway_ends", "ils"};

/// CREATE statements of every table and index.
inline constexpr std::string_view kSchemaSql = R"SQL(
CREATE TABLE meta (
  key TEXT PRIMARY KEY NOT NULL,
  value TEXT NOT NULL
);
CREATE TABLE navaids (
  id INTEGER PRIMARY KEY,                 -- OurAirports id
  ident TEXT NOT NULL COLLATE NOCASE,
  name TEXT NOT NULL,
  type TEXT NOT NULL CHECK (type IN ('VOR','VOR-DME','VORTAC','DME','TACAN','NDB','NDB-DME')),
  frequency_khz INTEGER NOT NULL,         -- VOR/NDB; DME/TACAN: paired VHF, 0 = unpaired channel
  lat_deg REAL NOT NULL CHECK (lat_deg BETWEEN -90 AND 90),
  lon_deg REAL NOT NULL CHECK (lon_deg BETWEEN -180 AND 180),
  elevation_m REAL,                       -- NULL: unknown
  dme_lat_deg REAL,                       -- NULL: no DME
  dme_lon_deg REAL,
  dme_elevation_m REAL,
  dme_channel TEXT NOT NULL,              -- '084X'; '' when none
  magnetic_variation_deg REAL NOT NULL,   -- east positive
  slaved_variation_deg REAL,              -- NULL: unknown
  power TEXT NOT NULL,
  usage TEXT NOT NULL,
  country TEXT NOT NULL,
  airport TEXT NOT NULL COLLATE NOCASE
);
CREATE INDEX navaids_by_ident ON navaids (ident);
CREATE INDEX navaids_by_frequency ON navaids (frequency_khz);
CREATE VIRTUAL TABLE navaids_rtree USING rtree (id, min_lat_deg, max_lat_deg, min_lon_deg, max_lon_deg);
CREATE TABLE runway_ends (
  airport TEXT NOT NULL COLLATE NOCASE,
  runway TEXT NOT NULL COLLATE NOCASE,
  threshold_lat_deg REAL NOT NULL,        -- the landing threshold (displacement applied)
  threshold_lon_deg REAL NOT NULL,
  elevation_m REAL,                       -- NULL: unknown
  end_lat_deg REAL NOT NULL,              -- the runway end as published
  end_lon_deg REAL NOT NULL,
  heading_true_deg REAL NOT NULL,         -- landing direction
  length_m REAL NOT NULL,                 -- 0: unknown
  width_m REAL NOT NULL,                  -- 0: unknown
  displaced_threshold_m REAL NOT NULL,
  surface TEXT NOT NULL,
  lighted INTEGER NOT NULL,
  closed INTEGER NOT NULL,
  PRIMARY KEY (airport, runway)
) WITHOUT ROWID;
CREATE TABLE ils (
  airport TEXT NOT NULL COLLATE NOCASE,
  runway TEXT NOT NULL COLLATE NOCASE,
  ident TEXT NOT NULL COLLATE NOCASE,
  frequency_khz INTEGER NOT NULL,
  course_magnetic_deg REAL NOT NULL,
  magnetic_variation_deg REAL NOT NULL,
  course_true_deg REAL NOT NULL,
  glide_path_angle_deg REAL NOT NULL,
  threshold_crossing_height_m REAL NOT NULL,
  course_width_deg REAL,                  -- NULL: by rule
  localizer_lat_deg REAL NOT NULL,
  localizer_lon_deg REAL NOT NULL,
  localizer_elevation_m REAL NOT NULL,
  glide_slope_lat_deg REAL NOT NULL,
  glide_slope_lon_deg REAL NOT NULL,
  glide_slope_elevation_m REAL NOT NULL,
  outer_marker_m REAL,                    -- from the threshold; NULL: none
  middle_marker_m REAL,
  inner_marker_m REAL,
  dme INTEGER NOT NULL,
  category TEXT NOT NULL,
  derived TEXT NOT NULL,
  source TEXT NOT NULL,
  PRIMARY KEY (airport, runway),
  FOREIGN KEY (airport, runway) REFERENCES runway_ends (airport, runway)
) WITHOUT ROWID;
CREATE INDEX ils_by_frequency ON ils (frequency_khz);
CREATE INDEX ils_by_ident ON ils (ident);
)SQL";

}  // namespace fedsim::nav
