// US Standard Atmosphere 1976 (seed 3.2, eqs 3.1-3.5) with non-standard sea-level conditions.
#pragma once

#include "common/units/units.hpp"

namespace fedsim {

/// Defining constants of the US Standard Atmosphere 1976 (NOAA-S/T 76-1562, section 1.2).
namespace us1976 {
inline constexpr double kGasConstant = 8314.32;           // R*, N·m/(kmol·K)
inline constexpr double kMolarMass = 28.9644;             // M0, kg/kmol
inline constexpr double kEarthRadius = 6356766.0;         // r0, m, for geopotential altitude
inline constexpr double kGamma = 1.4;                     // ratio of specific heats of air
inline constexpr double kSeaLevelTemperature = 288.15;    // K
inline constexpr double kSeaLevelPressure = 101325.0;     // Pa
inline constexpr double kSeaLevelDensity = 1.225;         // kg/m³ (to the table's 4 figures)
inline constexpr double kTropopauseTemperature = 216.65;  // K
inline constexpr double kTropopauseAltitude = 11000.0;    // geopotential m
inline constexpr double kSpecificGasConstant = kGasConstant / kMolarMass;  // J/(kg·K)
inline constexpr double kG0 = units::kStandardGravityMps2;  // g0, m/s², as US 1976 defines it
/// g0 M0 / R*: the hydrostatic constant of eq. 3.3 (K/m).
inline constexpr double kHydrostatic = kG0 * kMolarMass / kGasConstant;
/// The seven layers (Table 4): base geopotential altitudes (m) and standard lapse rates (K/m).
inline constexpr int kLayers = 7;
inline constexpr double kLayerBaseAltitudeM[kLayers] = {0.0,     11000.0, 20000.0, 32000.0,
                                                        47000.0, 51000.0, 71000.0};
inline constexpr double kLayerLapseKpm[kLayers] = {-0.0065, 0.0, 0.001, 0.0028,
                                                   0.0,     -0.0028, -0.002};
/// Sea-level speed of sound a0 = sqrt(gamma R T0) (eq. 3.5), 340.294 m/s.
double sea_level_speed_of_sound_mps();
}  // namespace us1976

/// Departure of the day from the standard: both zero give the US 1976 standard atmosphere.
/// The sea-level temperature offset changes the tropospheric lapse rate so that the temperature
/// still reaches the standard 216.65 K at the tropopause (seed 3.2, after eq. 3.2); the pressure
/// follows hydrostatically from the mean-sea-level pressure, so every layer above is continuous.
struct AtmosphereOffsets {
  double sea_level_temperature_offset_k = 0.0;   // T(MSL) - 288.15 K, limited to +-60 K
  double sea_level_pressure_pa = us1976::kSeaLevelPressure;  // actual MSL pressure, 85-110 kPa
};

/// The air at one altitude.
struct AirProperties {
  double geometric_alt_m = 0.0;
  double geopotential_alt_m = 0.0;     // eq. 3.1
  double temperature_k = 0.0;          // eq. 3.2
  double pressure_pa = 0.0;            // eq. 3.3
  double density_kgpm3 = 0.0;          // eq. 3.4
  double speed_of_sound_mps = 0.0;     // eq. 3.5
  double dynamic_viscosity_pas = 0.0;  // Sutherland's law (US 1976 eq. 51)
  double pressure_ratio = 0.0;         // delta = p / 101325 Pa
  double density_ratio = 0.0;          // sigma = rho / 1.225 kg/m³
  double temperature_ratio = 0.0;      // theta = T / 288.15 K
};

/// Temperature, pressure, density and speed of sound against geometric altitude. The seven
/// base layers of US 1976 are modelled (-5 km to 86 km geometric); altitudes outside are clamped
/// to that range so that a lookup always returns finite air. No allocation; thread-safe.
class Atmosphere {
 public:
  static constexpr double kMinAltitudeM = -5000.0;
  static constexpr double kMaxAltitudeM = 86000.0;

  /// Throws std::invalid_argument for offsets outside the limits stated on AtmosphereOffsets.
  explicit Atmosphere(AtmosphereOffsets offsets = {});

  AirProperties at(double geometric_alt_m) const;
  const AtmosphereOffsets& offsets() const { return offsets_; }

  /// Geopotential altitude H = r0 z / (r0 + z) (eq. 3.1) and its inverse.
  static double geopotential_from_geometric_m(double geometric_alt_m);
  static double geometric_from_geopotential_m(double geopotential_alt_m);

 private:
  static constexpr int kLayers = us1976::kLayers;
  struct Layer {
    double base_geopotential_m;
    double lapse_kpm;  // dT/dH
    double base_temperature_k;
    double base_pressure_pa;
  };
  double temperature_k(const Layer& layer, double geopotential_m) const;
  double pressure_pa(const Layer& layer, double geopotential_m, double temperature_k) const;
  const Layer& layer_at(double geopotential_m) const;

  AtmosphereOffsets offsets_;
  Layer layers_[kLayers];
};

}  // namespace fedsim
