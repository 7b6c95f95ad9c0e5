// The tag of a snapshot command (`fedsim command snapshot --tag`), which becomes part of the PNG's
// file name in both image federates (fedsim-visual: <channel>_<tag>.png, fedsim-displays:
// <display>_<tag>.png): [A-Za-z0-9_-]{0,48}, so that no tag can name another folder.
#pragma once

#include <optional>
#include <string>

namespace fedsim::picture {

/// The problem with `tag`, or nullopt when it is usable.
std::optional<std::string> snapshot_tag_problem(const std::string& tag);

}  // namespace fedsim::picture
