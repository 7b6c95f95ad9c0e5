// A sample of any DDS type as a plain tree (structs, arrays, sequences, scalars), read from a
// Fast DDS DynamicData once so that printing, field selection and CSV flattening need no further
// DynamicData calls. Member order is the IDL declaration order.
#pragma once

#include "tools/topic/dynamic_types.hpp"

#include <fastrtps/types/DynamicData.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::tools {

struct ScalarValue {
  enum class Kind { Bool, Int, UInt, Float32, Float64, Char, String, Enum, Unsupported };
  Kind kind = Kind::Unsupported;
  std::int64_t i = 0;   // Int
  std::uint64_t u = 0;  // UInt, Bool (0/1), Enum (value)
  double d = 0.0;       // Float32 (widened), Float64
  std::string s;        // String, Char, Enum (name), Unsupported (what it is)
};

struct SampleNode {
  enum class Kind { Struct, Array, Sequence, Scalar };
  Kind kind = Kind::Scalar;
  std::string name;  // member name in the parent struct; "[i]" (or "[i][j]") for array items
  ScalarValue value;                // Kind::Scalar
  std::vector<SampleNode> children;  // Struct members, Array/Sequence items

  /// The child struct member of that name, or null.
  const SampleNode* member(const std::string& member_name) const;
};

/// Reads a whole sample of `type` (a struct) from `data`.
SampleNode read_sample(ftypes::DynamicData& data, const ftypes::DynamicType_ptr& type);

/// Selects a sub-tree by a path like "stamp.frame", "gear[2].compression_m" or
/// "velocity_ned_mps[0]"; nullopt and `error` set if no such field.
std::optional<SampleNode> select_field(const SampleNode& root, const std::string& path,
                                       std::string& error);

/// Shortest text that reads back as exactly the same value (std::to_chars), "nan", "inf", "-inf".
std::string format_double(double value);
std::string format_float(float value);

/// YAML-like, one member per line, nested structs indented, scalar arrays inline, enums by name.
std::string to_yaml(const SampleNode& node);
/// One line of JSON (enums as their name, NaN/inf as null).
std::string to_json(const SampleNode& node);

}  // namespace fedsim::tools
