#include "common/picture/snapshot_tag.hpp"

namespace fedsim::picture {

std::optional<std::string> snapshot_tag_problem(const std::string& tag) {
  if (tag.size() > 48) return "snapshot tag longer than 48 characters";
  if (tag.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos) {
    return "snapshot tag '" + tag + "': only [A-Za-z0-9_-] (it becomes part of a file name)";
  }
  return std::nullopt;
}

}  // namespace fedsim::picture
