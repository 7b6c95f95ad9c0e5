// Snapshot tags: letters, digits, '_' and '-', at most 48; anything that could leave the folder
// (a '/', "..") or overrun a file name is refused with the reason.
#include "common/picture/snapshot_tag.hpp"

#include <gtest/gtest.h>

namespace fedsim::picture {
namespace {

TEST(SnapshotTag, FileNameCharactersOnly) {
  EXPECT_FALSE(snapshot_tag_problem("approach_1-2"));
  EXPECT_FALSE(snapshot_tag_problem(""));
  EXPECT_FALSE(snapshot_tag_problem(std::string(48, 'a')));
  EXPECT_EQ(snapshot_tag_problem("a/b").value_or(""), "snapshot tag 'a/b': only [A-Za-z0-9_-] (it becomes part of a file name)");
  EXPECT_TRUE(snapshot_tag_problem(".."));
  EXPECT_EQ(snapshot_tag_problem(std::string(49, 'a')).value_or(""), "snapshot tag longer than 48 characters");
}

}  // namespace
}  // namespace fedsim::picture
