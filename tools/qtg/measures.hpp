// Derived measures of a time history: oscillation period and damping ratio from the extrema,
// threshold crossings (time to bank, lift-off), values at a time, extremes over a window.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tools/qtg/channels.hpp"

namespace fedsim::qtg {

/// One extremum of an oscillation (time refined by a parabola through three samples).
struct Extremum {
  double t = 0, x = 0;
  bool is_max = false;
};

struct Oscillation {
  std::vector<Extremum> extrema;  // alternating maxima and minima used
  double period_s = 0;            // 2 x the mean spacing of the extrema
  double damping_ratio = 0;       // from the log decrement of half-cycle amplitudes
};

/// Analyses the samples in [from_s, to_s]. Peak-to-peak half-cycle amplitudes cancel a constant
/// offset: for x = c + A e^(-s t) cos(w t + f) the ratio of successive ones is e^(s T / 2)
/// exactly, so the log decrement per cycle is 2 ln(a_k / a_k+1) and
/// zeta = delta / sqrt(4 pi^2 + delta^2). Half-cycles smaller than `noise_fraction` of the
/// largest one (or of the signal's range in the window) are ripple: the analysis uses the first
/// unbroken run of larger ones.
/// Returns nullopt (with `why`) unless at least three extrema (one full cycle) are found.
std::optional<Oscillation> analyse_oscillation(const Series& s, double from_s, double to_s,
                                               std::string& why, double noise_fraction = 0.02);

/// The first time in [from_s, to_s] the series crosses `threshold` (either direction), linearly
/// interpolated between samples; nullopt if it never does.
std::optional<double> first_crossing(const Series& s, double threshold, double from_s,
                                     double to_s);

/// Minimum / maximum over [from_s, to_s] with its time; nullopt if no sample lies there.
struct Extreme {
  double t = 0, x = 0;
};
std::optional<Extreme> window_min(const Series& s, double from_s, double to_s);
std::optional<Extreme> window_max(const Series& s, double from_s, double to_s);

/// The 1 g stall speed of 14 CFR 25.103: V_CLmax / sqrt(n_z), V_CLmax the calibrated airspeed
/// at which the load-factor-corrected lift coefficient n_z W / (q S) is first a maximum in a
/// stall entry. W and S are constant and q = rho_0 V_c^2 / 2 (calibrated airspeed, low Mach), so
/// that coefficient is proportional to n_z / V_c^2. "First a maximum": the running maximum in
/// [from_s, to_s] once n_z / V_c^2 has fallen `drop_fraction` below it (the g-break, or the
/// recovery after an entry that ends at the elevator's stop). Samples below 1 kt are skipped.
struct StallPoint {
  double t = 0;        // when the corrected lift coefficient peaked [s]
  double cas_kt = 0;   // V_CLmax
  double nz = 0;       // n_z then
  double vs1g_kt = 0;  // V_CLmax / sqrt(n_z)
};
std::optional<StallPoint> stall_speed_1g(const Series& cas_kt, const Series& nz, double from_s, double to_s,
                                         std::string& why, double drop_fraction = 0.03);

/// Lanchester's phugoid period T = pi sqrt(2) V / g (V true airspeed in m/s), seed ch. 7 /
/// Etkin & Reid, Dynamics of Flight (1996) section 6.3.
double lanchester_period_s(double tas_mps, double g_mps2 = 9.80665);

}  // namespace fedsim::qtg
