// Aircraft-pack loader helpers: tables (3-vectors, breakpoints and duplicate names are
// common/aircraft_pack/pack_reading.hpp's).
#include "flight/model/aircraft/pack_reading.hpp"

#include <sstream>

namespace fedsim::flight::pack_detail {

namespace {
// One list of numbers of a known length; errors point at the list.
std::vector<double> read_row(const ConfigNode& row, std::size_t columns, const char* per) {
  if (!row.yaml().IsSequence()) {
    row.fail("expected a list of " + std::to_string(columns) + " numbers");
  }
  const auto items = row.items();
  if (items.size() != columns) {
    row.fail("expected " + std::to_string(columns) + " values (one per " + per +
             " breakpoint), got " + std::to_string(items.size()));
  }
  std::vector<double> out;
  out.reserve(columns);
  for (const auto& item : items) out.push_back(item.as_number());
  return out;
}

// A list of exactly `count` entries; errors point at the list.
std::vector<ConfigNode> sized_list(const ConfigNode& list, std::size_t count, const char* what) {
  if (!list.yaml().IsSequence()) list.fail("expected a list of " + std::string(what));
  auto items = list.items();
  if (items.size() != count) {
    list.fail("expected " + std::to_string(count) + " " + what + ", got " +
              std::to_string(items.size()));
  }
  return items;
}

void append(std::vector<double>& to, const std::vector<double>& from) {
  to.insert(to.end(), from.begin(), from.end());
}
}  // namespace

ParsedTable read_table(const ConfigNode& table) {
  ParsedTable out;
  const bool has_column = table.has("column");
  const bool has_page = table.has("page");
  if (has_page && !has_column) table.fail("a 3-D table needs page, row and column");
  out.dimensions = has_page ? 3 : (has_column ? 2 : 1);
  std::vector<std::string> allowed = {"row", "row_breakpoints", "values"};
  if (out.dimensions >= 2) allowed.insert(allowed.end(), {"column", "column_breakpoints"});
  if (out.dimensions == 3) allowed.insert(allowed.end(), {"page", "page_breakpoints"});
  table.reject_unknown_keys(allowed);

  std::vector<std::string> axes;
  if (out.dimensions == 3) axes.push_back("page");
  axes.push_back("row");
  if (out.dimensions >= 2) axes.push_back("column");
  for (const auto& axis : axes) {
    out.input_names.push_back(table.string(axis));
    out.input_nodes.push_back(table.child(axis));
    out.breakpoints.push_back(read_breakpoints(table, axis + "_breakpoints"));
  }

  const ConfigNode values = table.child("values");
  if (out.dimensions == 1) {
    out.values = read_row(values, out.breakpoints[0].size(), "row");
  } else if (out.dimensions == 2) {
    for (const auto& row : sized_list(values, out.breakpoints[0].size(), "rows")) {
      append(out.values, read_row(row, out.breakpoints[1].size(), "column"));
    }
  } else {
    for (const auto& page : sized_list(values, out.breakpoints[0].size(), "pages")) {
      for (const auto& row : sized_list(page, out.breakpoints[1].size(), "rows")) {
        append(out.values, read_row(row, out.breakpoints[2].size(), "column"));
      }
    }
  }
  return out;
}

namespace {
void require_inputs(const ParsedTable& table, const ConfigNode& node,
                    const std::vector<std::string>& names) {
  if (table.dimensions != static_cast<int>(names.size())) {
    node.fail("expected a " + std::to_string(names.size()) + "-D table");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (table.input_names[i] != names[i]) {
      table.input_nodes[i].fail("this table's input must be '" + names[i] + "'");
    }
  }
}
}  // namespace

Table1D read_table_1d(const ConfigNode& parent, const std::string& key,
                      const std::string& input_name) {
  const ConfigNode node = parent.child(key);
  ParsedTable t = read_table(node);
  require_inputs(t, node, {input_name});
  return Table1D(std::move(t.breakpoints[0]), std::move(t.values));
}

Table2D read_table_2d(const ConfigNode& parent, const std::string& key,
                      const std::string& row_name, const std::string& column_name) {
  const ConfigNode node = parent.child(key);
  ParsedTable t = read_table(node);
  require_inputs(t, node, {row_name, column_name});
  return Table2D(std::move(t.breakpoints[0]), std::move(t.breakpoints[1]), std::move(t.values));
}

}  // namespace fedsim::flight::pack_detail
