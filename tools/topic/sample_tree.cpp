#include "tools/topic/sample_tree.hpp"

#include <fastrtps/types/DynamicType.h>
#include <fastrtps/types/DynamicTypeMember.h>
#include <fastrtps/types/MemberDescriptor.h>
#include <fastrtps/types/TypeDescriptor.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

namespace fedsim::tools {

namespace {

using ftypes::DynamicData;
using ftypes::DynamicType_ptr;
using ftypes::MemberId;
using ftypes::TypeKind;

constexpr auto kOk = eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK;

/// Members of a struct type in declaration order.
std::vector<ftypes::DynamicTypeMember*> ordered_members(const DynamicType_ptr& type) {
  std::map<MemberId, ftypes::DynamicTypeMember*> by_id;
  type->get_all_members(by_id);
  std::vector<ftypes::DynamicTypeMember*> members;
  members.reserve(by_id.size());
  for (auto& [id, member] : by_id) members.push_back(member);
  std::stable_sort(members.begin(), members.end(), [](const auto* a, const auto* b) {
    return a->get_descriptor()->get_index() < b->get_descriptor()->get_index();
  });
  return members;
}

DynamicType_ptr resolve_alias(DynamicType_ptr type) {
  for (int depth = 0; type && type->get_kind() == ftypes::TK_ALIAS && depth < 16; ++depth) {
    type = type->get_descriptor()->get_base_type();
  }
  return type;
}

ScalarValue unsupported(const std::string& what) {
  ScalarValue v;
  v.kind = ScalarValue::Kind::Unsupported;
  v.s = "<" + what + ">";
  return v;
}

std::string kind_name(TypeKind kind) {
  switch (kind) {
    case ftypes::TK_UNION: return "union";
    case ftypes::TK_MAP: return "map";
    case ftypes::TK_BITSET: return "bitset";
    case ftypes::TK_BITMASK: return "bitmask";
    case ftypes::TK_STRING16: return "wstring";
    case ftypes::TK_CHAR16: return "wchar";
    case ftypes::TK_FLOAT128: return "long double";
    default: return "type kind " + std::to_string(static_cast<int>(kind));
  }
}

void read_value(DynamicData& data, MemberId id, const DynamicType_ptr& declared_type,
                SampleNode& out);

void read_struct(DynamicData& data, const DynamicType_ptr& type, SampleNode& out) {
  out.kind = SampleNode::Kind::Struct;
  for (auto* member : ordered_members(type)) {
    SampleNode child;
    child.name = member->get_name();
    read_value(data, member->get_id(), member->get_descriptor()->get_type(), child);
    out.children.push_back(std::move(child));
  }
}

std::string index_label(const std::vector<std::uint32_t>& position) {
  std::string label;
  for (auto p : position) label += "[" + std::to_string(p) + "]";
  return label;
}

void read_collection(DynamicData& data, const DynamicType_ptr& type, SampleNode& out) {
  const DynamicType_ptr element = type->get_descriptor()->get_element_type();
  if (type->get_kind() == ftypes::TK_SEQUENCE) {
    out.kind = SampleNode::Kind::Sequence;
    const std::uint32_t count = data.get_item_count();
    for (std::uint32_t i = 0; i < count; ++i) {
      SampleNode item;
      item.name = "[" + std::to_string(i) + "]";
      read_value(data, i, element, item);
      out.children.push_back(std::move(item));
    }
    return;
  }
  out.kind = SampleNode::Kind::Array;
  std::vector<std::uint32_t> bounds;
  std::uint32_t total = 1;
  for (std::uint32_t d = 0; d < type->get_bounds_size(); ++d) {
    bounds.push_back(type->get_bounds(d));
    total *= bounds.back();
  }
  std::vector<std::uint32_t> position(bounds.size(), 0);
  for (std::uint32_t flat = 0; flat < total; ++flat) {
    // Row-major position of `flat` (last index varies fastest).
    std::uint32_t rest = flat;
    for (std::size_t d = bounds.size(); d-- > 0;) {
      position[d] = rest % bounds[d];
      rest /= bounds[d];
    }
    SampleNode item;
    item.name = index_label(position);
    read_value(data, data.get_array_index(position), element, item);
    out.children.push_back(std::move(item));
  }
}

void read_value(DynamicData& data, MemberId id, const DynamicType_ptr& declared_type,
                SampleNode& out) {
  const DynamicType_ptr type = resolve_alias(declared_type);
  out.kind = SampleNode::Kind::Scalar;
  if (!type) {
    out.value = unsupported("no type");
    return;
  }
  ScalarValue& v = out.value;
  bool ok = true;
  switch (type->get_kind()) {
    case ftypes::TK_BOOLEAN: {
      bool b = false;
      ok = data.get_bool_value(b, id) == kOk;
      v.kind = ScalarValue::Kind::Bool;
      v.u = b ? 1 : 0;
      break;
    }
    case ftypes::TK_BYTE: {
      ftypes::octet b = 0;
      ok = data.get_byte_value(b, id) == kOk;
      v.kind = ScalarValue::Kind::UInt;
      v.u = b;
      break;
    }
    case ftypes::TK_INT16: {
      std::int16_t x = 0;
      ok = data.get_int16_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::Int;
      v.i = x;
      break;
    }
    case ftypes::TK_INT32: {
      std::int32_t x = 0;
      ok = data.get_int32_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::Int;
      v.i = x;
      break;
    }
    case ftypes::TK_INT64: {
      std::int64_t x = 0;
      ok = data.get_int64_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::Int;
      v.i = x;
      break;
    }
    case ftypes::TK_UINT16: {
      std::uint16_t x = 0;
      ok = data.get_uint16_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::UInt;
      v.u = x;
      break;
    }
    case ftypes::TK_UINT32: {
      std::uint32_t x = 0;
      ok = data.get_uint32_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::UInt;
      v.u = x;
      break;
    }
    case ftypes::TK_UINT64: {
      std::uint64_t x = 0;
      ok = data.get_uint64_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::UInt;
      v.u = x;
      break;
    }
    case ftypes::TK_FLOAT32: {
      float x = 0;
      ok = data.get_float32_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::Float32;
      v.d = x;
      break;
    }
    case ftypes::TK_FLOAT64: {
      double x = 0;
      ok = data.get_float64_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::Float64;
      v.d = x;
      break;
    }
    case ftypes::TK_CHAR8: {
      char c = 0;
      ok = data.get_char8_value(c, id) == kOk;
      v.kind = ScalarValue::Kind::Char;
      v.s = c == 0 ? std::string() : std::string(1, c);
      break;
    }
    case ftypes::TK_STRING8: {
      ok = data.get_string_value(v.s, id) == kOk;
      v.kind = ScalarValue::Kind::String;
      break;
    }
    case ftypes::TK_ENUM: {
      std::uint32_t x = 0;
      ok = data.get_enum_value(x, id) == kOk;
      v.kind = ScalarValue::Kind::Enum;
      v.u = x;
      if (data.get_enum_value(v.s, id) != kOk) v.s = std::to_string(x);
      break;
    }
    case ftypes::TK_STRUCTURE: {
      DynamicData* nested = data.loan_value(id);
      if (!nested) {
        out.value = unsupported("unreadable struct");
        return;
      }
      read_struct(*nested, type, out);
      data.return_loaned_value(nested);
      return;
    }
    case ftypes::TK_ARRAY:
    case ftypes::TK_SEQUENCE: {
      DynamicData* nested = data.loan_value(id);
      if (!nested) {
        out.value = unsupported("unreadable collection");
        return;
      }
      read_collection(*nested, type, out);
      data.return_loaned_value(nested);
      return;
    }
    default:
      out.value = unsupported(kind_name(type->get_kind()));
      return;
  }
  if (!ok) out.value = unsupported("unreadable " + type->get_name());
}

// --- formatting ------------------------------------------------------------------------------

std::string quote_json(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

std::string yaml_scalar(const ScalarValue& v) {
  switch (v.kind) {
    case ScalarValue::Kind::Bool: return v.u ? "true" : "false";
    case ScalarValue::Kind::Int: return std::to_string(v.i);
    case ScalarValue::Kind::UInt: return std::to_string(v.u);
    case ScalarValue::Kind::Float32:
    case ScalarValue::Kind::Float64: {
      if (std::isnan(v.d)) return ".nan";
      if (std::isinf(v.d)) return v.d > 0 ? ".inf" : "-.inf";
      return v.kind == ScalarValue::Kind::Float32 ? format_float(static_cast<float>(v.d))
                                                  : format_double(v.d);
    }
    case ScalarValue::Kind::Char:
    case ScalarValue::Kind::String: return quote_json(v.s);
    case ScalarValue::Kind::Enum: return v.s;
    case ScalarValue::Kind::Unsupported: return v.s;
  }
  return v.s;
}

std::string json_scalar(const ScalarValue& v) {
  switch (v.kind) {
    case ScalarValue::Kind::Float32:
    case ScalarValue::Kind::Float64:
      if (!std::isfinite(v.d)) return "null";
      return yaml_scalar(v);
    case ScalarValue::Kind::Enum:
    case ScalarValue::Kind::Unsupported: return quote_json(v.s);
    default: return yaml_scalar(v);
  }
}

bool all_scalars(const SampleNode& node) {
  return std::all_of(node.children.begin(), node.children.end(),
                     [](const SampleNode& c) { return c.kind == SampleNode::Kind::Scalar; });
}

void yaml_entry(const std::string& key, const SampleNode& node, int indent, std::string& out);

// A list item: "- " then the item, whose first line shares the dash's line.
void yaml_item(const SampleNode& item, int indent, std::string& out) {
  const std::string pad(indent, ' ');
  if (item.kind == SampleNode::Kind::Scalar) {
    out += pad + "- " + yaml_scalar(item.value) + "\n";
    return;
  }
  if (item.kind != SampleNode::Kind::Struct && (item.children.empty() || all_scalars(item))) {
    std::string inline_list = "[";
    for (std::size_t i = 0; i < item.children.size(); ++i) {
      if (i) inline_list += ", ";
      inline_list += yaml_scalar(item.children[i].value);
    }
    out += pad + "- " + inline_list + "]\n";
    return;
  }
  std::string body;
  if (item.kind == SampleNode::Kind::Struct) {
    for (const auto& child : item.children) yaml_entry(child.name, child, indent + 2, body);
  } else {
    for (const auto& child : item.children) yaml_item(child, indent + 2, body);
  }
  if (body.empty()) {
    out += pad + "- {}\n";
    return;
  }
  out += pad + "- " + body.substr(static_cast<std::size_t>(indent) + 2);
}

void yaml_entry(const std::string& key, const SampleNode& node, int indent, std::string& out) {
  const std::string pad(indent, ' ');
  switch (node.kind) {
    case SampleNode::Kind::Scalar:
      out += pad + key + ": " + yaml_scalar(node.value) + "\n";
      return;
    case SampleNode::Kind::Struct:
      if (node.children.empty()) {
        out += pad + key + ": {}\n";
        return;
      }
      out += pad + key + ":\n";
      for (const auto& child : node.children) yaml_entry(child.name, child, indent + 2, out);
      return;
    case SampleNode::Kind::Array:
    case SampleNode::Kind::Sequence:
      if (node.children.empty() || all_scalars(node)) {
        out += pad + key + ": [";
        for (std::size_t i = 0; i < node.children.size(); ++i) {
          if (i) out += ", ";
          out += yaml_scalar(node.children[i].value);
        }
        out += "]\n";
        return;
      }
      out += pad + key + ":\n";
      for (const auto& child : node.children) yaml_item(child, indent + 2, out);
      return;
  }
}

void json_node(const SampleNode& node, std::string& out) {
  switch (node.kind) {
    case SampleNode::Kind::Scalar: out += json_scalar(node.value); return;
    case SampleNode::Kind::Struct:
      out += "{";
      for (std::size_t i = 0; i < node.children.size(); ++i) {
        if (i) out += ",";
        out += quote_json(node.children[i].name) + ":";
        json_node(node.children[i], out);
      }
      out += "}";
      return;
    case SampleNode::Kind::Array:
    case SampleNode::Kind::Sequence:
      out += "[";
      for (std::size_t i = 0; i < node.children.size(); ++i) {
        if (i) out += ",";
        json_node(node.children[i], out);
      }
      out += "]";
      return;
  }
}

}  // namespace

const SampleNode* SampleNode::member(const std::string& member_name) const {
  if (kind != Kind::Struct) return nullptr;
  for (const auto& child : children) {
    if (child.name == member_name) return &child;
  }
  return nullptr;
}

SampleNode read_sample(ftypes::DynamicData& data, const ftypes::DynamicType_ptr& type) {
  SampleNode root;
  const DynamicType_ptr resolved = resolve_alias(type);
  if (resolved && resolved->get_kind() == ftypes::TK_STRUCTURE) {
    read_struct(data, resolved, root);
  } else {
    root.value = unsupported("top-level type is not a struct");
  }
  return root;
}

std::optional<SampleNode> select_field(const SampleNode& root, const std::string& path,
                                       std::string& error) {
  const SampleNode* node = &root;
  std::size_t pos = 0;
  std::string walked;
  while (pos < path.size()) {
    if (path[pos] == '.') {
      ++pos;
      continue;
    }
    if (path[pos] == '[') {
      const auto close = path.find(']', pos);
      if (close == std::string::npos) {
        error = "missing ']' in field path '" + path + "'";
        return std::nullopt;
      }
      std::size_t index = 0;
      const auto text = path.substr(pos + 1, close - pos - 1);
      auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), index);
      if (ec != std::errc() || end != text.data() + text.size()) {
        error = "bad index '" + text + "' in field path '" + path + "'";
        return std::nullopt;
      }
      if ((node->kind != SampleNode::Kind::Array && node->kind != SampleNode::Kind::Sequence) ||
          index >= node->children.size()) {
        error = "'" + walked + "' has no item [" + text + "] (it has " +
                std::to_string(node->children.size()) + " items)";
        return std::nullopt;
      }
      node = &node->children[index];
      walked += "[" + text + "]";
      pos = close + 1;
      continue;
    }
    const auto end = path.find_first_of(".[", pos);
    const std::string name = path.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    const SampleNode* child = node->member(name);
    if (!child) {
      std::string known;
      if (node->kind == SampleNode::Kind::Struct) {
        for (const auto& c : node->children) known += (known.empty() ? "" : ", ") + c.name;
      }
      error = "no field '" + name + "'" + (walked.empty() ? "" : " in '" + walked + "'") +
              (known.empty() ? std::string() : " (fields: " + known + ")");
      return std::nullopt;
    }
    node = child;
    walked += (walked.empty() ? "" : ".") + name;
    pos = end == std::string::npos ? path.size() : end;
  }
  return *node;
}

std::string format_double(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), value);
  return std::string(buf, end);
}

std::string format_float(float value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), value);
  return std::string(buf, end);
}

std::string to_yaml(const SampleNode& node) {
  std::string out;
  switch (node.kind) {
    case SampleNode::Kind::Scalar: return yaml_scalar(node.value) + "\n";
    case SampleNode::Kind::Struct:
      for (const auto& child : node.children) yaml_entry(child.name, child, 0, out);
      return out;
    case SampleNode::Kind::Array:
    case SampleNode::Kind::Sequence:
      if (node.children.empty() || all_scalars(node)) {
        out = "[";
        for (std::size_t i = 0; i < node.children.size(); ++i) {
          if (i) out += ", ";
          out += yaml_scalar(node.children[i].value);
        }
        return out + "]\n";
      }
      for (const auto& child : node.children) yaml_item(child, 0, out);
      return out;
  }
  return out;
}

std::string to_json(const SampleNode& node) {
  std::string out;
  json_node(node, out);
  return out;
}

}  // namespace fedsim::tools
