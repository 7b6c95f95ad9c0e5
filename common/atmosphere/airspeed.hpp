// Air-data conversions: Mach, dynamic pressure, TAS <-> EAS <-> CAS (compressible pitot formulas).
#pragma once

#include "common/atmosphere/atmosphere.hpp"

namespace fedsim {

/// Mach number M = V / a (eq. 3.6).
double mach_number(double tas_mps, const AirProperties& air);

/// Dynamic pressure qbar = rho V^2 / 2.
double dynamic_pressure_pa(double tas_mps, const AirProperties& air);

/// Equivalent airspeed EAS = TAS sqrt(rho / rho0) and its inverse.
double eas_from_tas_mps(double tas_mps, const AirProperties& air);
double tas_from_eas_mps(double eas_mps, const AirProperties& air);

/// Pitot impact pressure qc = p_total - p_static for a Mach number: isentropic (Saint-Venant)
/// below M 1, Rayleigh pitot formula (normal shock ahead of the probe) above.
double impact_pressure_pa(double mach, double static_pressure_pa);

/// Inverse of impact_pressure_pa (closed form subsonic, fixed-point iteration supersonic).
double mach_from_impact_pressure(double impact_pressure_pa, double static_pressure_pa);

/// Calibrated airspeed: the speed that gives the same impact pressure at sea-level standard
/// static pressure (what an airspeed indicator calibrated to US 1976 shows, no position error).
double cas_from_tas_mps(double tas_mps, const AirProperties& air);
double tas_from_cas_mps(double cas_mps, const AirProperties& air);

}  // namespace fedsim
