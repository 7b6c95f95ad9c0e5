// Numeric CSV reader for fedsim-fly's output.
#include "flight/fly/csv_table.hpp"

#include <charconv>
#include <fstream>
#include <stdexcept>

namespace fedsim::flight {

namespace {
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    std::string field =
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto first = field.find_first_not_of(" \t\r");
    const auto last = field.find_last_not_of(" \t\r");
    fields.push_back(first == std::string::npos ? "" : field.substr(first, last - first + 1));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}
}  // namespace

CsvTable CsvTable::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  CsvTable table;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ":1: no header");
  table.names_ = split(line);
  table.columns_.resize(table.names_.size());
  for (int line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = split(line);
    if (fields.size() != table.names_.size()) {
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": " +
                               std::to_string(fields.size()) + " fields, the header has " +
                               std::to_string(table.names_.size()));
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      double value = 0.0;
      const auto [end, error] =
          std::from_chars(fields[i].data(), fields[i].data() + fields[i].size(), value);
      if (error != std::errc() || end != fields[i].data() + fields[i].size()) {
        throw std::runtime_error(path + ":" + std::to_string(line_no) + ": " + table.names_[i] +
                                 ": not a number: '" + fields[i] + "'");
      }
      table.columns_[i].push_back(value);
    }
  }
  return table;
}

bool CsvTable::has(const std::string& column) const {
  for (const auto& n : names_) {
    if (n == column) return true;
  }
  return false;
}

const std::vector<double>& CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return columns_[i];
  }
  throw std::out_of_range("no column '" + name + "'");
}

}  // namespace fedsim::flight
