#include "common/csv/csv_reader.hpp"

#include <charconv>
#include <cmath>
#include <fstream>

namespace fedsim::csv {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

/// Parses `text` (one record, possibly spanning lines) into fields. Returns false if a quoted
/// field is still open at the end (the caller appends the next line and tries again).
bool parse_record(const std::string& text, std::vector<std::string>& fields, bool comments) {
  fields.clear();
  std::string field;
  bool quoted = false;       // inside a quoted section
  bool was_quoted = false;   // this field had a quoted section (no trimming of its content)
  std::string before_quote;  // unquoted text before the opening quote (blanks only, allowed)
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        field += c;
      }
    } else if (comments && c == '#') {
      break;  // the rest of the line is a comment
    } else if (c == '"' && !was_quoted && blank(field)) {
      quoted = true;
      was_quoted = true;
      field.clear();
    } else if (c == ',') {
      fields.push_back(was_quoted ? field : trimmed(field));
      field.clear();
      was_quoted = false;
    } else if (was_quoted) {
      if (c != ' ' && c != '\t' && c != '\r') field += c;  // text after a closing quote: kept
    } else {
      field += c;
    }
  }
  if (quoted) return false;
  fields.push_back(was_quoted ? field : trimmed(field));
  return true;
}

}  // namespace

CsvError::CsvError(const std::string& origin, int line, const std::string& message)
    : std::runtime_error(origin + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                         message),
      origin_(origin),
      line_(line) {}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields;
  if (!parse_record(line, fields, false)) throw std::invalid_argument("unterminated quote");
  return fields;
}

// ---- CsvRow -----------------------------------------------------------------------------------

std::string CsvRow::column_name(std::size_t index) const {
  if (reader_ && index < reader_->header().size()) return "'" + reader_->header()[index] + "'";
  return std::to_string(index + 1);
}

void CsvRow::fail(const std::string& message) const {
  throw CsvError(reader_ ? reader_->origin() : std::string("csv"), line_, message);
}

const std::string& CsvRow::text(std::size_t index) const {
  if (index >= fields_.size()) {
    fail("no column " + column_name(index) + " (the row has " + std::to_string(fields_.size()) +
         " fields)");
  }
  return fields_[index];
}

const std::string& CsvRow::text(const std::string& column) const {
  return text(reader_->column(column));
}

double CsvRow::number(std::size_t index) const {
  const std::string& s = text(index);
  double value = 0.0;
  const char* begin = s.data();
  const char* end = s.data() + s.size();
  if (!s.empty() && *begin == '+') ++begin;
  const auto [ptr, error] = std::from_chars(begin, end, value);
  if (s.empty() || error != std::errc() || ptr != end) {
    fail("column " + column_name(index) + ": not a number: '" + s + "'");
  }
  if (std::isnan(value)) fail("column " + column_name(index) + ": not a number: '" + s + "'");
  if (!std::isfinite(value)) fail("column " + column_name(index) + ": not finite: '" + s + "'");
  return value;
}

double CsvRow::number(const std::string& column) const { return number(reader_->column(column)); }

double CsvRow::number_in(const std::string& column, double min, double max) const {
  const double value = number(column);
  if (value < min || value > max) {
    fail("column '" + column + "': " + text(column) + " is outside [" + std::to_string(min) + ", " +
         std::to_string(max) + "]");
  }
  return value;
}

long long CsvRow::integer(const std::string& column) const {
  const std::string& s = text(column);
  long long value = 0;
  const auto [ptr, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || error != std::errc() || ptr != s.data() + s.size()) {
    fail("column '" + column + "': not an integer: '" + s + "'");
  }
  return value;
}

bool CsvRow::empty(const std::string& column) const { return text(column).empty(); }

// ---- CsvReader --------------------------------------------------------------------------------

CsvReader CsvReader::open(const std::string& path, CsvOptions options) {
  auto file = std::make_unique<std::ifstream>(path);
  if (!*file) throw CsvError(path, 0, "cannot open");
  std::istream& stream = *file;
  CsvReader reader(stream, path, options);
  reader.owned_ = std::move(file);
  return reader;
}

CsvReader::CsvReader(std::istream& in, std::string origin, CsvOptions options)
    : in_(&in), origin_(std::move(origin)), options_(options) {
  if (!options_.has_header) return;
  int first_line = 0;
  if (!read_record(header_, first_line)) throw CsvError(origin_, 0, "empty (no header line)");
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i].empty()) throw CsvError(origin_, first_line, "header column " +
                                                                    std::to_string(i + 1) + " is empty");
    for (std::size_t j = 0; j < i; ++j) {
      if (header_[j] == header_[i]) {
        throw CsvError(origin_, first_line, "header names '" + header_[i] + "' twice");
      }
    }
  }
}

CsvReader::CsvReader(CsvReader&&) noexcept = default;
CsvReader& CsvReader::operator=(CsvReader&&) noexcept = default;
CsvReader::~CsvReader() = default;

bool CsvReader::read_record(std::vector<std::string>& fields, int& first_line) {
  std::string line;
  while (std::getline(*in_, line)) {
    ++line_;
    if (blank(line)) continue;
    if (options_.comments && blank(line.substr(0, line.find('#')))) continue;
    first_line = line_;
    std::string record = line;
    while (!parse_record(record, fields, options_.comments)) {
      if (!std::getline(*in_, line)) throw CsvError(origin_, first_line, "unterminated quote");
      ++line_;
      record += '\n';
      record += line;
    }
    return true;
  }
  return false;
}

std::optional<std::size_t> CsvReader::find_column(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return i;
  }
  return std::nullopt;
}

std::size_t CsvReader::column(const std::string& name) const {
  if (auto i = find_column(name)) return *i;
  std::string have;
  for (const auto& h : header_) have += (have.empty() ? "" : ", ") + h;
  throw CsvError(origin_, 0, "no column '" + name + "' (the header has " + have + ")");
}

void CsvReader::require_columns(const std::vector<std::string>& names) const {
  for (const auto& n : names) column(n);
}

bool CsvReader::next(CsvRow& row) {
  row.reader_ = this;
  if (!read_record(row.fields_, row.line_)) return false;
  if (options_.has_header && row.fields_.size() != header_.size()) {
    row.fail(std::to_string(row.fields_.size()) + " fields, the header has " +
             std::to_string(header_.size()));
  }
  return true;
}

// ---- NumericTable -----------------------------------------------------------------------------

NumericTable NumericTable::load(const std::string& path, CsvOptions options) {
  CsvReader reader = CsvReader::open(path, options);
  return read(reader);
}

NumericTable NumericTable::read(CsvReader& reader) {
  NumericTable table;
  table.origin_ = reader.origin();
  table.names_ = reader.header();
  table.columns_.resize(table.names_.size());
  CsvRow row;
  while (reader.next(row)) {
    for (std::size_t i = 0; i < row.size(); ++i) table.columns_[i].push_back(row.number(i));
  }
  return table;
}

bool NumericTable::has(const std::string& column) const {
  for (const auto& n : names_) {
    if (n == column) return true;
  }
  return false;
}

const std::vector<double>& NumericTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return columns_[i];
  }
  throw std::out_of_range(origin_ + ": no column '" + name + "'");
}

}  // namespace fedsim::csv
