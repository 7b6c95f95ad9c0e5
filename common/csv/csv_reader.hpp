// The one CSV reader of fedsim: every CSV input (runway table, input profiles, spline tables,
// recorded time histories, reference data) is read through it, so that every bad row is
// reported the same way, as "file:line: column 'name': problem".
//
// Format: RFC 4180 fields (double quotes around a field that holds a comma or a quote, a quote
// doubled inside), blanks around unquoted fields trimmed, blank lines skipped, lines whose first
// non-blank character is '#' skipped when comments are on (the default). The first non-skipped line is the
// header unless the reader is told there is none. With comments on, '#' outside quotes starts a
// comment that runs to the end of the line. A row must have as many fields as the header.
#pragma once

#include <cstddef>
#include <istream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::csv {

/// A problem in a CSV input; what() is "origin:line: message" (or "origin: message").
class CsvError : public std::runtime_error {
 public:
  CsvError(const std::string& origin, int line, const std::string& message);
  const std::string& origin() const { return origin_; }
  int line() const { return line_; }  // 0 when the problem is not on one line

 private:
  std::string origin_;
  int line_;
};

struct CsvOptions {
  bool has_header = true;
  bool comments = true;  // '#' outside quotes starts a comment
};

class CsvReader;

/// One data row; its accessors throw CsvError naming the origin, line and column.
class CsvRow {
 public:
  int line() const { return line_; }
  std::size_t size() const { return fields_.size(); }
  const std::vector<std::string>& fields() const { return fields_; }
  /// The text of a field (index or header name).
  const std::string& text(std::size_t index) const;
  const std::string& text(const std::string& column) const;
  /// A finite number (NaN, infinities and trailing characters are errors).
  double number(std::size_t index) const;
  double number(const std::string& column) const;
  /// A finite number within [min, max].
  double number_in(const std::string& column, double min, double max) const;
  /// An integer (no fraction, no exponent).
  long long integer(const std::string& column) const;
  /// True for an empty field.
  bool empty(const std::string& column) const;
  /// Throws CsvError for this row with the message.
  [[noreturn]] void fail(const std::string& message) const;

 private:
  friend class CsvReader;
  std::string column_name(std::size_t index) const;
  const CsvReader* reader_ = nullptr;
  int line_ = 0;
  std::vector<std::string> fields_;
};

class CsvReader {
 public:
  /// Opens a file; throws CsvError "path: cannot open" if it cannot, and reads the header.
  static CsvReader open(const std::string& path, CsvOptions options = {});
  /// Reads from a stream named `origin` in messages (the stream must outlive the reader).
  CsvReader(std::istream& in, std::string origin, CsvOptions options = {});
  CsvReader(CsvReader&&) noexcept;
  CsvReader& operator=(CsvReader&&) noexcept;
  ~CsvReader();

  const std::string& origin() const { return origin_; }
  /// The header's names (empty without a header). Throws if the input had no header line.
  const std::vector<std::string>& header() const { return header_; }
  /// The index of a header column, or nullopt.
  std::optional<std::size_t> find_column(const std::string& name) const;
  /// The index of a header column; throws CsvError naming the columns there are.
  std::size_t column(const std::string& name) const;
  /// Requires these header columns (throws naming the first one missing).
  void require_columns(const std::vector<std::string>& names) const;

  /// Reads the next data row into `row`; false at the end of the input. Throws CsvError for a
  /// row whose field count differs from the header's, or an unterminated quote.
  bool next(CsvRow& row);
  /// The line number of the last line read.
  int line() const { return line_; }

 private:
  bool read_record(std::vector<std::string>& fields, int& first_line);

  std::unique_ptr<std::istream> owned_;
  std::istream* in_ = nullptr;
  std::string origin_;
  CsvOptions options_;
  std::vector<std::string> header_;
  int line_ = 0;
};

/// Splits one CSV line into trimmed fields (RFC 4180 quoting; no line breaks inside quotes).
/// Throws std::invalid_argument for an unterminated quote.
std::vector<std::string> split_csv_line(const std::string& line);

/// A numeric table with a header: every cell a finite number. For recorded time histories and
/// reference data.
class NumericTable {
 public:
  static NumericTable load(const std::string& path, CsvOptions options = {});
  static NumericTable read(CsvReader& reader);

  bool has(const std::string& column) const;
  /// A column's values; throws std::out_of_range naming the column if it is absent.
  const std::vector<double>& column(const std::string& name) const;
  const std::vector<std::string>& names() const { return names_; }
  std::size_t rows() const { return columns_.empty() ? 0 : columns_.front().size(); }
  const std::string& origin() const { return origin_; }

 private:
  std::string origin_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> columns_;
};

}  // namespace fedsim::csv
