// CSV input and output of the fedsim-spline tool.
#include "spline_csv.hpp"

#include "common/csv/csv_reader.hpp"

#include <charconv>
#include <istream>
#include <ostream>
#include <stdexcept>

namespace fedsim::tools {

namespace {
bool looks_numeric(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}
}  // namespace

XyData read_xy_csv(std::istream& in, const std::string& origin) {
  // No fixed header: the first row is the header when it is not two numbers.
  csv::CsvReader reader(in, origin, csv::CsvOptions{.has_header = false});
  XyData data;
  csv::CsvRow row;
  bool first_row = true;
  while (reader.next(row)) {
    if (row.size() < 2) row.fail("expected two columns, got " + std::to_string(row.size()));
    if (first_row && !looks_numeric(row.text(0))) {
      data.x_name = row.text(0);
      data.y_name = row.text(1);
    } else {
      data.x.push_back(row.number(0));
      data.y.push_back(row.number(1));
    }
    first_row = false;
  }
  return data;
}

void write_xy_csv(std::ostream& out, const XyData& table, int digits) {
  out.precision(digits);
  out << table.x_name << ',' << table.y_name << '\n';
  for (std::size_t i = 0; i < table.x.size(); ++i) out << table.x[i] << ',' << table.y[i] << '\n';
}

}  // namespace fedsim::tools
