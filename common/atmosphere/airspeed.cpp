// Air-data conversions between true, equivalent and calibrated airspeed.
#include "common/atmosphere/airspeed.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim {

namespace {
// qc/p at M = 1 where the subsonic and the Rayleigh formulas meet: 1.2^3.5 - 1.
const double kSonicImpactRatio = std::pow(1.2, 3.5) - 1.0;
// Rayleigh pitot formula constant: (gamma+1)^2 / (4 gamma) ... collected for gamma = 1.4.
constexpr double kRayleighNumerator = 166.921580;
constexpr int kRayleighIterations = 50;
}  // namespace

double mach_number(double tas_mps, const AirProperties& air) {
  return tas_mps / air.speed_of_sound_mps;
}

double dynamic_pressure_pa(double tas_mps, const AirProperties& air) {
  return 0.5 * air.density_kgpm3 * tas_mps * tas_mps;
}

double eas_from_tas_mps(double tas_mps, const AirProperties& air) {
  return tas_mps * std::sqrt(air.density_kgpm3 / us1976::kSeaLevelDensity);
}

double tas_from_eas_mps(double eas_mps, const AirProperties& air) {
  return eas_mps * std::sqrt(us1976::kSeaLevelDensity / air.density_kgpm3);
}

double impact_pressure_pa(double mach, double static_pressure_pa) {
  const double m = std::abs(mach);
  if (m <= 1.0) {
    return static_pressure_pa * (std::pow(1.0 + 0.2 * m * m, 3.5) - 1.0);
  }
  const double m2 = m * m;
  return static_pressure_pa *
         (kRayleighNumerator * std::pow(m, 7.0) / std::pow(7.0 * m2 - 1.0, 2.5) - 1.0);
}

double mach_from_impact_pressure(double impact_pressure_pa, double static_pressure_pa) {
  const double ratio = std::max(impact_pressure_pa, 0.0) / static_pressure_pa;
  if (ratio <= kSonicImpactRatio) {
    return std::sqrt(5.0 * (std::pow(ratio + 1.0, 1.0 / 3.5) - 1.0));
  }
  // Rayleigh formula rearranged as M = 0.881284 sqrt((qc/p + 1)(1 - 1/(7 M^2))^2.5); the map is
  // a contraction for M > 1, so a fixed number of iterations converges to machine precision.
  const double k = std::sqrt(std::pow(7.0, 2.5) / kRayleighNumerator);
  double m = 1.0;
  for (int i = 0; i < kRayleighIterations; ++i) {
    m = k * std::sqrt((ratio + 1.0) * std::pow(1.0 - 1.0 / (7.0 * m * m), 2.5));
  }
  return m;
}

double cas_from_tas_mps(double tas_mps, const AirProperties& air) {
  const double qc = impact_pressure_pa(mach_number(tas_mps, air), air.pressure_pa);
  const double cas = us1976::sea_level_speed_of_sound_mps() *
                     mach_from_impact_pressure(qc, us1976::kSeaLevelPressure);
  return std::copysign(cas, tas_mps);
}

double tas_from_cas_mps(double cas_mps, const AirProperties& air) {
  const double qc = impact_pressure_pa(cas_mps / us1976::sea_level_speed_of_sound_mps(),
                                       us1976::kSeaLevelPressure);
  const double tas = air.speed_of_sound_mps * mach_from_impact_pressure(qc, air.pressure_pa);
  return std::copysign(tas, cas_mps);
}

}  // namespace fedsim
