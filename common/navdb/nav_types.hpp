// The text forms of the navigation database's enumerations (OurAirports' spellings, also the
// values stored in the database) and the families of station types.
//
// Inputs/outputs: names as in OurAirports' navaids.csv ("VOR-DME", "HIGH", "TERMINAL"); parse_*
// return nullopt for a name that is not one of them (the caller reports where it came from).
#pragma once

#include "common/navdb/nav_records.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace fedsim::nav {

/// "VOR", "VOR-DME", "VORTAC", "DME", "TACAN", "NDB", "NDB-DME".
std::string_view navaid_type_name(NavaidType type);
/// The type of an OurAirports type name (exact spelling, case-insensitive).
std::optional<NavaidType> parse_navaid_type(std::string_view name);

/// "UNKNOWN", "LOW", "MEDIUM", "HIGH"; OurAirports leaves some empty (= UNKNOWN).
std::string_view power_class_name(PowerClass power);
std::optional<PowerClass> parse_power_class(std::string_view name);

/// "UNKNOWN", "TERMINAL", "LO", "HI", "BOTH", "RNAV"; empty = UNKNOWN.
std::string_view usage_type_name(UsageType usage);
std::optional<UsageType> parse_usage_type(std::string_view name);

/// Stations whose frequency is in the LF/MF band (kHz) rather than VHF.
bool is_ndb(NavaidType type);
/// Stations with a VOR (VHF omnidirectional range: radials).
bool has_vor(NavaidType type);
/// Stations with distance measuring equipment (a DME or the DME part of a TACAN).
bool has_dme(NavaidType type);

/// Upper-case copy (ASCII), for case-insensitive comparison of idents.
std::string upper_ascii(std::string_view text);

}  // namespace fedsim::nav
