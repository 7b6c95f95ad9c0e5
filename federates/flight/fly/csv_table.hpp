// Reads a numeric CSV file with a header line (such as fedsim-fly's output) into columns.
#pragma once

#include <string>
#include <vector>

namespace fedsim::flight {

class CsvTable {
 public:
  /// Throws std::runtime_error ("file:line: problem") for a missing file, a ragged row or a
  /// field that is not a number.
  static CsvTable load(const std::string& path);

  bool has(const std::string& column) const;
  /// A column's values; throws std::out_of_range naming the column if it is absent.
  const std::vector<double>& column(const std::string& name) const;
  const std::vector<std::string>& names() const { return names_; }
  std::size_t rows() const { return columns_.empty() ? 0 : columns_.front().size(); }

 private:
  std::vector<std::string> names_;
  std::vector<std::vector<double>> columns_;
};

}  // namespace fedsim::flight
