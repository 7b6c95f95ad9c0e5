#include "flight/model/afcs/afcs_modes.hpp"

namespace fedsim::flight::afcs {

std::string_view to_string(LateralMode mode) {
  switch (mode) {
    case LateralMode::kNone: return "";
    case LateralMode::kRollAttitude: return "CWS R";
    case LateralMode::kWingLevel: return "WLV";
    case LateralMode::kHeadingHold: return "HDG HOLD";
    case LateralMode::kHeadingSelect: return "HDG SEL";
    case LateralMode::kLocalizer: return "VOR/LOC";
    case LateralMode::kAlign: return "ALIGN";
    case LateralMode::kRollout: return "ROLLOUT";
    case LateralMode::kGoAround: return "TOGA";
  }
  return "?";
}

std::string_view to_string(VerticalMode mode) {
  switch (mode) {
    case VerticalMode::kNone: return "";
    case VerticalMode::kPitchAttitude: return "CWS P";
    case VerticalMode::kAltitudeHold: return "ALT HOLD";
    case VerticalMode::kAltitudeCapture: return "ALT ACQ";
    case VerticalMode::kVerticalSpeed: return "V/S";
    case VerticalMode::kLevelChange: return "MCP SPD";
    case VerticalMode::kGlideSlope: return "G/S";
    case VerticalMode::kFlare: return "FLARE";
    case VerticalMode::kRollout: return "ROLLOUT";
    case VerticalMode::kGoAround: return "TOGA";
  }
  return "?";
}

std::string_view to_string(ThrustMode mode) {
  switch (mode) {
    case ThrustMode::kNone: return "";
    case ThrustMode::kArm: return "ARM";
    case ThrustMode::kSpeed: return "MCP SPD";
    case ThrustMode::kClimb: return "N1";
    case ThrustMode::kIdle: return "THR HLD";
    case ThrustMode::kRetard: return "RETARD";
    case ThrustMode::kGoAround: return "GA";
  }
  return "?";
}

bool is_path_mode(VerticalMode mode) {
  switch (mode) {
    case VerticalMode::kAltitudeHold:
    case VerticalMode::kAltitudeCapture:
    case VerticalMode::kVerticalSpeed:
    case VerticalMode::kLevelChange:
    case VerticalMode::kGlideSlope:
    case VerticalMode::kFlare:
    case VerticalMode::kGoAround:
      return true;
    case VerticalMode::kNone:
    case VerticalMode::kPitchAttitude:
    case VerticalMode::kRollout:
      return false;
  }
  return false;
}

}  // namespace fedsim::flight::afcs
