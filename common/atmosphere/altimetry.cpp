// Barometric altimetry on the US 1976 standard pressure law.
#include "common/atmosphere/altimetry.hpp"

#include <cmath>

namespace fedsim {

namespace {
const Atmosphere& standard_atmosphere() {
  static const Atmosphere standard{};
  return standard;
}

// The standard law to invert: US 1976's layers.
using us1976::kHydrostatic;
using us1976::kLayerBaseAltitudeM;
using us1976::kLayerLapseKpm;
using us1976::kLayers;
}  // namespace

double standard_pressure_at_m(double geopotential_alt_m) {
  return standard_atmosphere()
      .at(Atmosphere::geometric_from_geopotential_m(geopotential_alt_m))
      .pressure_pa;
}

double pressure_altitude_m(double static_pressure_pa) {
  // Walk up to the highest layer whose base pressure is still above the static pressure.
  int i = 0;
  while (i + 1 < kLayers && standard_pressure_at_m(kLayerBaseAltitudeM[i + 1]) > static_pressure_pa) {
    ++i;
  }
  const double base_m = kLayerBaseAltitudeM[i];
  const double base_p = standard_pressure_at_m(base_m);
  const double base_t = standard_atmosphere()
                            .at(Atmosphere::geometric_from_geopotential_m(base_m))
                            .temperature_k;
  const double lapse = kLayerLapseKpm[i];
  if (lapse == 0.0) return base_m - base_t / kHydrostatic * std::log(static_pressure_pa / base_p);
  return base_m + base_t / lapse * (std::pow(static_pressure_pa / base_p, -lapse / kHydrostatic) - 1.0);
}

double altimeter_reading_m(double static_pressure_pa, double setting_pa) {
  return pressure_altitude_m(static_pressure_pa * kStandardAltimeterSettingPa / setting_pa);
}

double qfe_pa(const Atmosphere& atmosphere, double field_elevation_m) {
  return atmosphere.at(field_elevation_m).pressure_pa;
}

double qnh_pa(const Atmosphere& atmosphere, double field_elevation_m) {
  // Chosen so that altimeter_reading_m(qfe, qnh) returns the field elevation exactly.
  return qfe_pa(atmosphere, field_elevation_m) * kStandardAltimeterSettingPa /
         standard_pressure_at_m(field_elevation_m);
}

}  // namespace fedsim
