// Runs fedsim-spline on the seed's Table 2.5 and checks the dense table against f1tab (seed 2.9).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "../spline_csv.hpp"

namespace fedsim::tools {
namespace {

// Seed section 2.9, f1tab[]: the spline of Table 2.5 at M = 0, 0.01, ..., 1.0.
constexpr double kF1tab[] = {
    3.3000, 3.3019, 3.3036, 3.3051, 3.3065, 3.3076, 3.3087, 3.3096, 3.3104, 3.3111, 3.3116,
    3.3121, 3.3126, 3.3129, 3.3132, 3.3135, 3.3138, 3.3141, 3.3143, 3.3146, 3.3149, 3.3153,
    3.3157, 3.3161, 3.3167, 3.3173, 3.3181, 3.3189, 3.3199, 3.3211, 3.3224, 3.3238, 3.3255,
    3.3273, 3.3293, 3.3316, 3.3341, 3.3368, 3.3398, 3.3430, 3.3465, 3.3504, 3.3545, 3.3589,
    3.3637, 3.3688, 3.3743, 3.3801, 3.3864, 3.3930, 3.4000, 3.4074, 3.4153, 3.4237, 3.4327,
    3.4422, 3.4524, 3.4632, 3.4747, 3.4870, 3.5000, 3.5138, 3.5284, 3.5434, 3.5588, 3.5744,
    3.5900, 3.6056, 3.6208, 3.6357, 3.6500, 3.6637, 3.6772, 3.6912, 3.7062, 3.7228, 3.7416,
    3.7631, 3.7880, 3.8167, 3.8500, 3.8887, 3.9353, 3.9925, 4.0631, 4.1500, 4.2554, 4.3802,
    4.5233, 4.6500, 4.7010, 4.6500, 4.5000, 4.3211, 4.1476, 4.0000, 3.8930, 3.8184, 3.7622,
    3.7107, 3.650};

XyData run_tool(const std::string& arguments) {
  const std::string input = std::string(FEDSIM_TEST_DATA_DIR) + "/spline/table_2_5.csv";
  const std::string output = ::testing::TempDir() + "fedsim_spline_test.csv";
  const std::string command =
      std::string(FEDSIM_SPLINE_TOOL) + " " + input + " -o " + output + " " + arguments;
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
