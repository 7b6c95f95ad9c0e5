#include "tools/qtg/measures.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::qtg {
namespace {

/// The vertex of the parabola through (t-h, a), (t, b), (t+h, c) for equal spacing h.
Extremum refine(double t, double h, double a, double b, double c, bool is_max) {
  const double denom = a - 2 * b + c;
  if (denom == 0) return {t, b, is_max};
  const double offset = 0.5 * (a - c) / denom;  // in samples, within [-0.5, 0.5] at an extremum
  return {t + offset * h, b - 0.25 * (a - c) * offset, is_max};
}

/// Raw local extrema (plateaus count once), alternating max/min.
std::vector<Extremum> local_extrema(const Series& s, std::size_t i0, std::size_t i1) {
  std::vector<Extremum> out;
  for (std::size_t i = i0 + 1; i + 1 <= i1; ++i) {
    const double a = s.x[i - 1], b = s.x[i];
    std::size_t j = i + 1;
    while (j <= i1 && s.x[j] == b) ++j;  // skip a plateau
    if (j > i1) break;
    const double c = s.x[j];
    const bool is_max = b > a && b > c, is_min = b < a && b < c;
    if (is_max || is_min) {
      Extremum e = (j == i + 1) ? refine(s.t[i], s.t[i] - s.t[i - 1], a, b, c, is_max)
                                : Extremum{0.5 * (s.t[i] + s.t[j - 1]), b, is_max};
      if (!out.empty() && out.back().is_max == e.is_max) {
        // same kind twice (a ripple in between was dropped): keep the more extreme one
        if ((e.is_max && e.x > out.back().x) || (!e.is_max && e.x < out.back().x)) out.back() = e;
      } else {
        out.push_back(e);
      }
    }
    i = j - 1;
  }
  return out;
}

/// The run of extrema whose half-cycle amplitudes are all at least `floor`: it starts at the
/// first such amplitude (ripple before the mode is skipped) and ends where the mode has decayed
/// into the ripple.
std::vector<Extremum> mode_extrema(const std::vector<Extremum>& e, double floor) {
  std::size_t k = 0;
  while (k + 1 < e.size() && std::fabs(e[k + 1].x - e[k].x) < floor) ++k;
  std::size_t end = k + 1;
  while (end < e.size() && std::fabs(e[end].x - e[end - 1].x) >= floor) ++end;
  if (k + 1 >= e.size()) return {};
  return {e.begin() + static_cast<long>(k), e.begin() + static_cast<long>(end)};
}

std::pair<std::size_t, std::size_t> window(const Series& s, double from_s, double to_s) {
  const auto lo = std::lower_bound(s.t.begin(), s.t.end(), from_s) - s.t.begin();
  auto hi = std::upper_bound(s.t.begin(), s.t.end(), to_s) - s.t.begin();
  return {static_cast<std::size_t>(lo), static_cast<std::size_t>(hi)};  // [lo, hi)
}

}  // namespace

std::optional<Oscillation> analyse_oscillation(const Series& s, double from_s, double to_s,
                                               std::string& why, double noise_fraction) {
  const auto [lo, hi] = window(s, from_s, to_s);
  if (hi < lo + 3) {
    why = "fewer than three samples in the window";
    return std::nullopt;
  }
  auto extrema = local_extrema(s, lo, hi - 1);
  // the floor: a fraction of the largest half-cycle amplitude or of the signal's whole range in
  // the window, whichever is larger (a ripple on a ramp is not an oscillation)
  double largest = 0;
  for (std::size_t k = 0; k + 1 < extrema.size(); ++k)
    largest = std::max(largest, std::fabs(extrema[k + 1].x - extrema[k].x));
  const auto [lo_it, hi_it] = std::minmax_element(s.x.begin() + static_cast<long>(lo),
                                                  s.x.begin() + static_cast<long>(hi));
  extrema = mode_extrema(extrema, noise_fraction * std::max(largest, *hi_it - *lo_it));
  if (extrema.size() < 3) {
    why = "no oscillation: " + std::to_string(extrema.size()) +
          " extrema in the window (at least 3 needed for one cycle)";
    return std::nullopt;
  }
  Oscillation o;
  o.extrema = extrema;
  o.period_s = 2.0 * (extrema.back().t - extrema.front().t) /
               static_cast<double>(extrema.size() - 1);
  double log_sum = 0;
  int n = 0;
  for (std::size_t k = 0; k + 2 < extrema.size(); ++k) {
    const double a0 = std::fabs(extrema[k + 1].x - extrema[k].x);
    const double a1 = std::fabs(extrema[k + 2].x - extrema[k + 1].x);
    if (a0 <= 0 || a1 <= 0) continue;
    log_sum += std::log(a0 / a1);
    ++n;
  }
  if (n == 0) {
    why = "no pair of half-cycle amplitudes";
    return std::nullopt;
  }
  const double delta = 2.0 * log_sum / n;  // per full cycle
  o.damping_ratio = delta / std::sqrt(4 * M_PI * M_PI + delta * delta);
  return o;
}

std::optional<double> first_crossing(const Series& s, double threshold, double from_s,
                                     double to_s) {
  const auto [lo, hi] = window(s, from_s, to_s);
  for (std::size_t i = lo + 1; i < hi; ++i) {
    const double a = s.x[i - 1] - threshold, b = s.x[i] - threshold;
    if (a == 0) return s.t[i - 1];
    if ((a < 0) != (b < 0) || b == 0) {
      return s.t[i - 1] + (s.t[i] - s.t[i - 1]) * a / (a - b);
    }
  }
  return std::nullopt;
}

std::optional<Extreme> window_min(const Series& s, double from_s, double to_s) {
  const auto [lo, hi] = window(s, from_s, to_s);
  if (lo >= hi) return std::nullopt;
  const auto it = std::min_element(s.x.begin() + static_cast<long>(lo),
                                   s.x.begin() + static_cast<long>(hi));
  const auto i = static_cast<std::size_t>(it - s.x.begin());
  return Extreme{s.t[i], s.x[i]};
}

std::optional<Extreme> window_max(const Series& s, double from_s, double to_s) {
  const auto [lo, hi] = window(s, from_s, to_s);
  if (lo >= hi) return std::nullopt;
  const auto it = std::max_element(s.x.begin() + static_cast<long>(lo),
                                   s.x.begin() + static_cast<long>(hi));
  const auto i = static_cast<std::size_t>(it - s.x.begin());
  return Extreme{s.t[i], s.x[i]};
}

std::optional<StallPoint> stall_speed_1g(const Series& cas_kt, const Series& nz, double from_s, double to_s,
                                         std::string& why, double drop_fraction) {
  if (nz.empty()) {
    why = "no load factor (nz_g) recorded";
    return std::nullopt;
  }
  std::optional<StallPoint> peak;
  double peak_lift = 0;  // n_z / V^2 at the running maximum
  for (std::size_t i = 0; i < cas_kt.t.size(); ++i) {
    const double t = cas_kt.t[i], v = cas_kt.x[i];
    if (t < from_s || t > to_s || !(v >= 1.0)) continue;
    const double n = interpolate(nz, t);
    const double lift = n / (v * v);
    if (!peak || lift > peak_lift) {
      peak_lift = lift;
      peak = StallPoint{t, v, n, 0};
    } else if (lift < (1.0 - drop_fraction) * peak_lift) {
      if (!(peak->nz > 0)) break;
      peak->vs1g_kt = peak->cas_kt / std::sqrt(peak->nz);
      return peak;
    }
  }
  why = peak && !(peak->nz > 0)
            ? "the load factor at the lift coefficient's maximum is not positive"
            : "the load-factor-corrected lift coefficient (nz / V^2) never fell " +
                  std::to_string(static_cast<int>(drop_fraction * 100 + 0.5)) +
                  " % below a maximum: no stall in the window";
  return std::nullopt;
}

double lanchester_period_s(double tas_mps, double g_mps2) {
  return M_PI * std::sqrt(2.0) * tas_mps / g_mps2;
}

}  // namespace fedsim::qtg
