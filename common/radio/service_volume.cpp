#include "common/radio/service_volume.hpp"

#include "common/units/units.hpp"

namespace fedsim::radio {

namespace {
constexpr double kFt = units::kFtToM;
constexpr double kNm = units::kNmToM;
}  // namespace

VhfServiceClass vhf_service_class(const nav::Navaid& navaid) {
  switch (navaid.usage) {
    case nav::UsageType::kTerminal: return VhfServiceClass::kTerminal;
    case nav::UsageType::kLow: return VhfServiceClass::kLow;
    case nav::UsageType::kHigh:
    case nav::UsageType::kBoth: return VhfServiceClass::kHigh;
    case nav::UsageType::kRnav:
    case nav::UsageType::kUnknown: break;
  }
  switch (navaid.power) {
    case nav::PowerClass::kHigh: return VhfServiceClass::kHigh;
    case nav::PowerClass::kLow: return VhfServiceClass::kTerminal;
    case nav::PowerClass::kMedium:
    case nav::PowerClass::kUnknown: break;
  }
  return VhfServiceClass::kLow;
}

NdbServiceClass ndb_service_class(const nav::Navaid& navaid) {
  const bool terminal = navaid.usage == nav::UsageType::kTerminal;
  switch (navaid.power) {
    case nav::PowerClass::kHigh: return NdbServiceClass::kHighHigh;
    case nav::PowerClass::kMedium: return NdbServiceClass::kHigh;
    case nav::PowerClass::kLow:
    case nav::PowerClass::kUnknown: break;
  }
  return terminal ? NdbServiceClass::kCompassLocator : NdbServiceClass::kMediumHigh;
}

double vhf_service_range_m(VhfServiceClass service_class, double height_above_station_m) {
  const double h = height_above_station_m;
  switch (service_class) {
    case VhfServiceClass::kTerminal: return h <= 12000.0 * kFt ? 25.0 * kNm : 0.0;
    case VhfServiceClass::kLow: return h <= 18000.0 * kFt ? 40.0 * kNm : 0.0;
    case VhfServiceClass::kHigh:
      if (h <= 14500.0 * kFt) return 40.0 * kNm;
      if (h < 18000.0 * kFt) return 100.0 * kNm;
      if (h <= 45000.0 * kFt) return 130.0 * kNm;
      if (h <= 60000.0 * kFt) return 100.0 * kNm;
      return 0.0;
  }
  return 0.0;
}

double ndb_service_range_m(NdbServiceClass service_class) {
  switch (service_class) {
    case NdbServiceClass::kCompassLocator: return 15.0 * kNm;
    case NdbServiceClass::kMediumHigh: return 25.0 * kNm;
    case NdbServiceClass::kHigh: return 50.0 * kNm;
    case NdbServiceClass::kHighHigh: return 75.0 * kNm;
  }
  return 0.0;
}

SignalStatus vhf_reception(VhfServiceClass service_class, const LinkGeometry& link,
                           double station_msl_m, double aircraft_msl_m) {
  if (!within_radio_line_of_sight(station_msl_m, aircraft_msl_m, link.ground_distance_m)) {
    return SignalStatus::kBelowRadioHorizon;
  }
  if (link.ground_distance_m > vhf_service_range_m(service_class, link.height_above_station_m)) {
    return SignalStatus::kOutOfServiceVolume;
  }
  return SignalStatus::kValid;
}

}  // namespace fedsim::radio
