#include "common/radio/signal_status.hpp"

namespace fedsim::radio {

std::string_view to_string(SignalStatus status) {
  switch (status) {
    case SignalStatus::kValid: return "valid";
    case SignalStatus::kInvalidInput: return "invalid_input";
    case SignalStatus::kNotTuned: return "not_tuned";
    case SignalStatus::kNoStation: return "no_station";
    case SignalStatus::kReceiverFailed: return "receiver_failed";
    case SignalStatus::kStationOffAir: return "station_off_air";
    case SignalStatus::kOutOfServiceVolume: return "out_of_service_volume";
    case SignalStatus::kBelowRadioHorizon: return "below_radio_horizon";
    case SignalStatus::kConeOfConfusion: return "cone_of_confusion";
    case SignalStatus::kOutsideCoverage: return "outside_coverage";
    case SignalStatus::kBehindAntenna: return "behind_antenna";
  }
  return "unknown";
}

}  // namespace fedsim::radio
