#include "tools/qtg/compare.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/csv/csv_reader.hpp"

namespace fedsim::qtg {
namespace {

/// Scores a value against its limits: the ratio is the distance from the middle of the range
/// over half the range, or for an upper limit alone the share of it used; the excursion is
/// how far beyond the nearer limit it lies (negative: inside, by that much).
void score_limits(CheckResult& r, double measured, double t) {
  const Check& c = r.check;
  const double hi = *c.limit_max;
  r.measured = measured;
  r.worst_time_s = t;
  if (c.limit_min) {
    const double lo = *c.limit_min;
    r.band = 0.5 * (hi - lo);
    r.worst_ratio = std::fabs(measured - 0.5 * (lo + hi)) / r.band;
    r.worst_excursion = std::max(measured - hi, lo - measured);
  } else {
    r.band = hi;
    r.worst_ratio = std::max(measured, 0.0) / hi;
    r.worst_excursion = measured - hi;
  }
  r.passed = std::isfinite(measured) && measured <= hi && (!c.limit_min || measured >= *c.limit_min);
}

/// Scores a derived value against its reference (or its limits).
void score(CheckResult& r, double measured, double t) {
  if (r.check.is_limit()) return score_limits(r, measured, t);
  r.measured = measured;
  r.band = r.check.tolerance.band(*r.reference);
  r.worst_excursion = measured - *r.reference;
  r.worst_time_s = t;
  r.worst_ratio = r.band > 0 ? std::fabs(r.worst_excursion) / r.band
                             : (r.worst_excursion == 0 ? 0 : std::numeric_limits<double>::infinity());
  r.passed = std::isfinite(measured) && r.worst_ratio <= 1.0;
}

void compare_time_history(CheckResult& r, double from, double to) {
  const Series& ref = r.reference_series;
  const Series& sim = r.simulated;
  int compared = 0;
  for (std::size_t i = 0; i < sim.t.size(); ++i) {
    const double t = sim.t[i];
    if (t < from || t > to || t < ref.t.front() || t > ref.t.back()) continue;
    const double expected = interpolate(ref, t);
    const double dev = sim.x[i] - expected;
    const double band = r.check.tolerance.band(expected);
    const double ratio = band > 0 ? std::fabs(dev) / band
                                  : (dev == 0 ? 0 : std::numeric_limits<double>::infinity());
    if (compared == 0 || ratio > r.worst_ratio) {
      r.worst_ratio = ratio;
      r.worst_excursion = dev;
      r.worst_time_s = t;
      r.band = band;
    }
    ++compared;
  }
  if (compared == 0) {
    r.problem = "the reference (" + std::to_string(ref.t.front()) + ".." +
                std::to_string(ref.t.back()) + " s) does not cover the compared window";
    return;
  }
  r.passed = r.worst_ratio <= 1.0;
}

/// The samples of `s` where the condition's channel lies within [min, max]; sets `problem`
/// (and returns nothing) when that channel was not recorded.
Series where(const Series& s, const Condition& c, const Channels& flown, std::string& problem) {
  const auto it = flown.find(c.channel);
  if (it == flown.end() || it->second.empty()) {
    problem = "channel " + c.channel + " (the while condition) was not recorded";
    return {};
  }
  Series out;
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    const double v = interpolate(it->second, s.t[i]);
    if (v >= c.min && v <= c.max) out.t.push_back(s.t[i]), out.x.push_back(s.x[i]);
  }
  return out;
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

bool TestResult::passed() const {
  if (!ran || checks.empty()) return false;
  for (const auto& c : checks)
    if (!c.passed) return false;
  return true;
}

CheckResult evaluate_check(const Check& check, const Channels& flown, const Series* reference_series,
                           double duration_s) {
  CheckResult r;
  r.check = check;
  const auto it = flown.find(check.channel);
  if (it == flown.end() || it->second.empty()) {
    r.problem = "channel " + check.channel + " was not recorded";
    return r;
  }
  r.simulated = it->second;
  if (check.while_condition) {
    const Condition& w = *check.while_condition;
    r.simulated = where(it->second, w, flown, r.problem);
    if (!r.problem.empty()) return r;
    if (r.simulated.empty()) {
      r.problem = "no sample while " + w.channel + " is within " + number_text(w.min) + ".." +
                  number_text(w.max);
      return r;
    }
  }
  const double from = check.from_s;
  const double to = check.to_s.value_or(duration_s + 1e-9);
  r.reference = check.reference_value;
  std::string why;
  switch (check.measure) {
    case Measure::time_history:
      if (!reference_series || reference_series->empty()) {
        r.problem = "no reference time history";
        return r;
      }
      r.reference_series = *reference_series;
      compare_time_history(r, from, to);
      return r;
    case Measure::period:
    case Measure::damping_ratio: {
      const auto o = analyse_oscillation(r.simulated, from, to, why);
      if (!o) {
        r.problem = why;
        return r;
      }
      r.marks = o->extrema;
      score(r, check.measure == Measure::period ? o->period_s : o->damping_ratio,
            o->extrema.front().t);
      return r;
    }
    case Measure::time_to: {
      const auto t = first_crossing(r.simulated, *check.threshold, from, to);
      if (!t) {
        r.problem = check.channel + " never reaches " + std::to_string(*check.threshold);
        return r;
      }
      r.marks = {{*t, *check.threshold, true}};
      score(r, *t - from, *t);
      return r;
    }
    case Measure::value_at: {
      const double t = check.at_s.value_or(r.simulated.t.back());
      const double v = interpolate(r.simulated, t);
      r.marks = {{t, v, true}};
      score(r, v, t);
      return r;
    }
    case Measure::value_when: {
      const auto w = flown.find(check.when_channel);
      if (w == flown.end()) {
        r.problem = "channel " + check.when_channel + " was not recorded";
        return r;
      }
      const auto t = first_crossing(w->second, *check.threshold, from, to);
      if (!t) {
        r.problem = check.when_channel + " never crosses " + std::to_string(*check.threshold);
        return r;
      }
      const double v = interpolate(r.simulated, *t);
      r.marks = {{*t, v, true}};
      score(r, v, *t);
      return r;
    }
    case Measure::minimum:
    case Measure::maximum: {
      const auto e = check.measure == Measure::minimum ? window_min(r.simulated, from, to)
                                                       : window_max(r.simulated, from, to);
      if (!e) {
        r.problem = "no sample in the window";
        return r;
      }
      r.marks = {{e->t, e->x, check.measure == Measure::maximum}};
      score(r, e->x, e->t);
      return r;
    }
    case Measure::stall_speed_1g: {
      const auto nz = flown.find("nz_g");
      const auto stall = stall_speed_1g(r.simulated, nz == flown.end() ? Series{} : nz->second, from, to, why);
      if (!stall) {
        r.problem = why;
        return r;
      }
      r.marks = {{stall->t, stall->cas_kt, false}};
      score(r, stall->vs1g_kt, stall->t);
      return r;
    }
    case Measure::max_abs: {
      const auto hi = window_max(r.simulated, from, to), lo = window_min(r.simulated, from, to);
      if (!hi || !lo) {
        r.problem = "no sample in the window";
        return r;
      }
      const Extreme e = std::fabs(lo->x) > std::fabs(hi->x) ? *lo : *hi;
      for (double& x : r.simulated.x) x = std::fabs(x);  // plotted as compared: |channel|
      r.marks = {{e.t, std::fabs(e.x), true}};
      score(r, std::fabs(e.x), e.t);
      return r;
    }
  }
  r.problem = "unknown measure";
  return r;
}

std::vector<CheckResult> evaluate_test(const QtgTest& test, const Channels& flown) {
  std::vector<CheckResult> out;
  for (const auto& check : test.checks) {
    if (check.measure != Measure::time_history) {
      out.push_back(evaluate_check(check, flown, nullptr, test.duration_s));
      continue;
    }
    try {
      const Series ref = read_reference_column(test.reference.file, check.reference_column);
      out.push_back(evaluate_check(check, flown, &ref, test.duration_s));
    } catch (const std::exception& e) {
      CheckResult r;
      r.check = check;
      r.problem = e.what();
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace fedsim::qtg
