// `fedsim nav find|near` through its command-line parser: what it prints for the built database
// and the navdb fixtures (distances and bearings against GeographicLib), and a clear error with
// exit status 2 for every bad argument.
#include "fedsim/nav_cli.hpp"
#include "common/util/build_paths.hpp"

#include "common/navdb/test/navdb_test_support.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace fedsim::launcher {
namespace {

struct Result {
  int exit_code = -1;
  std::string out;
  std::string err;
};

Result run(const std::string& arguments, const std::string& db = fedsim::util::navdb_file()) {
  CLI::App app{"fedsim"};
  std::ostringstream out, err;
  Result result;
  result.exit_code = 0;
  add_nav_commands(app, result.exit_code, out, err);
  try {
    app.parse("nav --db " + db + " " + arguments, false);
  } catch (const CLI::ParseError& e) {
    result.exit_code = app.exit(e, out, err);
  }
  result.out = out.str();
  result.err = err.str();
  return result;
}

std::string fixture_database() {
  static const std::string path = [] {
    const std::string p = nav::test::temp_path("nav_cli_fixture.sqlite");
    nav::test::build_fixture_database(p);
    return p;
  }();
  return path;
}

TEST(NavCli, FindsAVorDmeWithWhatAPilotLooksUp) {
  const Result r = run("find sfo");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // SFO VOR-DME: 115.80 MHz, channel 105X, N37 37.17 W122 22.44 (37.6195, -122.3740), 13 ft,
  // variation 14.4 E.
  EXPECT_NE(r.out.find("SFO   VOR-DME 115.80 MHz 105X San Francisco"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("N37 37.17 W122 22.44      13 US 14.4E"), std::string::npos) << r.out;
}

TEST(NavCli, FindsAnAirportsRunwaysAndIls) {
  const Result shipped = run("find KSFO");
  ASSERT_EQ(shipped.exit_code, 0) << shipped.err;
  EXPECT_NE(shipped.out.find("Airport KSFO: 8 runway ends"), std::string::npos) << shipped.out;
  // 28R: threshold 300 ft in from the end, 13 ft, 298 true, 11870 x 200 ft.
  EXPECT_NE(shipped.out.find("28R  N37 36.84 W122 21.48      13   298     11870      200      300 ASP"),
            std::string::npos)
      << shipped.out;
  const Result fixture = run("find KSFO", fixture_database());
  ASSERT_EQ(fixture.exit_code, 0) << fixture.err;
  EXPECT_NE(fixture.out.find("KSFO 28R  IGWQ  111.70 MHz   284   298   3.00     55 III yes"),
            std::string::npos)
      << fixture.out;
  const Result localizer = run("find isfo", fixture_database());
  EXPECT_NE(localizer.out.find("Localizers ISFO:"), std::string::npos) << localizer.out;
}

TEST(NavCli, NearGivesDistanceAndBearingsFromThePosition) {
  // A point 10 NM west of the SFO VOR-DME (GeographicLib direct problem): the station at 10.0
  // NM, bearing the reverse azimuth, magnetic = true - 14.423 deg.
  const auto& g = GeographicLib::Geodesic::WGS84();
  const double sfo_lat = 37.61949920654297, sfo_lon = -122.3740005493164;
  double lat = 0.0, lon = 0.0, azimuth_at_point = 0.0;
  g.Direct(sfo_lat, sfo_lon, 270.0, 10.0 * units::kNmToM, lat, lon, azimuth_at_point);
  const double bearing_true = std::fmod(azimuth_at_point + 180.0 + 360.0, 360.0);
  char expected[64];
  std::snprintf(expected, sizeof expected, "    10.0   %03ld   %03ld", std::lround(bearing_true),
                std::lround(bearing_true - 14.423));
  char arguments[128];
  std::snprintf(arguments, sizeof arguments, "near %.9f %.9f --radius-nm 10.5 --type VOR-DME", lat,
                lon);
  const Result r = run(arguments);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto line = r.out.find("SFO   VOR-DME");
  ASSERT_NE(line, std::string::npos) << r.out;
  EXPECT_NE(r.out.substr(line, r.out.find('\n', line) - line).find(expected), std::string::npos)
      << r.out << "\nexpected " << expected;
  // Only the types asked for (negative control: OAK is a VORTAC, 13 NM away).
  EXPECT_EQ(r.out.find("VORTAC"), std::string::npos);
  const Result wider = run(std::string(arguments).replace(std::string(arguments).find("10.5"), 4, "40") +
                           ",VORTAC");
  EXPECT_NE(wider.out.find("OAK   VORTAC"), std::string::npos) << wider.out;
}

TEST(NavCli, EveryBadArgumentIsAClearError) {
  const struct {
    const char* arguments;
    const char* message;
  } cases[] = {
      {"near nan -122", "latitude nan deg: must be a number in [-90, 90]"},
      {"near 91 -122", "latitude 91 deg"},
      {"near 37 -181", "longitude -181 deg: must be a number in [-180, 180]"},
      {"near 37 inf", "longitude inf deg"},
      {"near 37 -122 --radius-nm 0", "--radius-nm 0: must be a number in (0, 10800]"},
      {"near 37 -122 --radius-nm nan", "--radius-nm nan"},
      {"near 37 -122 --type VOR,LOC", "--type: 'LOC' is not a station type"},
  };
  for (const auto& c : cases) {
    const Result r = run(c.arguments);
    EXPECT_EQ(r.exit_code, 2) << c.arguments;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << ": " << r.err;
  }
  const Result not_a_number = run("near abc 1");
  EXPECT_NE(not_a_number.exit_code, 0);
  const Result no_database = run("find SFO", "/nonexistent/nav.sqlite");
  EXPECT_EQ(no_database.exit_code, 2);
  EXPECT_NE(no_database.err.find("/nonexistent/nav.sqlite: no such file"), std::string::npos)
      << no_database.err;
  const Result unknown = run("find ZZZZZZ");
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.err.find("no navaid, localizer or airport 'ZZZZZZ'"), std::string::npos);
}

}  // namespace
}  // namespace fedsim::launcher
