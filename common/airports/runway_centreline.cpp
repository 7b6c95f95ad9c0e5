#include "common/airports/runway_centreline.hpp"

#include "common/units/units.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace fedsim {

std::string reciprocal_runway(const std::string& designator) {
  std::size_t digits = 0;
  while (digits < designator.size() && std::isdigit(static_cast<unsigned char>(designator[digits])))
    ++digits;
  const std::string suffix = designator.substr(digits);
  if (digits == 0 || digits > 2 || suffix.size() > 1 ||
      (suffix.size() == 1 && std::string("LCR").find(suffix) == std::string::npos))
    throw std::invalid_argument("runway '" + designator + "': not a designator such as 28R");
  const int number = std::stoi(designator.substr(0, digits));
  if (number < 1 || number > 36)
    throw std::invalid_argument("runway '" + designator + "': the number must be 1..36");
  const int other = (number + 18 - 1) % 36 + 1;
  const std::string side = suffix == "L" ? "R" : suffix == "R" ? "L" : suffix;
  return std::to_string(other) + side;
}

RunwayCentreline::RunwayCentreline(double threshold_lat_rad, double threshold_lon_rad, double far_lat_rad,
                                   double far_lon_rad)
    : lat0_deg_(threshold_lat_rad * units::kRadToDeg), lon0_deg_(threshold_lon_rad * units::kRadToDeg) {
  double east = 0.0, north = 0.0;
  plane_coordinates(far_lat_rad, far_lon_rad, east, north);
  length_m_ = std::hypot(east, north);
  if (!(length_m_ > 1.0)) throw std::invalid_argument("RunwayCentreline: the two ends coincide");
  along_east_ = east / length_m_;
  along_north_ = north / length_m_;
}

RunwayCentreline RunwayCentreline::from_table(const RunwayTable& table, const std::string& airport,
                                              const std::string& runway) {
  const RunwayEnd landing = table.at(airport, runway);
  // data/nav/runways.csv spells a one-digit end 01L (OurAirports); another table may write 1L.
  const std::string far_name = reciprocal_runway(runway);
  auto far = table.find(airport, far_name);
  const bool one_digit = far_name.size() == 1 || !std::isdigit(static_cast<unsigned char>(far_name[1]));
  if (!far && one_digit) far = table.find(airport, "0" + far_name);
  if (!far)
    throw std::invalid_argument(airport + " " + runway + ": no opposite end " + far_name +
                                " in the runway table (the centreline needs both ends)");
  try {
    return RunwayCentreline(landing.threshold_lat_rad, landing.threshold_lon_rad, far->threshold_lat_rad,
                            far->threshold_lon_rad);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(airport + " " + runway + ": the two ends coincide");
  }
}

void RunwayCentreline::plane_coordinates(double lat_rad, double lon_rad, double& east_m, double& north_m) const {
  const GeographicLib::LocalCartesian plane(lat0_deg_, lon0_deg_, 0.0);
  double up = 0.0;
  plane.Forward(lat_rad * units::kRadToDeg, lon_rad * units::kRadToDeg, 0.0, east_m, north_m, up);
}

double RunwayCentreline::beyond_threshold_m(double lat_rad, double lon_rad) const {
  double e = 0.0, n = 0.0;
  plane_coordinates(lat_rad, lon_rad, e, n);
  return e * along_east_ + n * along_north_;
}

double RunwayCentreline::left_m(double lat_rad, double lon_rad) const {
  double e = 0.0, n = 0.0;
  plane_coordinates(lat_rad, lon_rad, e, n);
  // Left of the landing direction (east, north) = (along rotated by +90 deg counter-clockwise).
  return -e * along_north_ + n * along_east_;
}

}  // namespace fedsim
