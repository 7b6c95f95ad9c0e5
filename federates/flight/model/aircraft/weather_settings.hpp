// The weather an aircraft flies in: non-standard atmosphere, steady wind by altitude, a
// microburst and Dryden turbulence (executive steps 1 and 2).
#pragma once

#include <cstdint>
#include <optional>

#include "common/atmosphere/atmosphere.hpp"
#include "flight/model/weather/turbulence.hpp"
#include "flight/model/weather/wind_profile.hpp"
#include "flight/model/weather/wind_shear.hpp"

namespace fedsim::flight {

/// Weather settings. Changing them (AircraftModel::set_weather) builds tables and may allocate;
/// stepping with them does not.
struct WeatherSettings {
  /// ISA deviation: sea-level temperature offset and sea-level pressure (US 1976 otherwise).
  AtmosphereOffsets atmosphere;
  /// Steady wind: speed and "from" direction against altitude above mean sea level (m).
  /// Empty tables: calm.
  WindProfile::Params wind;
  /// Oseguera-Bowles microburst; max_outflow_mps = 0 is none. Its centre is given in metres
  /// north and east of the scenario origin (the position of the last reset or reposition).
  WindShear::Params microburst;
  /// MIL-F-8785C Dryden turbulence intensity (none, light, moderate, severe).
  Turbulence::Severity turbulence = Turbulence::Severity::kNone;
  /// Seed of the turbulence generator; unset: AircraftModel::Options::turbulence_seed.
  std::optional<std::uint64_t> turbulence_seed;

  /// Throws std::invalid_argument naming the bad field.
  void validate() const;
};

}  // namespace fedsim::flight
