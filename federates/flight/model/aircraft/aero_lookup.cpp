// Constant-or-table lookup over value slots (tables from flight/model/math/interpolation).
#include "flight/model/aircraft/aero_lookup.hpp"

#include <utility>

namespace fedsim::flight {

namespace {
AeroLookup::Range span_of(const std::vector<double>& breakpoints) {
  return {breakpoints.front(), breakpoints.back()};
}
}  // namespace

AeroLookup AeroLookup::constant(double value) {
  AeroLookup out;
  out.constant_ = value;
  return out;
}

AeroLookup AeroLookup::table(std::size_t row_slot, Table1D table) {
  AeroLookup out;
  out.dimensions_ = 1;
  out.inputs_ = {row_slot, 0, 0};
  out.ranges_[0] = span_of(table.x());
  out.table1_ = std::move(table);
  return out;
}

AeroLookup AeroLookup::table(std::size_t row_slot, std::size_t column_slot, Table2D table) {
  AeroLookup out;
  out.dimensions_ = 2;
  out.inputs_ = {row_slot, column_slot, 0};
  out.ranges_[0] = span_of(table.rows());
  out.ranges_[1] = span_of(table.cols());
  out.table2_ = std::move(table);
  return out;
}

AeroLookup AeroLookup::table(std::size_t page_slot, std::size_t row_slot,
                             std::size_t column_slot, std::vector<double> pages,
                             std::vector<double> rows, std::vector<double> columns,
                             std::vector<double> values) {
  AeroLookup out;
  out.dimensions_ = 3;
  out.inputs_ = {page_slot, row_slot, column_slot};
  // Table3D checks the breakpoints (non-empty, increasing) before the spans are read.
  out.table3_ = Table3D(pages, rows, columns, std::move(values));
  out.ranges_ = {span_of(pages), span_of(rows), span_of(columns)};
  return out;
}

double AeroLookup::operator()(std::span<const double> slots) const {
  switch (dimensions_) {
    case 1:
      return table1_(slots[inputs_[0]]);
    case 2:
      return table2_(slots[inputs_[0]], slots[inputs_[1]]);
    case 3:
      return table3_(slots[inputs_[0]], slots[inputs_[1]], slots[inputs_[2]]);
    default:
      return constant_;
  }
}

}  // namespace fedsim::flight
