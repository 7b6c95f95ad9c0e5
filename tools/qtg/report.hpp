// The QTG report: one self-contained HTML page (inline SVG plots drawn here, no scripts) with a
// summary table first and, per test, its conditions, reference, checks and overlay plots.
#pragma once

#include <string>
#include <vector>

#include "tools/qtg/compare.hpp"

namespace fedsim::qtg {

struct ReportInfo {
  std::string generated_utc;  // e.g. 2026-12-06T04:00:00Z
  std::string tests_dir;
  double wall_s = 0;
};

/// An SVG line plot of the simulated channel, the reference (a series, or a value with its
/// band) and the tolerance band, with the measured points marked.
std::string svg_plot(const CheckResult& r);

/// The whole report as HTML.
std::string html_report(const std::vector<TestResult>& results, const ReportInfo& info);

/// HTML-escapes text.
std::string escape_html(const std::string& s);

}  // namespace fedsim::qtg
