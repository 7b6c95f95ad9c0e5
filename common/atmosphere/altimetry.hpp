// Barometric altimetry: pressure altitude, altimeter reading for a subscale setting, QNH and QFE.
#pragma once

#include "common/atmosphere/atmosphere.hpp"

namespace fedsim {

/// Standard pressure setting (1013.25 hPa) used for flight levels.
inline constexpr double kStandardAltimeterSettingPa = us1976::kSeaLevelPressure;

/// Pressure altitude: the US 1976 standard geopotential altitude at which the standard pressure
/// equals the given static pressure (altimeter set to 1013.25 hPa). Valid through all layers.
double pressure_altitude_m(double static_pressure_pa);

/// Standard-atmosphere pressure at a geopotential altitude (the altimeter's calibration law).
double standard_pressure_at_m(double geopotential_alt_m);

/// What a perfect barometric altimeter shows for a static pressure and a subscale setting: its
/// aneroid follows the standard law shifted so that it reads zero at the setting pressure.
double altimeter_reading_m(double static_pressure_pa, double setting_pa);

/// QFE: the station (field) pressure; an altimeter set to it reads height above the field.
double qfe_pa(const Atmosphere& atmosphere, double field_elevation_m);

/// QNH: the setting that makes the altimeter read the field elevation on the ground.
double qnh_pa(const Atmosphere& atmosphere, double field_elevation_m);

}  // namespace fedsim
