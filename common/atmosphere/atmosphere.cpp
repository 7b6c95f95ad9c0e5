// US Standard Atmosphere 1976 layers with the seed's non-standard-day lapse correction.
#include "common/atmosphere/atmosphere.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim {

namespace {
using us1976::kHydrostatic;
// Sutherland's law constants of US 1976 (beta in kg/(s·m·K^0.5), S in K).
constexpr double kSutherlandBeta = 1.458e-6;
constexpr double kSutherlandS = 110.4;
// A lapse rate smaller than this is treated as isothermal to avoid 0/0 in eq. 3.3.
constexpr double kIsothermalLapse = 1e-12;

void check_offsets(const AtmosphereOffsets& offsets) {
  const double dt = offsets.sea_level_temperature_offset_k;
  const double p = offsets.sea_level_pressure_pa;
  if (!std::isfinite(dt) || std::abs(dt) > 60.0) {
    throw std::invalid_argument("atmosphere: sea-level temperature offset " + std::to_string(dt) +
                                " K is outside +-60 K");
  }
  if (!std::isfinite(p) || p < 85000.0 || p > 110000.0) {
    throw std::invalid_argument("atmosphere: sea-level pressure " + std::to_string(p) +
                                " Pa is outside 85-110 kPa");
  }
}
}  // namespace

double us1976::sea_level_speed_of_sound_mps() {
  return std::sqrt(kGamma * kSpecificGasConstant * kSeaLevelTemperature);
}

Atmosphere::Atmosphere(AtmosphereOffsets offsets) : offsets_(offsets) {
  check_offsets(offsets_);
  // Troposphere: the day's sea-level temperature, lapse adjusted to meet 216.65 K at 11 km.
  const double t0 = us1976::kSeaLevelTemperature + offsets_.sea_level_temperature_offset_k;
  layers_[0] = {0.0, (us1976::kTropopauseTemperature - t0) / us1976::kTropopauseAltitude, t0,
                offsets_.sea_level_pressure_pa};
  // Upper layers: standard temperatures, pressure continuous at every base.
  for (int i = 1; i < kLayers; ++i) {
    const Layer& below = layers_[i - 1];
    const double base_m = us1976::kLayerBaseAltitudeM[i];
    const double base_t = temperature_k(below, base_m);
    layers_[i] = {base_m, us1976::kLayerLapseKpm[i], base_t, pressure_pa(below, base_m, base_t)};
  }
}

double Atmosphere::geopotential_from_geometric_m(double geometric_alt_m) {
  return us1976::kEarthRadius * geometric_alt_m / (us1976::kEarthRadius + geometric_alt_m);
}

double Atmosphere::geometric_from_geopotential_m(double geopotential_alt_m) {
  return us1976::kEarthRadius * geopotential_alt_m / (us1976::kEarthRadius - geopotential_alt_m);
}

const Atmosphere::Layer& Atmosphere::layer_at(double geopotential_m) const {
  int i = kLayers - 1;
  while (i > 0 && geopotential_m < layers_[i].base_geopotential_m) --i;
  return layers_[i];
}

double Atmosphere::temperature_k(const Layer& layer, double geopotential_m) const {
  return layer.base_temperature_k + layer.lapse_kpm * (geopotential_m - layer.base_geopotential_m);
}

double Atmosphere::pressure_pa(const Layer& layer, double geopotential_m,
                               double temperature_k) const {
  if (std::abs(layer.lapse_kpm) < kIsothermalLapse) {
    return layer.base_pressure_pa *
           std::exp(-kHydrostatic * (geopotential_m - layer.base_geopotential_m) /
                    layer.base_temperature_k);
  }
  // eq. 3.3 written from the layer base: p = pb (Tb / T)^(g0 M0 / (R* L)).
  return layer.base_pressure_pa *
         std::pow(layer.base_temperature_k / temperature_k, kHydrostatic / layer.lapse_kpm);
}

AirProperties Atmosphere::at(double geometric_alt_m) const {
  AirProperties air;
  air.geometric_alt_m = std::clamp(geometric_alt_m, kMinAltitudeM, kMaxAltitudeM);
  if (std::isnan(geometric_alt_m)) air.geometric_alt_m = 0.0;
  air.geopotential_alt_m = geopotential_from_geometric_m(air.geometric_alt_m);
  const Layer& layer = layer_at(air.geopotential_alt_m);
  air.temperature_k = temperature_k(layer, air.geopotential_alt_m);
  air.pressure_pa = pressure_pa(layer, air.geopotential_alt_m, air.temperature_k);
  air.density_kgpm3 = air.pressure_pa / (us1976::kSpecificGasConstant * air.temperature_k);
  air.speed_of_sound_mps =
      std::sqrt(us1976::kGamma * us1976::kSpecificGasConstant * air.temperature_k);
  air.dynamic_viscosity_pas = kSutherlandBeta * std::pow(air.temperature_k, 1.5) /
                              (air.temperature_k + kSutherlandS);
  air.pressure_ratio = air.pressure_pa / us1976::kSeaLevelPressure;
  air.density_ratio = air.density_kgpm3 / us1976::kSeaLevelDensity;
  air.temperature_ratio = air.temperature_k / us1976::kSeaLevelTemperature;
  return air;
}

}  // namespace fedsim
