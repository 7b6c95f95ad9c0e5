// Validation of the weather settings.
#include "flight/model/aircraft/weather_settings.hpp"

#include <stdexcept>
#include <string>

namespace fedsim::flight {

void WeatherSettings::validate() const {
  // Each sub-model checks its own figures; prefix the field so a message points at it.
  try {
    Atmosphere check(atmosphere);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("weather.atmosphere: ") + e.what());
  }
  try {
    wind.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("weather.wind: ") + e.what());
  }
  try {
    microburst.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("weather.microburst: ") + e.what());
  }
}

}  // namespace fedsim::flight
