#include "common/symbology/input_checks.hpp"

#include "common/symbology/flight_director.hpp"
#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"

namespace fedsim::symbology {

void check_angle(double value, double limit_deg, std::string_view where, std::string_view field) {
  util::require_in_range(value, -limit_deg * units::kDegToRad, limit_deg * units::kDegToRad, where, field, "rad");
}

void validate(const FlightDirector& fd, std::string_view where) {
  check_angle(fd.pitch_command_rad, 90.0, where, "flight_director.pitch_command_rad");
  check_angle(fd.roll_command_rad, 180.0, where, "flight_director.roll_command_rad");
}

}  // namespace fedsim::symbology
