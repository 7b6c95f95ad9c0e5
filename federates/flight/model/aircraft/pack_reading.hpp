// Internal helpers of the aircraft-pack loader: vectors, angles, tables and section readers.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "common/units/units.hpp"
#include "common/util/config_node.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

namespace fedsim::flight::pack_detail {

using util::ConfigNode;


/// A required [x, y, z] list of three numbers.
Eigen::Vector3d read_vector3(const ConfigNode& parent, const std::string& key);

/// A strictly increasing list of finite numbers; errors point at the offending entry.
std::vector<double> read_breakpoints(const ConfigNode& parent, const std::string& key);

/// Fails at the first duplicate name (the node of each item is given for its line).
void require_unique_names(const std::vector<ConfigNode>& items, const std::string& key);

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
std::vector<EngineSpec> read_propulsion(const ConfigNode& section, const MassSpec& mass);
LandingGearSpec read_landing_gear(const ConfigNode& section);

}  // namespace fedsim::flight::pack_detail
