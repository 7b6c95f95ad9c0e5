// A folder of the running GoogleTest case's own: ctest runs the cases of one test program in
// parallel (each case in its own process), and a case that removes or reads back the files it
// wrote must not meet another case doing the same in a shared folder (DisplaysComponentTest read
// a half-written pfd.png of its neighbour that way under ctest -j2).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace fedsim::util::test {

/// <root>/<Suite.Case> (a parameterised name's '/' as '_'), created.
inline std::filesystem::path case_dir(const std::filesystem::path& root) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info != nullptr ? std::string(info->test_suite_name()) + "." + info->name() : "no_test";
  std::replace(name.begin(), name.end(), '/', '_');
  const std::filesystem::path dir = root / name;
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace fedsim::util::test
