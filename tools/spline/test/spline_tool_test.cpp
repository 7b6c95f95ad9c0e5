// Runs fedsim-spline on the seed's Table 2.5 and checks the dense table against f1tab (seed 2.9).
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "../spline_csv.hpp"
#include "common/math/test/seed_f1tab.hpp"

namespace fedsim::tools {
namespace {

using fedsim::testing::kF1tab;  // seed section 2.9, f1tab[]

XyData run_tool(const std::string& arguments) {
  const std::string input = fedsim::util::test_data_dir() + "/spline/table_2_5.csv";
  const std::string output = ::testing::TempDir() + "fedsim_spline_test.csv";
  const std::string command =
      (fedsim::util::bin_dir() + "/fedsim-spline") + " " + input + " -o " + output + " " + arguments;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(output);
  return read_xy_csv(in, output);
}

TEST(SplineTool, ReproducesTheSeedF1tab) {
  // The book's table matches the spline with end slopes equal to the end chords.
  const XyData table = run_tool("--ends chord --step 0.01");
  ASSERT_EQ(table.x.size(), 101u);
  EXPECT_EQ(table.x_name, "mach");
  EXPECT_EQ(table.y_name, "dcl_dalpha");
  for (std::size_t i = 0; i < table.y.size(); ++i) {
    EXPECT_NEAR(table.x[i], 0.01 * i, 1e-12);
    EXPECT_NEAR(table.y[i], kF1tab[i], 1e-3) << "M = " << table.x[i];
  }
}

TEST(SplineTool, NaturalEndsAndPointCount) {
  const XyData table = run_tool("--points 11 --from 0.5 --to 0.95");
  ASSERT_EQ(table.x.size(), 11u);
  EXPECT_NEAR(table.x.back(), 0.95, 1e-12);
  EXPECT_NEAR(table.y.front(), 3.4, 1e-12);  // passes through the data points
  EXPECT_NEAR(table.y.back(), 4.0, 1e-12);
}

TEST(SplineCsv, RejectsMalformedRows) {
  std::istringstream bad("x,y\n1,2\n3,oops\n");
  EXPECT_THROW(read_xy_csv(bad, "bad.csv"), std::runtime_error);
}

}  // namespace
}  // namespace fedsim::tools
