#include "tools/topic/csv_layout.hpp"

#include <fastrtps/types/DynamicType.h>
#include <fastrtps/types/DynamicTypeMember.h>
#include <fastrtps/types/MemberDescriptor.h>
#include <fastrtps/types/TypeDescriptor.h>

#include <algorithm>
#include <map>

namespace fedsim::tools {

namespace {

using ftypes::DynamicType_ptr;

DynamicType_ptr resolve_alias(DynamicType_ptr type) {
  for (int depth = 0; type && type->get_kind() == ftypes::TK_ALIAS && depth < 16; ++depth) {
    type = type->get_descriptor()->get_base_type();
  }
  return type;
}

std::string join(const std::string& prefix, const std::string& name) {
  return prefix.empty() ? name : prefix + "." + name;
}

void type_columns(const DynamicType_ptr& declared, const std::string& prefix,
                  std::vector<std::string>& out) {
  const DynamicType_ptr type = resolve_alias(declared);
  if (type && type->get_kind() == ftypes::TK_STRUCTURE) {
    std::map<ftypes::MemberId, ftypes::DynamicTypeMember*> by_id;
    type->get_all_members(by_id);
    std::vector<ftypes::DynamicTypeMember*> members;
    for (auto& [id, m] : by_id) members.push_back(m);
    std::stable_sort(members.begin(), members.end(), [](const auto* a, const auto* b) {
      return a->get_descriptor()->get_index() < b->get_descriptor()->get_index();
    });
    for (auto* m : members) {
      type_columns(m->get_descriptor()->get_type(), join(prefix, m->get_name()), out);
    }
    return;
  }
  if (type && type->get_kind() == ftypes::TK_ARRAY) {
    std::vector<std::uint32_t> bounds;
    std::uint32_t total = 1;
    for (std::uint32_t d = 0; d < type->get_bounds_size(); ++d) {
      bounds.push_back(type->get_bounds(d));
      total *= bounds.back();
    }
    const DynamicType_ptr element = type->get_descriptor()->get_element_type();
    for (std::uint32_t flat = 0; flat < total; ++flat) {
      std::string label;
      std::uint32_t rest = flat;
      std::vector<std::uint32_t> position(bounds.size());
      for (std::size_t d = bounds.size(); d-- > 0;) {
        position[d] = rest % bounds[d];
        rest /= bounds[d];
      }
      for (auto p : position) label += "[" + std::to_string(p) + "]";
      type_columns(element, prefix + label, out);
    }
    return;
  }
  out.push_back(prefix);  // scalar, string, enum, sequence (one cell), unsupported kinds
}

std::string scalar_cell(const ScalarValue& v) {
  switch (v.kind) {
    case ScalarValue::Kind::Bool: return v.u ? "1" : "0";
    case ScalarValue::Kind::Int: return std::to_string(v.i);
    case ScalarValue::Kind::UInt:
    case ScalarValue::Kind::Enum: return std::to_string(v.u);
    case ScalarValue::Kind::Float32: return format_float(static_cast<float>(v.d));
    case ScalarValue::Kind::Float64: return format_double(v.d);
    case ScalarValue::Kind::Char:
    case ScalarValue::Kind::String:
    case ScalarValue::Kind::Unsupported: return csv_quote(v.s);
  }
  return {};
}

void sample_cells(const SampleNode& node, std::vector<std::string>& out) {
  switch (node.kind) {
    case SampleNode::Kind::Scalar: out.push_back(scalar_cell(node.value)); return;
    case SampleNode::Kind::Struct:
    case SampleNode::Kind::Array:
      for (const auto& child : node.children) sample_cells(child, out);
      return;
    case SampleNode::Kind::Sequence: out.push_back(csv_quote(to_json(node))); return;
  }
}

const SampleNode* find_path(const SampleNode& root, const std::vector<std::string>& path) {
  const SampleNode* node = &root;
  for (const auto& name : path) {
    node = node->member(name);
    if (!node) return nullptr;
  }
  return node;
}

}  // namespace

std::string csv_quote(const std::string& cell) {
  const bool needs = cell.find_first_of(",\"\r\n") != std::string::npos ||
                     (!cell.empty() && (cell.front() == ' ' || cell.back() == ' ' ||
                                        cell.front() == '\t' || cell.back() == '\t'));
  if (!needs) return cell;
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::vector<std::string> flattened_field_names(const ftypes::DynamicType_ptr& type) {
  std::vector<std::string> out;
  const DynamicType_ptr resolved = resolve_alias(type);
  if (resolved && resolved->get_kind() == ftypes::TK_STRUCTURE) type_columns(resolved, "", out);
  return out;
}

std::vector<std::string> flattened_cells(const SampleNode& sample) {
  std::vector<std::string> out;
  sample_cells(sample, out);
  return out;
}

CsvLayout::CsvLayout(const ftypes::DynamicType_ptr& type) {
  const std::vector<std::string> fields = flattened_field_names(type);
  field_count_ = fields.size();
  auto has = [&](const std::string& name) {
    return std::find(fields.begin(), fields.end(), name) != fields.end();
  };
  if (has("stamp.sim_time_s")) {
    time_source_ = TimeSource::Stamp;
  } else if (has("sim_time_s")) {
    time_source_ = TimeSource::TopLevel;
    moved_field_ = static_cast<std::size_t>(
        std::find(fields.begin(), fields.end(), "sim_time_s") - fields.begin());
  }
  if (has("stamp.frame")) {
    frame_path_ = std::vector<std::string>{"stamp", "frame"};
  } else if (has("frame")) {
    frame_path_ = std::vector<std::string>{"frame"};
  }
  columns_.push_back(has_sim_time() ? "sim_time_s" : "receive_time_s");
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (moved_field_ && *moved_field_ == i) continue;
    columns_.push_back(fields[i]);
  }
}

std::string CsvLayout::header() const {
  std::string line;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) line += ',';
    line += csv_quote(columns_[i]);
  }
  return line;
}

std::optional<std::uint64_t> CsvLayout::frame_of(const SampleNode& sample) const {
  if (!frame_path_) return std::nullopt;
  const SampleNode* node = find_path(sample, *frame_path_);
  if (!node || node->kind != SampleNode::Kind::Scalar) return std::nullopt;
  if (node->value.kind == ScalarValue::Kind::UInt) return node->value.u;
  if (node->value.kind == ScalarValue::Kind::Int && node->value.i >= 0) {
    return static_cast<std::uint64_t>(node->value.i);
  }
  return std::nullopt;
}

std::string CsvLayout::row(const SampleNode& sample, double receive_time_s) const {
  std::vector<std::string> cells = flattened_cells(sample);
  cells.resize(field_count_);  // a sample that could not be read fully keeps the column count
  std::string time_cell = format_double(receive_time_s);
  if (time_source_ != TimeSource::Receive) {
    const SampleNode* t = time_source_ == TimeSource::Stamp
                              ? find_path(sample, {"stamp", "sim_time_s"})
                              : sample.member("sim_time_s");
    if (t && t->kind == SampleNode::Kind::Scalar) {
      time_cell = t->value.kind == ScalarValue::Kind::Float32
                      ? format_float(static_cast<float>(t->value.d))
                      : format_double(t->value.d);
    }
  }
  std::string line = time_cell;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (moved_field_ && *moved_field_ == i) continue;
    line += ',';
    line += cells[i];
  }
  return line;
}

}  // namespace fedsim::tools
