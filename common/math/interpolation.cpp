#include "common/math/interpolation.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim {

Bracket find_bracket(const std::vector<double>& breakpoints, double x) {
  const std::size_t n = breakpoints.size();
  if (n < 2 || !(x > breakpoints.front())) return {0, 0.0};  // also catches NaN
  if (x >= breakpoints.back()) return {n - 2, 1.0};
  const auto upper = std::upper_bound(breakpoints.begin(), breakpoints.end(), x);
  const std::size_t i = static_cast<std::size_t>(upper - breakpoints.begin()) - 1;
  return {i, (x - breakpoints[i]) / (breakpoints[i + 1] - breakpoints[i])};
}

void check_breakpoints(const std::vector<double>& breakpoints, const std::string& what) {
  if (breakpoints.empty()) throw std::invalid_argument(what + ": no breakpoints");
  for (std::size_t i = 0; i < breakpoints.size(); ++i) {
    if (!std::isfinite(breakpoints[i])) {
      throw std::invalid_argument(what + ": breakpoint " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && !(breakpoints[i] > breakpoints[i - 1])) {
      throw std::invalid_argument(what + ": breakpoints must be strictly increasing (entry " +
                                  std::to_string(i) + ")");
    }
  }
}

namespace {
void check_values(const std::vector<double>& values, std::size_t expected, const char* what) {
  if (values.size() != expected) {
    throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(expected) +
                                " values, got " + std::to_string(values.size()));
  }
  for (double v : values) {
    if (!std::isfinite(v)) throw std::invalid_argument(std::string(what) + ": value not finite");
  }
}

// Exact at both ends (f = 0 gives a, f = 1 gives b), unlike a + (b - a) * f.
double lerp(double a, double b, double f) { return a * (1.0 - f) + b * f; }

// Index of the upper neighbour; equals the lower one for single-breakpoint axes.
std::size_t upper_index(const std::vector<double>& axis, const Bracket& b) {
  return axis.size() > 1 ? b.index + 1 : b.index;
}
}  // namespace

Table1D::Table1D(std::vector<double> x, std::vector<double> values)
    : x_(std::move(x)), values_(std::move(values)) {
  check_breakpoints(x_, "1-D table");
  check_values(values_, x_.size(), "1-D table");
}

double Table1D::operator()(double x) const {
  if (x_.empty()) return 0.0;
  const Bracket b = find_bracket(x_, x);
  return lerp(values_[b.index], values_[upper_index(x_, b)], b.fraction);
}

Table2D::Table2D(std::vector<double> rows, std::vector<double> cols, std::vector<double> values)
    : rows_(std::move(rows)), cols_(std::move(cols)), values_(std::move(values)) {
  check_breakpoints(rows_, "2-D table rows");
  check_breakpoints(cols_, "2-D table columns");
  check_values(values_, rows_.size() * cols_.size(), "2-D table");
}

double Table2D::operator()(double row, double col) const {
  if (rows_.empty()) return 0.0;
  const Bracket r = find_bracket(rows_, row);
  const Bracket c = find_bracket(cols_, col);
  const std::size_t nc = cols_.size();
  const std::size_t r1 = upper_index(rows_, r);
  const std::size_t c1 = upper_index(cols_, c);
  const double low = lerp(values_[r.index * nc + c.index], values_[r.index * nc + c1], c.fraction);
  const double high = lerp(values_[r1 * nc + c.index], values_[r1 * nc + c1], c.fraction);
  return lerp(low, high, r.fraction);
}

Table3D::Table3D(std::vector<double> pages, std::vector<double> rows, std::vector<double> cols,
                 std::vector<double> values)
    : pages_(std::move(pages)),
      rows_(std::move(rows)),
      cols_(std::move(cols)),
      values_(std::move(values)) {
  check_breakpoints(pages_, "3-D table pages");
  check_breakpoints(rows_, "3-D table rows");
  check_breakpoints(cols_, "3-D table columns");
  check_values(values_, pages_.size() * rows_.size() * cols_.size(), "3-D table");
}

double Table3D::operator()(double page, double row, double col) const {
  if (pages_.empty()) return 0.0;
  const Bracket p = find_bracket(pages_, page);
  const Bracket r = find_bracket(rows_, row);
  const Bracket c = find_bracket(cols_, col);
  const std::size_t nr = rows_.size();
  const std::size_t nc = cols_.size();
  const std::size_t p1 = upper_index(pages_, p);
  const std::size_t r1 = upper_index(rows_, r);
  const std::size_t c1 = upper_index(cols_, c);
  auto at = [&](std::size_t ip, std::size_t ir, std::size_t ic) {
    return values_[(ip * nr + ir) * nc + ic];
  };
  auto plane = [&](std::size_t ip) {
    const double low = lerp(at(ip, r.index, c.index), at(ip, r.index, c1), c.fraction);
    const double high = lerp(at(ip, r1, c.index), at(ip, r1, c1), c.fraction);
    return lerp(low, high, r.fraction);
  };
  return lerp(plane(p.index), plane(p1), p.fraction);
}

}  // namespace fedsim
