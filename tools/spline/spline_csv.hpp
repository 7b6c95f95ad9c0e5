// Reading x,y point lists and writing dense tables as CSV for the fedsim-spline tool.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace fedsim::tools {

/// Two columns of numbers read from CSV; the header names are kept for the output.
struct XyData {
  std::string x_name = "x";
  std::string y_name = "y";
  std::vector<double> x;
  std::vector<double> y;
};

/// Parses "x,y" rows with the common CSV reader (comma separated; blank lines and '#' comments
/// skipped); a first row that is not numeric is the header. Extra columns are ignored. Throws
/// csv::CsvError (a std::runtime_error) naming the file, line and column of a malformed row.
XyData read_xy_csv(std::istream& in, const std::string& origin);

/// Writes "x_name,y_name" then one "x,y" row per sample with `digits` significant figures.
void write_xy_csv(std::ostream& out, const XyData& table, int digits);

}  // namespace fedsim::tools
