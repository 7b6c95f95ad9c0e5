// fedsim-spline: fits a cubic spline through sparse x,y points and writes a dense lookup table
// (seed 2.8: tables are generated offline, then interpolated linearly at run time, seed 2.9).
#include <CLI/CLI.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>

#include "common/util/cli_checks.hpp"
#include "common/math/cubic_spline.hpp"
#include "spline_csv.hpp"

namespace {

fedsim::SplineEnd end_condition(const std::string& ends, std::optional<double> slope) {
  if (slope) return fedsim::SplineEnd::clamped(*slope);
  if (ends == "chord") return fedsim::SplineEnd::chord();
  return fedsim::SplineEnd::natural();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fit a cubic spline through sparse x,y CSV points and write a dense x,y table."};
  std::string input;
  std::string output;
  std::string ends = "natural";
  std::optional<double> start_slope;
  std::optional<double> end_slope;
  std::optional<double> from;
  std::optional<double> to;
  double step = 0.0;
  int points = 0;
  int digits = 8;
  app.add_option("input", input, "CSV with x,y columns (header line optional, '#' comments)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("-o,--output", output, "output CSV (default: standard output)");
  app.add_option("--ends", ends,
                 "end condition: natural (zero curvature) or chord (slope of the end segment)")
      ->check(CLI::IsMember({"natural", "chord"}));
  app.add_option("--start-slope", start_slope, "clamp the first end to this dy/dx");
  app.add_option("--end-slope", end_slope, "clamp the last end to this dy/dx");
  app.add_option("--from", from, "first x of the table (default: first data x)");
  app.add_option("--to", to, "last x of the table (default: last data x)");
  auto* step_option = app.add_option("--step", step, "x interval of the table")
                          ->check(fedsim::util::kFinitePositive);
  app.add_option("--points", points, "number of table points (default 101)")
      ->check(fedsim::util::kFinitePositive)
      ->excludes(step_option);
  app.add_option("--digits", digits, "significant figures written")->check(fedsim::util::FiniteRange(3, 17));
  CLI11_PARSE(app, argc, argv);

  try {
    std::ifstream in(input);
    const fedsim::tools::XyData data = fedsim::tools::read_xy_csv(in, input);
    const fedsim::CubicSpline spline(data.x, data.y, end_condition(ends, start_slope),
                                             end_condition(ends, end_slope));
    const double x0 = from.value_or(data.x.front());
    const double x1 = to.value_or(data.x.back());
    if (!(x1 > x0)) throw std::invalid_argument("--to must be greater than --from");
    std::size_t n = points > 0 ? static_cast<std::size_t>(points) : 101;
    double dx = (x1 - x0) / static_cast<double>(n - 1);
    if (step > 0.0) {
      n = static_cast<std::size_t>(std::floor((x1 - x0) / step + 1e-9)) + 1;
      dx = step;
    }
    fedsim::tools::XyData table{data.x_name, data.y_name, {}, {}};
    for (std::size_t i = 0; i < n; ++i) {
      table.x.push_back(x0 + dx * static_cast<double>(i));
      table.y.push_back(spline(table.x.back()));
    }
    if (output.empty()) {
      fedsim::tools::write_xy_csv(std::cout, table, digits);
    } else {
      std::ofstream out(output);
      fedsim::tools::write_xy_csv(out, table, digits);
      if (!out) throw std::runtime_error("cannot write " + output);
    }
  } catch (const std::exception& e) {
    std::cerr << "fedsim-spline: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
