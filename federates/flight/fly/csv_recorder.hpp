// Writes the aircraft's outputs as CSV, one row per recorded frame, units in the column names
// (the columns are listed in docs/fedsim-fly.md).
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "flight/model/aircraft/aircraft_controls.hpp"
#include "flight/model/aircraft/aircraft_outputs.hpp"

namespace fedsim::flight {

class CsvRecorder {
 public:
  /// Columns for an aircraft with this many engines and ground contacts.
  CsvRecorder(std::size_t engines, std::size_t contacts);
  ~CsvRecorder();
  CsvRecorder(const CsvRecorder&) = delete;
  CsvRecorder& operator=(const CsvRecorder&) = delete;

  /// Opens the file and writes the header; throws std::runtime_error if it cannot.
  void open(const std::string& path);
  /// One row: the outputs and the commands in force from that time on.
  void write(const AircraftOutputs& outputs, const AircraftControls& controls);
  /// Flushes and closes; throws std::runtime_error on a write error.
  void close();

  std::vector<std::string> column_names() const;

 private:
  using Value = std::function<double(const AircraftOutputs&, const AircraftControls&)>;
  struct Column {
    std::string name;
    Value value;
  };
  void add(std::string name, Value value);
  void add_standard_columns();
  void add_engine_columns(std::size_t engine);
  void add_contact_columns(std::size_t contact);

  std::vector<Column> columns_;
  std::FILE* file_ = nullptr;
  std::string path_;
  std::string line_;  // reused row buffer
};

}  // namespace fedsim::flight
