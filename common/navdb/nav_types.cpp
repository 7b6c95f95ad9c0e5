#include "common/navdb/nav_types.hpp"

#include <array>
#include <utility>

namespace fedsim::nav {

namespace {

constexpr std::array<std::pair<NavaidType, std::string_view>, 7> kTypeNames{{
    {NavaidType::kVor, "VOR"},
    {NavaidType::kVorDme, "VOR-DME"},
    {NavaidType::kVortac, "VORTAC"},
    {NavaidType::kDme, "DME"},
    {NavaidType::kTacan, "TACAN"},
    {NavaidType::kNdb, "NDB"},
    {NavaidType::kNdbDme, "NDB-DME"},
}};

constexpr std::array<std::pair<PowerClass, std::string_view>, 4> kPowerNames{{
    {PowerClass::kUnknown, "UNKNOWN"},
    {PowerClass::kLow, "LOW"},
    {PowerClass::kMedium, "MEDIUM"},
    {PowerClass::kHigh, "HIGH"},
}};

constexpr std::array<std::pair<UsageType, std::string_view>, 6> kUsageNames{{
    {UsageType::kUnknown, "UNKNOWN"},
    {UsageType::kTerminal, "TERMINAL"},
    {UsageType::kLow, "LO"},
    {UsageType::kHigh, "HI"},
    {UsageType::kBoth, "BOTH"},
    {UsageType::kRnav, "RNAV"},
}};

template <typename Enum, std::size_t N>
std::string_view name_of(const std::array<std::pair<Enum, std::string_view>, N>& names, Enum value) {
  for (const auto& [e, name] : names) {
    if (e == value) return name;
  }
  return "?";
}

template <typename Enum, std::size_t N>
std::optional<Enum> parse(const std::array<std::pair<Enum, std::string_view>, N>& names,
                          std::string_view text) {
  const std::string upper = upper_ascii(text);
  for (const auto& [e, name] : names) {
    if (upper == name) return e;
  }
  return std::nullopt;
}

}  // namespace

std::string upper_ascii(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return out;
}

std::string_view navaid_type_name(NavaidType type) { return name_of(kTypeNames, type); }
std::optional<NavaidType> parse_navaid_type(std::string_view name) {
  return parse(kTypeNames, name);
}

std::string_view power_class_name(PowerClass power) { return name_of(kPowerNames, power); }
std::optional<PowerClass> parse_power_class(std::string_view name) {
  if (name.empty()) return PowerClass::kUnknown;
  return parse(kPowerNames, name);
}

std::string_view usage_type_name(UsageType usage) { return name_of(kUsageNames, usage); }
std::optional<UsageType> parse_usage_type(std::string_view name) {
  if (name.empty()) return UsageType::kUnknown;
  return parse(kUsageNames, name);
}

bool is_ndb(NavaidType type) { return type == NavaidType::kNdb || type == NavaidType::kNdbDme; }

bool has_vor(NavaidType type) {
  return type == NavaidType::kVor || type == NavaidType::kVorDme || type == NavaidType::kVortac;
}

bool has_dme(NavaidType type) {
  return type == NavaidType::kVorDme || type == NavaidType::kVortac || type == NavaidType::kDme ||
         type == NavaidType::kTacan || type == NavaidType::kNdbDme;
}

}  // namespace fedsim::nav
