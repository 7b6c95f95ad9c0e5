#include "tools/qtg/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace fedsim::qtg {
namespace {

constexpr double kW = 640, kH = 260, kLeft = 60, kRight = 15, kTop = 25, kBottom = 35;

std::string num(double v, int precision = 4) {
  if (!std::isfinite(v)) return "—";
  std::ostringstream s;
  s << std::setprecision(precision) << v;
  return s.str();
}

std::string unit_text(const std::string& unit) { return unit == "1" ? "" : " " + unit; }

/// "200 .. 2700" or "≤ 6".
std::string limits_text(const Check& c) {
  return c.limit_min ? num(*c.limit_min, 6) + " .. " + num(*c.limit_max, 6) : "≤ " + num(*c.limit_max, 6);
}

/// Maps data to pixels.
struct Axes {
  double t0, t1, y0, y1;
  double px(double t) const { return kLeft + (t - t0) / (t1 - t0) * (kW - kLeft - kRight); }
  double py(double y) const { return kTop + (y1 - y) / (y1 - y0) * (kH - kTop - kBottom); }
};

/// Ticks at 1, 2 or 5 times a power of ten, about five across.
std::vector<double> ticks(double lo, double hi) {
  const double raw = (hi - lo) / 5;
  const double p = std::pow(10, std::floor(std::log10(raw)));
  const double step = raw / p < 2 ? 2 * p : raw / p < 5 ? 5 * p : 10 * p;
  std::vector<double> out;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step)
    out.push_back(std::fabs(v) < 1e-12 * step ? 0 : v);
  return out;
}

std::string polyline(const Axes& a, const std::vector<double>& t, const std::vector<double>& y,
                     const std::string& style) {
  std::ostringstream s;
  s << "<polyline fill='none' " << style << " points='";
  // at most ~1500 points: decimate evenly (the plot is 640 px wide)
  const std::size_t step = std::max<std::size_t>(1, t.size() / 1500);
  for (std::size_t i = 0; i < t.size(); i += step)
    s << std::fixed << std::setprecision(1) << a.px(t[i]) << ',' << a.py(y[i]) << ' ';
  if (!t.empty()) s << a.px(t.back()) << ',' << a.py(y.back());
  s << "'/>\n";
  return s.str();
}

/// The band polygon: upper edge forwards, lower edge backwards.
std::string band_polygon(const Axes& a, const std::vector<double>& t, const std::vector<double>& lo,
                         const std::vector<double>& hi) {
  std::ostringstream s;
  s << "<polygon fill='#2ca02c' fill-opacity='0.18' stroke='none' points='" << std::fixed
    << std::setprecision(1);
  const std::size_t step = std::max<std::size_t>(1, t.size() / 750);
  for (std::size_t i = 0; i < t.size(); i += step) s << a.px(t[i]) << ',' << a.py(hi[i]) << ' ';
  for (std::size_t i = t.size(); i-- > 0;)
    if (i % step == 0) s << a.px(t[i]) << ',' << a.py(lo[i]) << ' ';
  s << "'/>\n";
  return s.str();
}

}  // namespace

std::string escape_html(const std::string& in) {
  std::string out;
  for (char c : in) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string svg_plot(const CheckResult& r) {
  if (r.simulated.empty()) return "<p>(nothing to plot)</p>";
  const Check& c = r.check;
  // a limit on a value at an event (touchdown) is shown around it: 30 s before, 15 s after
  const bool zoom = c.is_limit() && c.measure == Measure::value_when && !r.marks.empty();
  Series zoomed;
  if (zoom) {
    for (std::size_t i = 0; i < r.simulated.t.size(); ++i)
      if (std::fabs(r.simulated.t[i] - r.marks.front().t + 7.5) <= 22.5)
        zoomed.t.push_back(r.simulated.t[i]), zoomed.x.push_back(r.simulated.x[i]);
  }
  const Series& sim = zoom && zoomed.t.size() > 1 ? zoomed : r.simulated;
  const bool history = c.measure == Measure::time_history && !r.reference_series.empty();
  const bool value_band = !history && r.reference && c.measure != Measure::period &&
                          c.measure != Measure::damping_ratio && c.measure != Measure::time_to;
  // the band: around the reference series, or around the reference value over the window
  std::vector<double> bt, blo, bhi, rt, ry;
  const double from = c.from_s, to = c.to_s.value_or(sim.t.back());
  if (history) {
    for (std::size_t i = 0; i < r.reference_series.t.size(); ++i) {
      const double t = r.reference_series.t[i], y = r.reference_series.x[i];
      const double b = c.tolerance.band(y);
      bt.push_back(t), blo.push_back(y - b), bhi.push_back(y + b);
      rt.push_back(t), ry.push_back(y);
    }
  } else if (value_band) {
    const double b = c.tolerance.band(*r.reference);
    bt = {from, to}, blo = {*r.reference - b, *r.reference - b},
    bhi = {*r.reference + b, *r.reference + b};
    rt = {from, to}, ry = {*r.reference, *r.reference};
  } else if (c.is_limit()) {
    // the allowed range; for a value at an instant (touchdown) only around that instant
    const double lo = c.limit_min.value_or(std::min(0.0, *std::min_element(sim.x.begin(), sim.x.end())));
    double b0 = std::max(from, sim.t.front()), b1 = std::min(to, sim.t.back());
    if ((c.measure == Measure::value_when || c.measure == Measure::value_at) && !r.marks.empty()) {
      const double half = 0.02 * (sim.t.back() - sim.t.front());
      b0 = r.marks.front().t - half, b1 = r.marks.front().t + half;
    }
    bt = {b0, b1}, blo = {lo, lo}, bhi = {*c.limit_max, *c.limit_max};
  }
  double y0 = *std::min_element(sim.x.begin(), sim.x.end());
  double y1 = *std::max_element(sim.x.begin(), sim.x.end());
  for (double v : blo) y0 = std::min(y0, v);
  for (double v : bhi) y1 = std::max(y1, v);
  if (y1 - y0 < 1e-9) y0 -= 1, y1 += 1;
  const double pad = 0.05 * (y1 - y0);
  Axes a{sim.t.front(), std::max(sim.t.back(), sim.t.front() + 1e-6), y0 - pad, y1 + pad};
  if (history) a.t1 = std::max(a.t1, r.reference_series.t.back());

  std::ostringstream s;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kW << "' height='" << kH
    << "' viewBox='0 0 " << kW << ' ' << kH << "' font-family='sans-serif' font-size='11'>\n";
  s << "<rect x='" << kLeft << "' y='" << kTop << "' width='" << kW - kLeft - kRight
    << "' height='" << kH - kTop - kBottom << "' fill='white' stroke='#999'/>\n";
  for (double t : ticks(a.t0, a.t1))
    s << "<line x1='" << a.px(t) << "' x2='" << a.px(t) << "' y1='" << kTop << "' y2='"
      << kH - kBottom << "' stroke='#eee'/><text x='" << a.px(t) << "' y='" << kH - kBottom + 14
      << "' text-anchor='middle'>" << num(t) << "</text>\n";
  for (double y : ticks(a.y0, a.y1))
    s << "<line x1='" << kLeft << "' x2='" << kW - kRight << "' y1='" << a.py(y) << "' y2='"
      << a.py(y) << "' stroke='#eee'/><text x='" << kLeft - 4 << "' y='" << a.py(y) + 4
      << "' text-anchor='end'>" << num(y) << "</text>\n";
  s << "<text x='" << (kW + kLeft) / 2 << "' y='" << kH - 4 << "' text-anchor='middle'>time (s)</text>\n";
  s << "<text x='" << kLeft << "' y='" << kTop - 8 << "'>" << escape_html(c.name) << ": "
    << escape_html(c.channel)
    << " — simulator (blue)";
  if (!rt.empty()) s << ", reference (black dashed), tolerance " << escape_html(c.tolerance.text()) << " (green)";
  if (c.is_limit()) s << ", limits " << limits_text(c) << " (green)";
  s << "</text>\n";
  if (!bt.empty()) s << band_polygon(a, bt, blo, bhi);
  if (c.measure == Measure::time_to && r.reference) {
    // the reference time and its band, as vertical lines from the window start
    const double tr = c.from_s + *r.reference, b = c.tolerance.band(*r.reference);
    s << "<rect x='" << a.px(tr - b) << "' y='" << kTop << "' width='" << a.px(tr + b) - a.px(tr - b)
      << "' height='" << kH - kTop - kBottom << "' fill='#2ca02c' fill-opacity='0.18'/>\n";
    s << "<line x1='" << a.px(tr) << "' x2='" << a.px(tr) << "' y1='" << kTop << "' y2='"
      << kH - kBottom << "' stroke='black' stroke-dasharray='5,3'/>\n";
  }
  if (!rt.empty()) s << polyline(a, rt, ry, "stroke='black' stroke-dasharray='5,3' stroke-width='1.2'");
  s << polyline(a, sim.t, sim.x, "stroke='#1f77b4' stroke-width='1.5'");
  for (const auto& m : r.marks)
    s << "<circle cx='" << a.px(m.t) << "' cy='" << a.py(m.x) << "' r='3.5' fill='"
      << (r.passed ? "#2ca02c" : "#d62728") << "'/>\n";
  if (history && r.worst_ratio > 0)
    s << "<line x1='" << a.px(r.worst_time_s) << "' x2='" << a.px(r.worst_time_s) << "' y1='"
      << kTop << "' y2='" << kH - kBottom << "' stroke='#d62728' stroke-dasharray='2,2'/>\n";
  s << "</svg>\n";
  return s.str();
}

std::string html_report(const std::vector<TestResult>& results, const ReportInfo& info) {
  int passed = 0;
  for (const auto& r : results) passed += r.passed();
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>fedsim QTG report</title>\n"
       "<style>body{font-family:sans-serif;margin:2em;max-width:60em}"
       "table{border-collapse:collapse;margin:0.5em 0}td,th{border:1px solid #bbb;padding:2px 6px;"
       "text-align:left;font-size:90%}.pass{color:#1a7f1a;font-weight:bold}"
       ".fail{color:#c00;font-weight:bold}.test{page-break-before:always}"
       ".note{background:#fff6d5;padding:4px}</style></head><body>\n";
  h << "<h1>fedsim Qualification Test Guide — report</h1>\n";
  h << "<p>Generated " << escape_html(info.generated_utc) << " from <code>"
    << escape_html(info.tests_dir) << "</code> in " << num(info.wall_s, 3) << " s. "
    << "Tolerances in the terms of 14 CFR Part 60, Appendix A, Table A2A. <b>" << passed << " of "
    << results.size() << " tests passed.</b></p>\n";
  h << "<p class='note'>References are what each test says they are: <i>handbook</i> (published "
       "figures, source named), <i>analytic</i> (a textbook formula), <i>criteria</i> "
       "(acceptance limits such as certification criteria, named: no reference data), <i>regression</i> "
       "(fedsim's own earlier run: it detects change, it is <b>not</b> flight data), "
       "<i>flight_test</i> (a user's own data). Passing a regression test does not validate "
       "the model.</p>\n";
  h << "<h2>Summary</h2>\n<table><tr><th>test</th><th>Part 60 item</th><th>reference</th>"
       "<th>result</th><th>worst check: |excursion| as % of its tolerance</th></tr>\n";
  for (const auto& r : results) {
    const CheckResult* worst = nullptr;
    for (const auto& c : r.checks)
      if (!worst || c.worst_ratio > worst->worst_ratio || (!c.passed && worst->passed)) worst = &c;
    h << "<tr><td><a href='#" << escape_html(r.test.name) << "'>" << escape_html(r.test.name)
      << "</a></td><td>" << escape_html(r.test.part60_item) << "</td><td>"
      << escape_html(r.test.reference.kind) << "</td><td class='"
      << (r.passed() ? "pass'>PASS" : "fail'>FAIL") << "</td><td>";
    if (!r.ran) h << escape_html(r.problem);
    else if (worst) h << escape_html(worst->check.name) << ": "
                      << (worst->problem.empty() ? num(100 * worst->worst_ratio, 3) + " %" : escape_html(worst->problem));
    h << "</td></tr>\n";
  }
  h << "</table>\n";
  for (const auto& r : results) {
    const auto& t = r.test;
    h << "<div class='test' id='" << escape_html(t.name) << "'><h2>" << escape_html(t.name)
      << ": " << escape_html(t.title) << " — <span class='"
      << (r.passed() ? "pass'>PASS" : "fail'>FAIL") << "</span></h2>\n<table>";
    const auto row = [&](const std::string& k, const std::string& v) {
      h << "<tr><th>" << k << "</th><td>" << escape_html(v) << "</td></tr>";
    };
    row("Part 60 Table A2A item", t.part60_item);
    row("aircraft", t.aircraft);
    if (t.federation) {
      row("federation", "fedsim run " + t.federation->deployment + " --in-process" +
                            (t.federation->scenario.empty() ? "" : " --scenario " + t.federation->scenario) +
                            " (its federates in one process, closed loop; byte-identical to the DDS lockstep run)");
    } else {
      std::ostringstream start;
      start << "trim " << t.start.trim;
      if (t.start.trim != "ground") start << ", " << num(t.start.alt_ft) << " ft";
      if (t.start.ktas) start << ", " << num(*t.start.ktas) << " KTAS";
      if (t.start.kcas) start << ", " << num(*t.start.kcas) << " KCAS";
      start << ", heading " << num(t.start.heading_deg) << "°, flaps " << num(t.start.flaps)
            << (t.start.gear_down ? ", gear down" : "");
      if (t.start.trim == "climb") start << ", flight path " << num(t.start.gamma_deg) << "°";
      if (t.start.trim == "turn") start << ", bank " << num(t.start.bank_deg) << "°";
      if (t.start.trim == "ground")
        start << ", throttle " << num(t.start.throttle) << ", runway " << num(t.start.runway_elevation_m) << " m";
      row("start", start.str());
      std::string inputs = t.inputs.empty() ? (t.pilot.empty() ? "controls held at the start" : "")
                                            : t.inputs + (t.inputs_relative ? " (offsets about the start)" : " (absolute)");
      if (t.pilot == "stall_entry") {
        char pilot[200];
        std::snprintf(pilot, sizeof pilot,
                      "%sthe stall-entry test pilot: wings level, airspeed down %.2g kt/s at throttle %.2g until "
                      "the stall is identified, then the recovery",
                      inputs.empty() ? "" : ", then ", t.pilot_entry_rate_kt_per_s, t.pilot_throttle);
        inputs += pilot;
      }
      row("inputs", inputs);
    }
    if (t.runway) row("runway", t.runway->airport + " " + t.runway->runway + " (data/nav/runways.csv)");
    if (r.from_recording) row("recording", r.out_dir + " (evaluated from this recording, not flown by the QTG)");
    row("run", num(t.duration_s) + " s at " + num(t.rate_hz) + " Hz; " + num(r.wall_s, 3) + " s wall");
    row("reference", t.reference.kind + ": " + t.reference.source +
                         (t.reference.file.empty() ? "" : " (" + t.reference.file + ")"));
    row("test file", t.path);
    if (!r.ran) row("problem", r.problem);
    h << "</table>\n";
    if (!r.checks.empty()) {
      h << "<table><tr><th>check</th><th>measure</th><th>simulator</th><th>reference</th>"
           "<th>tolerance</th><th>worst excursion</th><th>at (s)</th><th>result</th></tr>\n";
      for (const auto& c : r.checks) {
        const std::string u = unit_text(measure_unit(c.check));
        const Check& k = c.check;
        h << "<tr><td>" << escape_html(k.name) << "</td><td>" << measure_name(k.measure)
          << " of " << escape_html(k.channel);
        if (k.while_condition)
          h << " while " << escape_html(k.while_condition->channel) << " is within "
            << num(k.while_condition->min) << " .. " << num(k.while_condition->max);
        if (k.measure == Measure::value_when)
          h << " when " << escape_html(k.when_channel) << " crosses " << num(*k.threshold);
        h << "</td><td>"
          << (c.measured ? num(*c.measured) + u : (k.measure == Measure::time_history ? "time history" : "—"))
          << "</td><td>";
        if (k.is_limit()) h << limits_text(k) << u << "</td><td>limits";
        else h << (c.reference ? num(*c.reference) + u : "time history") << "</td><td>"
               << escape_html(k.tolerance.text());
        h << "</td><td>";
        if (!c.problem.empty()) h << escape_html(c.problem);
        else if (k.is_limit() && c.measured)
          h << (c.passed ? "inside, " : "OUTSIDE, ") << num(std::fabs(c.worst_excursion)) << u
            << (c.passed ? " from the limit" : " beyond the limit") << " (" << num(100 * c.worst_ratio, 3)
            << (k.limit_min ? " % of the half-range from its middle)" : " % of the limit)");
        else h << (c.worst_excursion >= 0 ? "+" : "") << num(c.worst_excursion) << u << " ("
               << num(100 * c.worst_ratio, 3) << " % of tolerance)";
        h << "</td><td>" << num(c.worst_time_s) << "</td><td class='"
          << (c.passed ? "pass'>pass" : "fail'>FAIL") << "</td></tr>\n";
      }
      h << "</table>\n";
      for (const auto& c : r.checks) h << "<div>" << svg_plot(c) << "</div>\n";
    }
    h << "</div>\n";
  }
  h << "</body></html>\n";
  return h.str();
}

}  // namespace fedsim::qtg
