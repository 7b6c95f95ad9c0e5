// Table lookup with linear interpolation on non-uniform breakpoints (seed 2.9, eq. 2.58-2.59
// generalised to 2-D and 3-D as in Example 2.4). Inputs outside the breakpoints are clamped to
// the edge values: a lookup never reads out of bounds and never extrapolates.
// Lookups do not allocate; tables are built once when an aircraft pack is loaded.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim {

/// Where x falls on a strictly increasing breakpoint list: lower index and fraction in [0, 1].
struct Bracket {
  std::size_t index = 0;
  double fraction = 0.0;
};

/// Clamped bracket search (binary search; O(log n), no allocation).
Bracket find_bracket(const std::vector<double>& breakpoints, double x);

/// Throws std::invalid_argument unless the breakpoints are finite and strictly increasing.
void check_breakpoints(const std::vector<double>& breakpoints, const std::string& what);

/// y = f(x).
class Table1D {
 public:
  Table1D() = default;
  Table1D(std::vector<double> x, std::vector<double> values);
  double operator()(double x) const;
  bool empty() const { return x_.empty(); }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<double> x_;
  std::vector<double> values_;
};

/// z = f(row, col); values are row-major: values[i_row * cols + i_col].
class Table2D {
 public:
  Table2D() = default;
  Table2D(std::vector<double> rows, std::vector<double> cols, std::vector<double> values);
  double operator()(double row, double col) const;
  bool empty() const { return rows_.empty(); }
  const std::vector<double>& rows() const { return rows_; }
  const std::vector<double>& cols() const { return cols_; }
  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<double> rows_;
  std::vector<double> cols_;
  std::vector<double> values_;
};

/// w = f(page, row, col); values[(i_page * rows + i_row) * cols + i_col].
class Table3D {
 public:
  Table3D() = default;
  Table3D(std::vector<double> pages, std::vector<double> rows, std::vector<double> cols,
          std::vector<double> values);
  double operator()(double page, double row, double col) const;
  bool empty() const { return pages_.empty(); }

 private:
  std::vector<double> pages_;
  std::vector<double> rows_;
  std::vector<double> cols_;
  std::vector<double> values_;
};

}  // namespace fedsim
