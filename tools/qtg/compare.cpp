#include "tools/qtg/compare.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/csv/csv_reader.hpp"

namespace fedsim::qtg {
namespace {

/// Scores a derived value against its reference.
void score(CheckResult& r, double measured, double t) {
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
