// A constant or a 1-D/2-D/3-D table whose inputs are read from numbered value slots.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

/// The "base" of one aerodynamic term: either a constant or a table looked up with the values
/// of up to three slots (see AeroVariable for the slot numbering). Built once at load time;
/// evaluating it neither allocates nor throws.
class AeroLookup {
 public:
  /// Table inputs in lookup order: 1-D {row}, 2-D {row, column}, 3-D {page, row, column}.
  using Inputs = std::array<std::size_t, 3>;
  /// The span of one input's breakpoints: the table holds data there and clamps outside.
  struct Range {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
  };
  using Ranges = std::array<Range, 3>;

  AeroLookup() = default;  // the constant 0
  static AeroLookup constant(double value);
  static AeroLookup table(std::size_t row_slot, Table1D table);
  static AeroLookup table(std::size_t row_slot, std::size_t column_slot, Table2D table);
  /// A 3-D table from its breakpoints (pages, rows, columns) and values, page-major.
  static AeroLookup table(std::size_t page_slot, std::size_t row_slot, std::size_t column_slot,
                          std::vector<double> pages, std::vector<double> rows,
                          std::vector<double> columns, std::vector<double> values);

  /// The value for the current slot values (tables clamp outside their breakpoints).
  double operator()(std::span<const double> slots) const;

  /// 0 for a constant, else the table's dimension.
  int dimensions() const { return dimensions_; }
  /// The slots the table reads, first dimensions() entries valid.
  const Inputs& input_slots() const { return inputs_; }
  /// The breakpoint span of each input, first dimensions() entries valid.
  const Ranges& input_ranges() const { return ranges_; }
  double constant_value() const { return constant_; }

 private:
  int dimensions_ = 0;
  Inputs inputs_{};
  Ranges ranges_{};
  double constant_ = 0.0;
  Table1D table1_;
  Table2D table2_;
  Table3D table3_;
};

}  // namespace fedsim::flight
