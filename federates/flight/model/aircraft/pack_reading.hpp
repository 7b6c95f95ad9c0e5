// Internal helpers of the aircraft-pack loader: tables and the flight model's section readers.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "common/aircraft_pack/pack_reading.hpp"
#include "common/units/units.hpp"
#include "common/util/config_node.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

namespace fedsim::flight::pack_detail {

using util::ConfigNode;
// The pack's generic readers (common/aircraft_pack), shared with its common sections.
using aircraft_pack::read_breakpoints;
using aircraft_pack::read_vector3;
using aircraft_pack::require_unique_names;

/// A table as written in a pack (see data/aircraft/README.md, "Tables"), before its input names
/// are resolved. Everything is in lookup order: 1-D (row), 2-D (row, column), 3-D (page, row,
/// column); values are flattened row-major as Table1D/2D/3D expect.
struct ParsedTable {
  int dimensions = 0;
  std::vector<std::string> input_names;
  std::vector<ConfigNode> input_nodes;  // for error messages about the names
  std::vector<std::vector<double>> breakpoints;
  std::vector<double> values;
};
ParsedTable read_table(const ConfigNode& table);

/// A 1-D table whose single input must be `input_name`.
Table1D read_table_1d(const ConfigNode& parent, const std::string& key,
                      const std::string& input_name);
/// A 2-D table with the given row and column input names.
Table2D read_table_2d(const ConfigNode& parent, const std::string& key,
                      const std::string& row_name, const std::string& column_name);

// Section readers (one per pack section; see aircraft_pack_loader.cpp for the order).
FlightControlsSpec read_flight_controls(const ConfigNode& section);
AeroModelSpec read_aerodynamics(const ConfigNode& section, const FlightControlsSpec& controls);
std::vector<EngineSpec> read_propulsion(const ConfigNode& section, const aircraft_pack::MassSpec& mass);
LandingGearSpec read_landing_gear(const ConfigNode& section);

}  // namespace fedsim::flight::pack_detail
