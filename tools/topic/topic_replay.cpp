#include "tools/topic/topic_replay.hpp"

#include "tools/topic/recording_index.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/util/cli_checks.hpp"
#include "tools/topic/dynamic_reader.hpp"
#include "tools/topic/topic_tools.hpp"

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastrtps/types/DynamicDataFactory.h>
#include <fastrtps/types/DynamicType.h>
#include <fastrtps/types/DynamicTypeMember.h>
#include <fastrtps/types/MemberDescriptor.h>
#include <fastrtps/types/TypeDescriptor.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <ostream>
#include <set>
#include <sstream>
#include <string_view>

namespace fedsim::tools {

// ---- the type, compiled once ----------------------------------------------------------------

struct RowDecoder::Node {
  enum class Kind { Struct, Array, Sequence, Scalar, Unsupported };
  Kind kind = Kind::Unsupported;
  ftypes::TypeKind scalar = 0;  // TK_* of a Scalar
  ftypes::MemberId id = MEMBER_ID_INVALID;  // as a struct member
  std::string name;                                  // as a struct member
  bool key = false;                                  // an @key member
  std::vector<Node> members;                         // Struct
  std::vector<std::uint32_t> bounds;                 // Array dimensions
  std::vector<Node> element;                         // Array, Sequence: exactly one
  std::map<std::string, std::uint32_t> enumerators;  // Enum: name -> value
};

namespace {

using Node = RowDecoder::Node;
using ftypes::DynamicData;
using ftypes::DynamicType_ptr;
using ftypes::MemberId;

constexpr auto kOk = eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK;

DynamicType_ptr resolve_alias(DynamicType_ptr type) {
  for (int depth = 0; type && type->get_kind() == ftypes::TK_ALIAS && depth < 16; ++depth) {
    type = type->get_descriptor()->get_base_type();
  }
  return type;
}

/// Members in declaration order (the order CsvLayout flattens them in).
std::vector<ftypes::DynamicTypeMember*> ordered_members(const DynamicType_ptr& type) {
  std::map<MemberId, ftypes::DynamicTypeMember*> by_id;
  type->get_all_members(by_id);
  std::vector<ftypes::DynamicTypeMember*> members;
  for (auto& [id, member] : by_id) members.push_back(member);
  std::stable_sort(members.begin(), members.end(), [](const auto* a, const auto* b) {
    return a->get_descriptor()->get_index() < b->get_descriptor()->get_index();
  });
  return members;
}

bool is_scalar_kind(ftypes::TypeKind kind) {
  switch (kind) {
    case ftypes::TK_BOOLEAN: case ftypes::TK_BYTE: case ftypes::TK_INT16: case ftypes::TK_INT32:
    case ftypes::TK_INT64: case ftypes::TK_UINT16: case ftypes::TK_UINT32: case ftypes::TK_UINT64:
    case ftypes::TK_FLOAT32: case ftypes::TK_FLOAT64: case ftypes::TK_CHAR8:
    case ftypes::TK_STRING8: case ftypes::TK_ENUM:
      return true;
    default:
      return false;
  }
}

Node compile(const DynamicType_ptr& declared) {
  Node node;
  const DynamicType_ptr type = resolve_alias(declared);
  if (!type) return node;
  const ftypes::TypeKind kind = type->get_kind();
  if (kind == ftypes::TK_STRUCTURE) {
    node.kind = Node::Kind::Struct;
    for (auto* m : ordered_members(type)) {
      Node child = compile(m->get_descriptor()->get_type());
      child.id = m->get_id();
      child.name = m->get_name();
      child.key = m->get_descriptor()->annotation_get_key();
      node.members.push_back(std::move(child));
    }
  } else if (kind == ftypes::TK_ARRAY || kind == ftypes::TK_SEQUENCE) {
    node.kind = kind == ftypes::TK_ARRAY ? Node::Kind::Array : Node::Kind::Sequence;
    if (kind == ftypes::TK_ARRAY) {
      for (std::uint32_t d = 0; d < type->get_bounds_size(); ++d) node.bounds.push_back(type->get_bounds(d));
    }
    node.element.push_back(compile(type->get_descriptor()->get_element_type()));
  } else if (is_scalar_kind(kind)) {
    node.kind = Node::Kind::Scalar;
    node.scalar = kind;
    if (kind == ftypes::TK_ENUM) {
      std::map<MemberId, ftypes::DynamicTypeMember*> literals;
      type->get_all_members(literals);
      for (auto& [id, m] : literals) node.enumerators[m->get_name()] = id;
    }
  }
  return node;
}

std::uint32_t array_total(const Node& node) {
  std::uint32_t total = 1;
  for (auto b : node.bounds) total *= b;
  return total;
}

/// Row-major position of the flat index (last index fastest), as the recorder numbers items.
std::vector<std::uint32_t> array_position(const Node& node, std::uint32_t flat) {
  std::vector<std::uint32_t> position(node.bounds.size());
  for (std::size_t d = node.bounds.size(); d-- > 0;) {
    position[d] = flat % node.bounds[d];
    flat /= node.bounds[d];
  }
  return position;
}

/// CSV cells of a node: what CsvLayout flattens it into.
std::size_t leaf_count(const Node& node) {
  switch (node.kind) {
    case Node::Kind::Struct: {
      std::size_t n = 0;
      for (const auto& m : node.members) n += leaf_count(m);
      return n;
    }
    case Node::Kind::Array: return array_total(node) * leaf_count(node.element.front());
    default: return 1;
  }
}

// ---- scalar text -> value ---------------------------------------------------------------------

template <class T>
bool read_number(std::string_view s, T& out) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return !s.empty() && ec == std::errc() && ptr == end;
}

/// An integer of type T written as the recorder writes it (decimal, no sign for unsigned).
template <class T>
std::string read_integer(std::string_view s, T& out) {
  using Wide = std::conditional_t<std::is_signed_v<T>, std::int64_t, std::uint64_t>;
  Wide wide = 0;
  if (read_number(s, wide) && wide >= std::numeric_limits<T>::min() &&
      wide <= std::numeric_limits<T>::max()) {
    out = static_cast<T>(wide);
    return {};
  }
  return "not an integer in [" + std::to_string(std::numeric_limits<T>::min()) + ", " +
         std::to_string(std::numeric_limits<T>::max()) + "]: '" + std::string(s) + "'";
}

std::string set_failed(const ftypes::ReturnCode_t& rc) {
  return rc == kOk ? std::string() : "the DynamicData refused the value";
}

/// Reads `text` as a value of the scalar node and, with `data`, sets member `id` to it. Returns
/// the problem, empty if none. Floating-point text is read with from_chars: the shortest text
/// the recorder wrote reads back as exactly the same value ("nan", "inf", "-inf" included).
std::string set_scalar(const Node& node, std::string_view text, DynamicData* data, MemberId id) {
  switch (node.scalar) {
    case ftypes::TK_BOOLEAN: {
      if (text != "0" && text != "1") return "not a boolean (1 or 0): '" + std::string(text) + "'";
      return data ? set_failed(data->set_bool_value(text == "1", id)) : std::string();
    }
    case ftypes::TK_FLOAT64: {
      double v = 0;
      if (!read_number(text, v)) return "not a number: '" + std::string(text) + "'";
      return data ? set_failed(data->set_float64_value(v, id)) : std::string();
    }
    case ftypes::TK_FLOAT32: {
      float v = 0;
      if (!read_number(text, v)) return "not a 32-bit number: '" + std::string(text) + "'";
      return data ? set_failed(data->set_float32_value(v, id)) : std::string();
    }
    case ftypes::TK_CHAR8: {
      if (text.size() > 1) return "more than one character: '" + std::string(text) + "'";
      return data ? set_failed(data->set_char8_value(text.empty() ? '\0' : text[0], id)) : std::string();
    }
    case ftypes::TK_STRING8:
      return data ? set_failed(data->set_string_value(std::string(text), id)) : std::string();
    case ftypes::TK_ENUM: {
      std::uint32_t v = 0;
      std::string problem = read_integer(text, v);
      if (problem.empty() && std::none_of(node.enumerators.begin(), node.enumerators.end(),
                                          [v](const auto& e) { return e.second == v; })) {
        problem = "no enumerator has the value " + std::string(text);
      }
      if (!problem.empty() || !data) return problem;
      return set_failed(data->set_enum_value(v, id));
    }
    default: break;
  }
  // Integers: read in their own width so that an out-of-range cell is an error, not a wrap.
  auto integer = [&](auto value, auto setter) -> std::string {
    std::string problem = read_integer(text, value);
    if (!problem.empty() || !data) return problem;
    return set_failed(setter(value));
  };
  switch (node.scalar) {
    case ftypes::TK_BYTE: return integer(std::uint8_t{}, [&](std::uint8_t v) { return data->set_byte_value(v, id); });
    case ftypes::TK_INT16: return integer(std::int16_t{}, [&](std::int16_t v) { return data->set_int16_value(v, id); });
    case ftypes::TK_INT32: return integer(std::int32_t{}, [&](std::int32_t v) { return data->set_int32_value(v, id); });
    case ftypes::TK_INT64: return integer(std::int64_t{}, [&](std::int64_t v) { return data->set_int64_value(v, id); });
    case ftypes::TK_UINT16: return integer(std::uint16_t{}, [&](std::uint16_t v) { return data->set_uint16_value(v, id); });
    case ftypes::TK_UINT32: return integer(std::uint32_t{}, [&](std::uint32_t v) { return data->set_uint32_value(v, id); });
    case ftypes::TK_UINT64: return integer(std::uint64_t{}, [&](std::uint64_t v) { return data->set_uint64_value(v, id); });
    default: return "unsupported member type";
  }
}

// ---- sequence cells: one JSON array (sample_tree's to_json) -----------------------------------

struct Json {
  enum class Kind { Null, Bool, Number, String, Array, Object };
  Kind kind = Kind::Null;
  std::string text;  // Number (as written, read later in the member's own width), String
  bool flag = false; // Bool
  std::vector<Json> items;                            // Array
  std::vector<std::pair<std::string, Json>> members;  // Object
};

class JsonParser {
 public:
  explicit JsonParser(std::string_view text) : s_(text) {}

  Json parse() {
    Json value = parse_value();
    skip_blanks();
    if (i_ != s_.size()) fail("text after the JSON value");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("bad JSON array cell (" + what + " at character " +
                                std::to_string(i_ + 1) + ")");
  }
  void skip_blanks() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
  }
  bool take(char c) {
    skip_blanks();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  bool take_word(std::string_view word) {
    if (s_.substr(i_, word.size()) != word) return false;
    i_ += word.size();
    return true;
  }

  Json parse_value() {
    skip_blanks();
    if (i_ >= s_.size()) fail("unexpected end");
    Json v;
    const char c = s_[i_];
    if (c == '[') {
      v.kind = Json::Kind::Array;
      ++i_;
      if (take(']')) return v;
      do v.items.push_back(parse_value()); while (take(','));
      if (!take(']')) fail("',' or ']' expected");
    } else if (c == '{') {
      v.kind = Json::Kind::Object;
      ++i_;
      if (take('}')) return v;
      do {
        skip_blanks();
        std::string key = parse_string();
        if (!take(':')) fail("':' expected");
        v.members.emplace_back(std::move(key), parse_value());
      } while (take(','));
      if (!take('}')) fail("',' or '}' expected");
    } else if (c == '"') {
      v.kind = Json::Kind::String;
      v.text = parse_string();
    } else if (take_word("true")) {
      v.kind = Json::Kind::Bool;
      v.flag = true;
    } else if (take_word("false")) {
      v.kind = Json::Kind::Bool;
    } else if (take_word("null")) {
      v.kind = Json::Kind::Null;
    } else {
      v.kind = Json::Kind::Number;
      const std::size_t start = i_;
      while (i_ < s_.size() && std::string_view("+-.0123456789eE").find(s_[i_]) != std::string_view::npos) ++i_;
      if (i_ == start) fail("unexpected character");
      v.text = std::string(s_.substr(start, i_ - start));
    }
    return v;
  }

  std::string parse_string() {
    if (i_ >= s_.size() || s_[i_] != '"') fail("'\"' expected");
    ++i_;
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= s_.size()) break;
      c = s_[i_++];
      switch (c) {
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': out += unicode_escape(); break;
        default: out += c;  // '"', '\\', '/'
      }
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return out;
  }

  /// \uXXXX as UTF-8 (the recorder only escapes control characters this way).
  std::string unicode_escape() {
    unsigned code = 0;
    if (i_ + 4 > s_.size() || std::from_chars(s_.data() + i_, s_.data() + i_ + 4, code, 16).ptr !=
                                  s_.data() + i_ + 4) {
      fail("bad \\u escape");
    }
    i_ += 4;
    std::string out;
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
    return out;
  }

  std::string_view s_;
  std::size_t i_ = 0;
};

/// The scalar text a JSON item stands for, in the cell format set_scalar reads. JSON has no
/// NaN or infinity: to_json wrote them as null, read back as NaN (the one lossy case).
std::string json_scalar_text(const Node& node, const Json& j) {
  const bool floating = node.scalar == ftypes::TK_FLOAT32 || node.scalar == ftypes::TK_FLOAT64;
  switch (j.kind) {
    case Json::Kind::Null:
      if (floating) return "nan";
      break;
    case Json::Kind::Bool:
      if (node.scalar == ftypes::TK_BOOLEAN) return j.flag ? "1" : "0";
      break;
    case Json::Kind::Number:
      if (node.scalar != ftypes::TK_STRING8 && node.scalar != ftypes::TK_CHAR8 &&
          node.scalar != ftypes::TK_BOOLEAN) {
        return j.text;
      }
      break;
    case Json::Kind::String:
      if (node.scalar == ftypes::TK_STRING8 || node.scalar == ftypes::TK_CHAR8) return j.text;
      if (node.scalar == ftypes::TK_ENUM) {
        const auto it = node.enumerators.find(j.text);
        if (it != node.enumerators.end()) return std::to_string(it->second);
        throw std::invalid_argument("no enumerator '" + j.text + "'");
      }
      break;
    default: break;
  }
  throw std::invalid_argument("a JSON item of the wrong kind for its member");
}

/// Borrows a nested value of `parent` and gives it back however the scope is left (a CellError
/// thrown mid-row must not leave the reused DynamicData loaned).
class Loan {
 public:
  Loan(DynamicData* parent, MemberId id) : parent_(parent) {
    if (parent_) {
      child_ = parent_->loan_value(id);
      if (!child_) throw std::invalid_argument("cannot borrow a nested member of the DynamicData");
    }
  }
  ~Loan() {
    if (child_) parent_->return_loaned_value(child_);
  }
  Loan(const Loan&) = delete;
  Loan& operator=(const Loan&) = delete;
  DynamicData* get() const { return child_; }

 private:
  DynamicData* parent_;
  DynamicData* child_ = nullptr;
};

void set_json(const Node& node, const Json& j, DynamicData* data, MemberId id);

/// Empties the sequence and appends one item per JSON item.
void fill_sequence(const Node& node, const Json& j, DynamicData* seq) {
  if (j.kind != Json::Kind::Array) throw std::invalid_argument("a JSON array expected");
  if (seq) seq->clear_data();
  for (const Json& item : j.items) {
    MemberId item_id = MEMBER_ID_INVALID;
    if (seq && seq->insert_sequence_data(item_id) != kOk) {
      throw std::invalid_argument("more items than the sequence's bound");
    }
    set_json(node.element.front(), item, seq, item_id);
  }
}

void set_json(const Node& node, const Json& j, DynamicData* data, MemberId id) {
  switch (node.kind) {
    case Node::Kind::Scalar: {
      const std::string problem = set_scalar(node, json_scalar_text(node, j), data, id);
      if (!problem.empty()) throw std::invalid_argument(problem);
      return;
    }
    case Node::Kind::Struct: {
      if (j.kind != Json::Kind::Object) throw std::invalid_argument("a JSON object expected");
      Loan nested(data, id);
      for (const Node& m : node.members) {
        const auto it = std::find_if(j.members.begin(), j.members.end(),
                                     [&](const auto& p) { return p.first == m.name; });
        if (it == j.members.end()) throw std::invalid_argument("no member '" + m.name + "'");
        set_json(m, it->second, nested.get(), m.id);
      }
      return;
    }
    case Node::Kind::Array: {
      const std::uint32_t total = array_total(node);
      if (j.kind != Json::Kind::Array || j.items.size() != total) {
        throw std::invalid_argument("a JSON array of " + std::to_string(total) + " items expected");
      }
      Loan nested(data, id);
      for (std::uint32_t flat = 0; flat < total; ++flat) {
        const MemberId item = nested.get() ? nested.get()->get_array_index(array_position(node, flat)) : 0;
        set_json(node.element.front(), j.items[flat], nested.get(), item);
      }
      return;
    }
    case Node::Kind::Sequence: {
      Loan nested(data, id);
      fill_sequence(node, j, nested.get());
      return;
    }
    case Node::Kind::Unsupported: return;
  }
}

// ---- a row's cells -> the nodes -----------------------------------------------------------------

/// The cells of a row in field order (IDL order), with the CSV column of each for messages.
struct Cursor {
  const std::vector<std::string>& cells;
  const std::vector<std::size_t>& columns;  // field -> CSV column
  std::size_t field = 0;

  std::size_t column() const { return columns[field]; }
  const std::string& take() { return cells[columns[field++]]; }
};

void fill(const Node& node, DynamicData* data, MemberId id, Cursor& cursor);

void fill_members(const Node& node, DynamicData* data, Cursor& cursor) {
  for (const Node& m : node.members) fill(m, data, m.id, cursor);
}

void fill(const Node& node, DynamicData* data, MemberId id, Cursor& cursor) {
  switch (node.kind) {
    case Node::Kind::Scalar: {
      const std::size_t column = cursor.column();
      const std::string problem = set_scalar(node, cursor.take(), data, id);
      if (!problem.empty()) throw CellError(column, problem);
      return;
    }
    case Node::Kind::Struct: {
      Loan nested(data, id);
      fill_members(node, nested.get(), cursor);
      return;
    }
    case Node::Kind::Array: {
      Loan nested(data, id);
      for (std::uint32_t flat = 0, total = array_total(node); flat < total; ++flat) {
        const MemberId item = nested.get() ? nested.get()->get_array_index(array_position(node, flat)) : 0;
        fill(node.element.front(), nested.get(), item, cursor);
      }
      return;
    }
    case Node::Kind::Sequence: {
      const std::size_t column = cursor.column();
      try {
        const Json j = JsonParser(cursor.take()).parse();
        Loan nested(data, id);
        fill_sequence(node, j, nested.get());
      } catch (const std::invalid_argument& e) {
        throw CellError(column, e.what());
      }
      return;
    }
    case Node::Kind::Unsupported:
      cursor.take();  // a kind the recorder wrote as a placeholder: the member keeps its default
      return;
  }
}

/// Reads the recorder's CSV: RFC 4180 fields, a quoted field may hold commas, doubled quotes and
/// line breaks (so one record can span lines); nothing is trimmed, '#' is ordinary text.
/// (common/csv's reader would do, but it trims and lives in a library the topic tools do not link.)
class RecordReader {
 public:
  explicit RecordReader(const std::filesystem::path& file) : file_(file), in_(file) {
    if (!in_) throw ReplayError(file.string() + ": cannot open");
  }
  /// Goes on reading at the record starting `offset` bytes into the file, row `row` (0 = the
  /// first after the header), as the file's index says; throws if no line starts there.
  void skip_to(std::uint64_t offset, std::uint64_t row) {
    char before = 0;
    in_.seekg(static_cast<std::streamoff>(offset) - 1);
    if (!in_.get(before) || before != '\n') {
      throw ReplayError(file_.string() + ": its index does not match it (no line starts at byte " +
                        std::to_string(offset) + "); remove " + index_file_for(file_).string());
    }
    line_ = static_cast<int>(row) + 1;  // the header is line 1
  }
  /// The next record and the line it starts on; false at the end of the file.
  bool next(std::vector<std::string>& fields, int& first_line) {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      unterminated_ = in_.eof();  // the file ends without a line break here
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty()) continue;
      first_line = line_;
      std::string record = line;
      while (!split(record, fields)) {
        if (!std::getline(in_, line)) {
          throw ReplayError(file_.string() + ":" + std::to_string(first_line) + ": unterminated quote");
        }
        ++line_;
        record += '\n' + line;
      }
      return true;
    }
    return false;
  }
  /// True if the last record read ends the file without a line break (a line being written).
  bool unterminated() const { return unterminated_; }
  /// Splits a whole record; false if a quoted field is still open at its end.
  static bool split(const std::string& text, std::vector<std::string>& fields) {
    fields.assign(1, std::string());
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
      const char c = text[i];
      if (quoted && c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = !quoted;
      } else if (c == ',' && !quoted) {
        fields.emplace_back();
      } else {
        fields.back() += c;
      }
    }
    return !quoted;
  }

 private:
  std::filesystem::path file_;
  std::ifstream in_;
  int line_ = 0;
  bool unterminated_ = false;
};

/// A header that differs from this build's layout was written by another fedsim version: its
/// cells would land in the wrong members.
void check_header(const std::filesystem::path& file, const runtime::TopicInfo& topic,
                  const std::vector<std::string>& have, const std::vector<std::string>& want) {
  for (std::size_t i = 0; i < std::max(have.size(), want.size()); ++i) {
    if (i < have.size() && i < want.size() && have[i] == want[i]) continue;
    const std::string in_file = i < have.size() ? "'" + have[i] + "'" : "nothing";
    const std::string expected = i < want.size() ? "'" + want[i] + "'" : "nothing";
    throw ReplayError(file.string() + ": the header differs from this fedsim's layout of " +
                      topic.type_name + " at column " + std::to_string(i + 1) + ": " + in_file +
                      " in the file, " + expected + " expected (recorded by another fedsim version?)");
  }
}

std::string cell_error_text(const std::filesystem::path& file, int line, const CsvLayout& layout,
                            const CellError& e) {
  const auto& columns = layout.columns();
  const std::string name = e.column() < columns.size() ? columns[e.column()] : "?";
  return file.string() + ":" + std::to_string(line) + ":" + std::to_string(e.column() + 1) +
         ": column '" + name + "': " + e.what();
}

}  // namespace

// ---- RowDecoder --------------------------------------------------------------------------------

RowDecoder::RowDecoder(const ftypes::DynamicType_ptr& type)
    : type_(type), layout_(type), root_(std::make_unique<Node>(compile(type))) {
  if (root_->kind != Node::Kind::Struct) throw ReplayError("a topic type must be a struct");
  // Field i (IDL order) -> CSV column: the time column comes first; a top-level sim_time_s
  // field was moved there (csv_layout.hpp), any other field follows it in order.
  const std::vector<std::string> fields = flattened_field_names(type);
  std::optional<std::size_t> moved;
  const bool stamped = std::find(fields.begin(), fields.end(), "stamp.sim_time_s") != fields.end();
  const auto top = std::find(fields.begin(), fields.end(), "sim_time_s");
  if (!stamped && top != fields.end()) moved = static_cast<std::size_t>(top - fields.begin());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (moved && i == *moved) field_columns_.push_back(0);
    else field_columns_.push_back(moved && i > *moved ? i : i + 1);
  }
  if (leaf_count(*root_) != fields.size() ||
      layout_.columns().size() != fields.size() + (moved ? 0 : 1)) {
    throw ReplayError("cannot map the CSV layout of " + type->get_name() + " onto its members");
  }
  std::size_t field = 0;
  for (const Node& m : root_->members) {
    if (m.key && m.kind == Node::Kind::Scalar) key_columns_.push_back(field_columns_[field]);
    field += leaf_count(m);
  }
}

RowDecoder::~RowDecoder() = default;

void RowDecoder::walk(const std::vector<std::string>& cells, ftypes::DynamicData* out) const {
  if (cells.size() != layout_.columns().size()) {
    throw CellError(std::min(cells.size(), layout_.columns().size()),
                    std::to_string(cells.size()) + " cells, the header has " +
                        std::to_string(layout_.columns().size()));
  }
  Cursor cursor{cells, field_columns_};
  fill_members(*root_, out, cursor);
}

void RowDecoder::decode(const std::vector<std::string>& cells, ftypes::DynamicData& out) const {
  walk(cells, &out);
}

void RowDecoder::validate(const std::vector<std::string>& cells) const { walk(cells, nullptr); }

std::vector<std::string> split_recorded_row(const std::string& line) {
  std::vector<std::string> fields;
  if (!RecordReader::split(line, fields)) throw std::invalid_argument("unterminated quote");
  return fields;
}

// ---- Recording ---------------------------------------------------------------------------------

RecordedTopic Recording::load_topic(const runtime::TopicInfo& topic,
                                    const std::filesystem::path& file, double from_s) {
  const DynamicType_ptr type = dynamic_type_by_name(topic.type_name);
  if (!type) throw ReplayError("no type object for " + topic.type_name + " in this build");
  RecordedTopic out;
  out.info = &topic;
  out.file = file;
  out.decoder = std::make_shared<const RowDecoder>(type);
  const CsvLayout& layout = out.decoder->layout();
  RecordReader reader(file);
  std::vector<std::string> have;
  int line = 0;
  if (!reader.next(have, line)) throw ReplayError(file.string() + ": empty (no header line)");
  check_header(file, topic, have, layout.columns());
  // A later start skips the rows its index says are earlier, unread (an hour-long recording
  // replayed from minute 50 parses ten minutes).
  if (from_s > 0.0) {
    if (const auto index = RecordingIndex::read(index_file_for(file))) {
      if (const auto start = index->start_for(from_s)) reader.skip_to(start->byte_offset, start->row);
    }
  }
  // A recorder's file (it has an index) may be read while it is being written: its last line
  // can be half there. That line is left for the next read, not refused.
  const bool recorder_file = std::filesystem::exists(index_file_for(file));
  std::map<std::string, std::uint32_t> instances;
  RecordedRow r;
  while (reader.next(r.cells, r.line)) {
    if (recorder_file && reader.unterminated()) break;
    try {
      out.decoder->validate(r.cells);
      if (!read_number(std::string_view(r.cells[0]), r.time_s) || !std::isfinite(r.time_s)) {
        throw CellError(0, "not a finite time: '" + r.cells[0] + "'");
      }
    } catch (const CellError& e) {
      throw ReplayError(cell_error_text(file, r.line, layout, e));
    }
    std::string key;
    for (std::size_t c : out.decoder->key_columns()) key += r.cells[c] + '\x1f';
    r.instance = instances.emplace(key, static_cast<std::uint32_t>(instances.size())).first->second;
    out.rows.push_back(std::move(r));
    r = RecordedRow();
  }
  out.instances = static_cast<std::uint32_t>(instances.size());
  return out;
}

Recording Recording::load(const std::filesystem::path& dir, const std::vector<std::string>& topics,
                          double from_s) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw RecordingNotFound("no recording folder '" + dir.string() + "'");
  }
  for (const auto& name : topics) {
    if (!runtime::topics::find(name)) throw ReplayError("'" + name + "' is not a fedsim topic");
    if (!std::filesystem::exists(dir / csv_file_name(name))) {
      throw ReplayError((dir / csv_file_name(name)).string() + ": no recording of " + name);
    }
  }
  Recording recording;
  recording.dir_ = dir;
  std::set<std::string> known_files;
  for (const runtime::TopicInfo* info : runtime::topics::all()) {
    const std::string file_name = csv_file_name(info->name);
    known_files.insert(file_name);
    const auto file = dir / file_name;
    if (!std::filesystem::exists(file)) continue;
    const bool named = std::find(topics.begin(), topics.end(), info->name) != topics.end();
    if (!topics.empty() && !named) continue;
    if (topics.empty() && runtime::topics::is_backbone(info->name)) {
      recording.notes_.push_back(file_name + ": backbone topic, replayed only when named (--topics)");
      continue;
    }
    const DynamicType_ptr type = dynamic_type_by_name(info->type_name);
    if (type && !CsvLayout(type).has_sim_time()) {
      recording.notes_.push_back(file_name + ": recorded with reception time only, no simulation "
                                 "time to replay it by");
      continue;
    }
    recording.topics_.push_back(load_topic(*info, file, from_s));
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".csv" && !known_files.count(name)) {
      recording.notes_.push_back(name + ": not a fedsim topic");
    }
  }
  if (recording.topics_.empty()) {
    std::string why = "'" + dir.string() + "' holds no recording of a fedsim topic to replay";
    for (const auto& note : recording.notes_) why += "; " + note;
    throw RecordingNotFound(why);
  }
  return recording;
}

std::size_t Recording::samples() const {
  std::size_t n = 0;
  for (const auto& t : topics_) n += t.rows.size();
  return n;
}

double Recording::start_s() const {
  std::optional<double> start;
  for (const auto& t : topics_) {
    for (const auto& r : t.rows) start = std::min(start.value_or(r.time_s), r.time_s);
  }
  return start.value_or(0.0);
}

double Recording::end_s() const {
  std::optional<double> end;
  for (const auto& t : topics_) {
    for (const auto& r : t.rows) end = std::max(end.value_or(r.time_s), r.time_s);
  }
  return end.value_or(0.0);
}

// ---- Replayer ----------------------------------------------------------------------------------

struct Replayer::Writer {
  std::shared_ptr<runtime::DdsParticipant> dds;
  const RecordedTopic* topic = nullptr;
  fdds::DataWriter* writer = nullptr;
  DynamicData* scratch = nullptr;  // reused for every sample of the topic (replay thread only)
  bool state = false;              // catalogue QoS "state": jumps on a seek

  Writer(std::shared_ptr<runtime::DdsParticipant> participant, const RecordedTopic& recorded)
      : dds(std::move(participant)), topic(&recorded) {
    const runtime::TopicInfo& info = *recorded.info;
    fdds::TypeSupport support = dynamic_type_support(recorded.decoder->type());
    auto* dds_topic = dds->topic_for(info.name, support);
    // As DynamicReader: a compiled type support registered first under the name would be used.
    if (dds->participant()->find_type(support.get_type_name()).get() != support.get()) {
      throw runtime::DdsError("participant '" + dds->options().name + "' already has a compiled "
                              "type support for " + info.type_name + ": the replay needs a "
                              "participant of its own");
    }
    writer = dds->publisher()->create_datawriter_with_profile(dds_topic, info.default_qos, nullptr);
    if (!writer) {
      throw runtime::DdsError("cannot create a writer for " + info.name + " with QoS profile '" +
                              info.default_qos + "'");
    }
    scratch = ftypes::DynamicDataFactory::get_instance()->create_data(recorded.decoder->type());
    state = info.default_qos == runtime::qos::kState;
  }
  ~Writer() {
    if (writer) dds->publisher()->delete_datawriter(writer);
    if (scratch) ftypes::DynamicDataFactory::get_instance()->delete_data(scratch);
  }
  int matched() const {
    fdds::PublicationMatchedStatus status;
    writer->get_publication_matched_status(status);
    return status.current_count;
  }
  void write(const RecordedRow& row) {
    topic->decoder->decode(row.cells, *scratch);
    if (!writer->write(scratch)) {
      throw std::runtime_error("the writer of " + topic->info->name + " refused a sample");
    }
  }
};

Replayer::Replayer(std::shared_ptr<runtime::DdsParticipant> dds, Recording recording,
                   ReplayOptions options)
    : dds_(std::move(dds)), recording_(std::move(recording)), options_(options) {
  if (!std::isfinite(options_.speed) || options_.speed < 0 || options_.speed > 100) {
    throw std::invalid_argument("replay speed must be a finite number within [0, 100]");
  }
  if (!std::isfinite(options_.from_s) || options_.from_s < 0) {
    throw std::invalid_argument("replay start time must be a finite number >= 0");
  }
  for (const auto& topic : recording_.topics()) writers_.push_back(std::make_unique<Writer>(dds_, topic));
  latest_row_.resize(writers_.size());
  position_s_ = options_.from_s;
  build_timeline();
}

Replayer::~Replayer() { stop(); }

/// Merges the topics by time, keeping each topic's file order (a reset in the recording makes
/// time go back: its samples must still go out in the order they were recorded).
void Replayer::build_timeline() {
  const auto& topics = recording_.topics();
  std::vector<std::size_t> next(topics.size(), 0);
  timeline_.reserve(recording_.samples());
  for (;;) {
    std::optional<std::size_t> best;
    for (std::size_t t = 0; t < topics.size(); ++t) {
      if (next[t] >= topics[t].rows.size()) continue;
      if (!best || topics[t].rows[next[t]].time_s < topics[*best].rows[next[*best]].time_s) best = t;
    }
    if (!best) return;
    const auto row = static_cast<std::uint32_t>(next[*best]++);
    timeline_.push_back({topics[*best].rows[row].time_s, static_cast<std::uint32_t>(*best), row});
  }
}

bool Replayer::wait_for_readers(std::chrono::milliseconds timeout) const {
  const auto until = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (std::all_of(writers_.begin(), writers_.end(), [](const auto& w) { return w->matched() > 0; })) {
      return true;
    }
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

void Replayer::start() {
  std::lock_guard lock(mutex_);
  if (started_) return;
  started_ = true;
  if (!pending_seek_) pending_seek_ = options_.from_s;  // finds (and anchors at) the first sample
  thread_ = std::thread([this] { run(); });
}

void Replayer::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void Replayer::pause() {
  std::unique_lock lock(mutex_);
  paused_ = true;
  changed_.notify_all();
  changed_.wait(lock, [this] { return !publishing_; });  // the sample in flight, if any, is out
}

void Replayer::resume() {
  {
    std::lock_guard lock(mutex_);
    if (!paused_) return;
    paused_ = false;
    re_anchor(position_s_);  // the pause does not count as replayed time
  }
  changed_.notify_all();
}

bool Replayer::paused() const {
  std::lock_guard lock(mutex_);
  return paused_;
}

void Replayer::seek(double sim_time_s) {
  {
    std::lock_guard lock(mutex_);
    pending_seek_ = sim_time_s;
    position_s_ = sim_time_s;
  }
  changed_.notify_all();
}

double Replayer::position_s() const {
  std::lock_guard lock(mutex_);
  return position_s_;
}

bool Replayer::finished() const {
  std::lock_guard lock(mutex_);
  return finished_;
}

std::optional<std::map<std::string, double>> Replayer::latest_fields(const std::string& topic) const {
  const RecordedTopic* recorded = nullptr;
  std::optional<std::uint32_t> row;
  {
    std::lock_guard lock(mutex_);
    for (std::size_t t = 0; t < writers_.size(); ++t) {
      if (writers_[t]->topic->info->name == topic) {
        recorded = writers_[t]->topic;
        row = latest_row_[t];
      }
    }
  }
  if (!recorded || !row) return std::nullopt;
  // Numbers, booleans and enums read back as numbers; strings and sequences do not.
  const auto& columns = recorded->decoder->layout().columns();
  const auto& cells = recorded->rows[*row].cells;
  std::map<std::string, double> fields;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    double value = 0;
    if (read_number(std::string_view(cells[c]), value)) fields[columns[c]] = value;
  }
  return fields;
}

void Replayer::re_anchor(double sim_time_s) {
  anchor_wall_ = std::chrono::steady_clock::now();
  anchor_sim_ = sim_time_s;
}

void Replayer::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    if (pending_seek_) {
      const double target = *pending_seek_;
      pending_seek_.reset();
      apply_seek(lock, target);
    } else if (paused_) {
      changed_.wait(lock);
    } else if (next_ >= timeline_.size()) {
      if (options_.loop && !timeline_.empty()) {
        next_ = 0;
        loops_.fetch_add(1);
        re_anchor(timeline_.front().time_s);
        continue;
      }
      finished_ = true;
      changed_.wait(lock);  // until a seek or stop
    } else if (wait_until_due(lock)) {
      const Entry entry = timeline_[next_++];
      publish(lock, entry);
    }
  }
}

/// True when the next sample is due; false after waiting (the state may have changed meanwhile:
/// the caller looks again).
bool Replayer::wait_until_due(std::unique_lock<std::mutex>& lock) {
  if (options_.speed == 0) return true;
  const double t = timeline_[next_].time_s;
  if (t < anchor_sim_) re_anchor(t);  // time went back (a reset in the recording)
  const auto due = anchor_wall_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>((t - anchor_sim_) / options_.speed));
  if (std::chrono::steady_clock::now() >= due) return true;
  changed_.wait_until(lock, due);
  return false;
}

void Replayer::apply_seek(std::unique_lock<std::mutex>& lock, double target) {
  finished_ = false;
  const auto first = std::find_if(timeline_.begin(), timeline_.end(),
                                  [target](const Entry& e) { return e.time_s >= target; });
  next_ = static_cast<std::size_t>(first - timeline_.begin());
  // The state topics' latest sample of each instance before that point, oldest first.
  std::vector<std::vector<bool>> seen(writers_.size());
  std::size_t missing = 0;
  for (std::size_t t = 0; t < writers_.size(); ++t) {
    if (!writers_[t]->state) continue;
    seen[t].assign(writers_[t]->topic->instances, false);
    missing += writers_[t]->topic->instances;
  }
  std::vector<Entry> jump;
  for (std::size_t i = next_; i-- > 0 && missing > 0;) {
    const Entry& e = timeline_[i];
    if (!writers_[e.topic]->state) continue;
    const std::uint32_t instance = recording_.topics()[e.topic].rows[e.row].instance;
    if (seen[e.topic][instance]) continue;
    seen[e.topic][instance] = true;
    --missing;
    jump.push_back(e);
  }
  std::reverse(jump.begin(), jump.end());
  for (const Entry& e : jump) publish(lock, e);
  if (!pending_seek_) position_s_ = target;
  re_anchor(next_ < timeline_.size() ? timeline_[next_].time_s : target);
}

void Replayer::publish(std::unique_lock<std::mutex>& lock, const Entry& entry) {
  publishing_ = true;
  lock.unlock();  // pause(), seek() and the getters never wait for the middleware
  std::string error;
  try {
    writers_[entry.topic]->write(recording_.topics()[entry.topic].rows[entry.row]);
  } catch (const std::exception& e) {
    error = e.what();
  }
  lock.lock();
  publishing_ = false;
  if (error.empty()) {
    position_s_ = entry.time_s;
    latest_row_[entry.topic] = entry.row;
    published_.fetch_add(1);
  } else {
    error_ = error;
    stopping_ = true;
    finished_ = true;
  }
  changed_.notify_all();
}

std::string Replayer::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

// ---- fedsim replay -----------------------------------------------------------------------------

namespace {

std::vector<std::string> trimmed_topics(const std::vector<std::string>& topics) {
  std::vector<std::string> out;
  for (auto topic : topics) {  // trimmed, each once
    topic.erase(0, topic.find_first_not_of(" \t"));
    topic.erase(topic.find_last_not_of(" \t") + 1);
    if (!topic.empty() && std::find(out.begin(), out.end(), topic) == out.end()) out.push_back(topic);
  }
  return out;
}

std::string seconds(double s) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << s;
  return text.str();
}

void print_plan(const Recording& recording, std::ostream& out) {
  for (const auto& topic : recording.topics()) {
    out << "replaying " << topic.info->name << ": " << topic.rows.size() << " samples, QoS '"
        << topic.info->default_qos << "' <- " << topic.file.string() << "\n";
  }
  for (const auto& note : recording.notes()) out << "not replayed: " << note << "\n";
  out.flush();
}

/// Publishes until the end (or Ctrl-C), printing progress; returns the reason it stopped.
std::string replay_until_done(Replayer& replayer, const ReplayCliOptions& options,
                              std::ostream& out) {
  const double total = replayer.recording().end_s();
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(options.progress_period_s));
  auto next_progress = std::chrono::steady_clock::now() + period;
  for (;;) {
    if (runtime::wait_for_shutdown(std::chrono::milliseconds(50))) return "interrupted";
    if (replayer.finished()) return replayer.error().empty() ? "end of the recording" : "error";
    if (options.progress_period_s > 0 && std::chrono::steady_clock::now() >= next_progress) {
      next_progress += period;
      out << "replayed " << seconds(replayer.position_s()) << " / " << seconds(total) << " s, "
          << replayer.published() << " samples\n";
      out.flush();
    }
  }
}

}  // namespace

int run_replay(const ReplayCliOptions& options, std::ostream& out, std::ostream& err) {
  std::optional<Recording> recording;
  try {
    // --loop comes back to the start of the recording: it needs every row; otherwise the rows
    // well before --from-s are left unread.
    recording = Recording::load(options.dir, trimmed_topics(options.topics), options.loop ? 0.0 : options.from_s);
  } catch (const RecordingNotFound& e) {
    err << "fedsim replay: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "fedsim replay: " << e.what() << "\n";
    return 1;
  }
  try {
    runtime::install_shutdown_handler();  // before the participant starts its threads
    print_plan(*recording, out);
    auto dds = runtime::DdsParticipant::create(options.dds);
    Replayer replayer(dds, std::move(*recording), {options.speed, options.from_s, options.loop});
    if (replayer.wait_for_readers(std::chrono::milliseconds(static_cast<long long>(options.wait_s * 1000)))) {
      // The writers know their readers; a reader drops a best-effort sample of a writer it has
      // not matched yet, so give the other side of the match a moment too (as fedsim record).
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
    } else {
      out << "(not every topic has a reader yet: publishing anyway)\n";
    }
    const auto start = std::chrono::steady_clock::now();
    replayer.start();
    const std::string reason = replay_until_done(replayer, options, out);
    replayer.stop();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out << "stopped (" << reason << "): replayed " << replayer.published() << " samples up to "
        << seconds(replayer.position_s()) << " / " << seconds(replayer.recording().end_s())
        << " s of simulation time in " << seconds(wall) << " s";
    if (replayer.loops() > 0) out << " (" << replayer.loops() << " loops)";
    out << "\n";
    if (!replayer.error().empty()) {
      err << "fedsim replay: " << replayer.error() << "\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim replay: " << e.what() << "\n";
    return 1;
  }
}

void add_replay_command(CLI::App& app) {
  auto options = std::make_shared<ReplayCliOptions>();
  options->dds.name = "replay";
  auto* cmd = app.add_subcommand("replay", "publish a recording (fedsim record's CSV files) on DDS");
  cmd->add_option("dir", options->dir, "recording folder")->required();
  cmd->add_option("--speed", options->speed,
                  "simulation seconds per wall-clock second (0 = as fast as possible)")
      ->check(util::FiniteRange(0, 100))
      ->capture_default_str();
  cmd->add_option("--from-s", options->from_s, "start at this simulation time [s]")
      ->check(util::kFiniteNonNegative);
  cmd->add_option("--topics", options->topics, "topics to replay, comma-separated (default: all)")
      ->delimiter(',');
  cmd->add_flag("--loop", options->loop, "start over at the end (until Ctrl-C)");
  cmd->add_option("--wait", options->wait_s, "how long to wait for readers before publishing [s]")
      ->check(util::kFiniteNonNegative)
      ->capture_default_str();
  runtime::add_dds_options(*cmd, options->dds);
  cmd->callback([options] {
    const int code = run_replay(*options, std::cout, std::cerr);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace fedsim::tools
