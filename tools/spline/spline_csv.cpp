// CSV input and output of the fedsim-spline tool.
#include "spline_csv.hpp"

#include <cstdlib>
#include <istream>
#include <ostream>
#include <stdexcept>

namespace fedsim::tools {

namespace {
std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  for (char c : line) {
    if (c == ',' || c == ';' || c == '\t' || c == ' ' || c == '\r') {
      if (!field.empty()) fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  if (!field.empty()) fields.push_back(field);
  return fields;
}

bool parse_number(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}
}  // namespace

XyData read_xy_csv(std::istream& in, const std::string& origin) {
  XyData data;
  std::string line;
  int line_number = 0;
  bool first_row = true;
  while (std::getline(in, line)) {
    ++line_number;
    const std::vector<std::string> fields = split_fields(line);
    if (fields.empty() || fields[0][0] == '#') continue;
    double x = 0.0;
    double y = 0.0;
    const bool numeric =
        fields.size() >= 2 && parse_number(fields[0], x) && parse_number(fields[1], y);
    if (!numeric && first_row && fields.size() >= 2) {
      data.x_name = fields[0];
      data.y_name = fields[1];
    } else if (!numeric) {
      throw std::runtime_error(origin + ":" + std::to_string(line_number) +
                               ": expected two numbers, got '" + line + "'");
    } else {
      data.x.push_back(x);
      data.y.push_back(y);
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
