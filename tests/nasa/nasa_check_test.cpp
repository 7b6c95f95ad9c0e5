// NASA TM-2015-218675 atmospheric check cases 1, 2, 3, 6, 7, 9, 10 flown through the batch
// program fedsim-fly (aircraft packs data/aircraft/nasa_*.yaml, IC files tests/data/nasa/<case>/
// ic.yaml, rotating WGS-84 earth, J2 gravity, US 1976 air) and, underneath it, on the rigid-body
// library alone; both compared with the envelope of NASA's simulation tools. Also tests of the
// reference loader and the comparator themselves.
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "check_case.hpp"
#include "comparison_plot.hpp"
#include "envelope_comparator.hpp"
#include "fly_check_case.hpp"
#include "nasa_reference.hpp"

namespace fedsim::flight::nasa {
namespace {

const std::string kDataDir = fedsim::util::test_data_dir() + "/nasa/";
constexpr double kFt = units::kFtToM;
constexpr double kDeg = units::kDegToRad;

// Allowed distance OUTSIDE the min/max of NASA's tools, per channel group (SI units).
// Why not zero: the tools do not share one atmosphere. sim_04, the tool fedsim tracks most
// closely (1e-11 rad on the undamped brick, 25 um on the sphere with drag), has air densities
// 5e-7 to 9e-7 (relative) above what the US 1976 defining equations give; scaling fedsim's
// density by 1 + 6.5e-7 takes the cannonball from 0.85 mm to 0.07 mm of sim_04 after 30 s.
// Where sim_04 sits on the edge of the envelope (cannonballs, damped brick) that density offset
// puts fedsim up to ~1.1 mm, 4.4e-5 m/s and 1e-6 rad outside it. The margins are about twice
// those figures, and far below the spread between the tools (metres, 1e-2 m/s, 1e-2 rad).
// Rates and Euler angles also absorb the 12-significant-figure rounding of the trimmed files.
const std::map<std::string, double> kMargins = {
    {"altitude", 0.002},     // m
    {"position", 0.002},     // m
    {"velocity", 1e-4},      // m/s
    {"euler", 2e-6},         // rad
    {"body_rates", 1e-8},    // rad/s
};

NasaReference load_reference(const std::string& case_id) {
  NasaReference reference = NasaReference::load(kDataDir + case_id);
  // sim_02 records geocentric, not geodetic, latitude (46.8 m apart at the end of case 10,
  // = e^2 N / (N + h) times the latitude); it is left out of the latitude envelope.
  reference.exclude("sim_02", "north_m");
  return reference;
}

void print_table(const std::string& id, const std::vector<ChannelComparison>& results) {
  std::printf("%s  %-12s %4s %4s %13s %7s %13s %13s %9s\n", id.c_str(), "channel", "n", "runs",
              "max excess", "at t", "NASA spread", "|fedsim-mid|", "margin");
  for (const ChannelComparison& r : results) {
    std::printf("%s  %-12s %4d %4d %13.4g %7.2f %13.4g %13.4g %9.2g %s\n", id.c_str(),
                r.channel.c_str(), r.samples, r.runs, r.max_excess, r.time_of_max_excess,
                r.max_envelope_width, r.max_distance_to_middle, r.margin,
                r.passed() ? "" : "<-- OUTSIDE");
  }
}

class NasaCheckCases : public ::testing::TestWithParam<CheckCase> {};
class NasaCheckCasesThroughFedsimFly : public ::testing::TestWithParam<FlyCheckCase> {};

void expect_inside_envelope(const std::string& id, const TimeHistory& fedsim,
                            const NasaReference& reference) {
  const std::vector<ChannelComparison> results =
      EnvelopeComparator(reference).compare_all(fedsim, kMargins);
  print_table(id, results);
  EXPECT_EQ(results.size(), 12u);  // every channel is recorded by at least one NASA tool
  for (const ChannelComparison& r : results) {
    EXPECT_TRUE(r.passed()) << id << " " << r.channel << ": " << r.max_excess
                            << " outside NASA's envelope at t = " << r.time_of_max_excess
                            << " s (margin " << r.margin << ")";
  }
}

}  // namespace

// Names the case in GoogleTest's messages instead of dumping its bytes.
void PrintTo(const CheckCase& check_case, std::ostream* os) { *os << check_case.id; }
void PrintTo(const FlyCheckCase& check_case, std::ostream* os) { *os << check_case.id; }

namespace {

TEST_P(NasaCheckCasesThroughFedsimFly, StaysWithinTheNasaEnvelope) {
  // The whole product path: pack + IC file -> fedsim-fly (AircraftModel: atmosphere, weather,
  // air data, aerodynamics, equations of motion) -> CSV -> comparison. The plots
  // build/nasa/<case>.png are drawn from these runs.
  const FlyCheckCase& check_case = GetParam();
  const NasaReference reference = load_reference(check_case.id);
  const std::string work_dir = ::testing::TempDir() + "nasa_fly";
  std::filesystem::create_directories(work_dir);
  const TimeHistory fedsim = fly_case(check_case, work_dir);
  expect_inside_envelope(check_case.id, fedsim, reference);
  if (!plot_comparison(check_case.id, check_case.title, fedsim, reference,
                       fedsim::util::binary_dir() + "/nasa")) {
    std::printf("%s: gnuplot unavailable or failed; no PNG drawn\n", check_case.id.c_str());
  }
}

INSTANTIATE_TEST_SUITE_P(Atmospheric, NasaCheckCasesThroughFedsimFly,
                         ::testing::ValuesIn(fly_check_cases()),
                         [](const auto& info) { return info.param.id; });

TEST_P(NasaCheckCases, StaysWithinTheNasaEnvelope) {
  // The rigid-body library alone, with hand-written force sources (check_case.cpp).
  const CheckCase& check_case = GetParam();
  const NasaReference reference = load_reference(check_case.id);
  // RK4 at 100 Hz, recorded at 10 Hz; the answers are converged in the step (h = 0.002 s
  // changes nothing at the printed precision).
  const TimeHistory fedsim = simulate(check_case, IntegrationMethod::kRk4, 0.01, 0.1);
  expect_inside_envelope(check_case.id, fedsim, reference);
}

INSTANTIATE_TEST_SUITE_P(Atmospheric, NasaCheckCases,
                         ::testing::ValuesIn(atmospheric_check_cases()),
                         [](const auto& info) { return info.param.id; });

TEST(NasaCheckCases, CaseOneIsDraglessAndDiffersFromCaseSix) {
  // The Aetherion JSON for case 1 carries CD = 0.1; the report's case 1 is dragless. With drag
  // the sphere ends ~210 m higher, far outside case 1's NASA envelope (0.6 mm wide).
  CheckCase dragless = atmospheric_check_cases().front();
  ASSERT_EQ(dragless.id, "Atmos_01");
  EXPECT_EQ(dragless.drag_coefficient, 0.0);
  CheckCase with_drag = dragless;
  with_drag.drag_coefficient = 0.1;
  const NasaReference reference = load_reference("Atmos_01");
  const TimeHistory wrong = simulate(with_drag, IntegrationMethod::kRk4, 0.01, 0.1);
  const ChannelComparison r =
      EnvelopeComparator(reference).compare(wrong, "altitude_m", "altitude", false, 0.002);
  EXPECT_FALSE(r.passed());
  EXPECT_GT(r.max_excess, 150.0);
}

TEST(NasaReference, ConvertsNasaUnitsToSi) {
  const TimeHistory sim04 = NasaReference::read_nasa_csv(kDataDir + "Atmos_01/Atmos_01_sim_04.csv");
  EXPECT_DOUBLE_EQ(sim04.at("altitude_m", 0.0), 30000.0 * kFt);
  EXPECT_NEAR(sim04.at("altitude_m", 30.0), 15598.9043522 * kFt, 1e-9);
  EXPECT_NEAR(sim04.at("v_down_mps", 30.0), 960.293064507 * kFt, 1e-9);
  EXPECT_NEAR(sim04.at("phi_rad", 30.0), -0.125399679189 * kDeg, 1e-14);
  EXPECT_NEAR(sim04.at("east_m", 30.0), 5.74552213287e-5 * kDeg * 6378137.0, 1e-9);
  const TimeHistory sim02 = NasaReference::read_nasa_csv(kDataDir + "Atmos_02/Atmos_02_sim_02.csv");
  EXPECT_NEAR(sim02.at("p_radps", 0.0), 10.0 * kDeg, 1e-9);
  // sim_03 records no attitude: those channels are absent, not zero.
  const TimeHistory sim03 = NasaReference::read_nasa_csv(kDataDir + "Atmos_01/Atmos_01_sim_03.csv");
  EXPECT_FALSE(sim03.has("phi_rad"));
  EXPECT_TRUE(sim03.has("v_down_mps"));
}

TEST(EnvelopeComparator, MeasuresTheDistanceOutsideTheEnvelope) {
  const NasaReference reference = load_reference("Atmos_06");
  // A history that runs exactly 0.5 m above NASA's highest altitude and inside elsewhere.
  TimeHistory probe({"altitude_m", "v_down_mps"});
  for (double t : reference.times()) {
    const Envelope alt = reference.envelope("altitude_m", t, false, 0.0);
    const Envelope vd = reference.envelope("v_down_mps", t, false, 0.0);
    probe.append(t, {alt.high + 0.5, 0.5 * (vd.low + vd.high)});
  }
  const EnvelopeComparator comparator(reference);
  const ChannelComparison above = comparator.compare(probe, "altitude_m", "altitude", false, 0.4);
  EXPECT_NEAR(above.max_excess, 0.5, 1e-9);
  EXPECT_EQ(above.runs, 5);
  EXPECT_EQ(above.samples, 61);
  EXPECT_FALSE(above.passed());
  const ChannelComparison inside = comparator.compare(probe, "v_down_mps", "velocity", false, 0.0);
  EXPECT_EQ(inside.max_excess, 0.0);
  EXPECT_TRUE(inside.passed());
  EXPECT_EQ(comparator.compare(probe, "psi_rad", "euler", true, 1.0).samples, 0);
  // A record that stops half way is inside the envelope where it exists, and still fails:
  // every reference time must be compared.
  TimeHistory half({"v_down_mps"});
  for (double t : reference.times()) {
    if (t > 15.0) break;
    const Envelope vd = reference.envelope("v_down_mps", t, false, 0.0);
    half.append(t, {0.5 * (vd.low + vd.high)});
  }
  const ChannelComparison partial = comparator.compare(half, "v_down_mps", "velocity", false, 0.0);
  EXPECT_EQ(partial.max_excess, 0.0);
  EXPECT_EQ(partial.reference_samples, 61);
  EXPECT_LT(partial.samples, 61);
  EXPECT_FALSE(partial.passed());
}

TEST(EnvelopeComparator, ComparesAnglesAcrossTheWrap) {
  // Two tools at +179.9 and -179.9 deg: the envelope is the 0.2 deg through 180, not 359.8 deg.
  const std::string folder = ::testing::TempDir() + "nasa_wrap_case";
  std::filesystem::create_directories(folder);
  for (const auto& [name, yaw] : {std::pair{"Atmos_99_sim_01.csv", 179.9},
                                  std::pair{"Atmos_99_sim_02.csv", -179.9}}) {
    std::ofstream out(folder + "/" + name);
    out << "time,eulerAngle_deg_Yaw\n0," << yaw << "\n1," << yaw << "\n";
  }
  const NasaReference reference = NasaReference::load(folder);
  const EnvelopeComparator comparator(reference);
  TimeHistory on_the_wrap({"psi_rad"});
  on_the_wrap.append(0.0, {180.0 * kDeg});
  on_the_wrap.append(1.0, {-179.95 * kDeg});
  EXPECT_EQ(comparator.compare(on_the_wrap, "psi_rad", "euler", true, 0.0).max_excess, 0.0);
  TimeHistory outside({"psi_rad"});
  outside.append(0.0, {179.0 * kDeg});
  outside.append(1.0, {179.0 * kDeg});
  EXPECT_NEAR(comparator.compare(outside, "psi_rad", "euler", true, 0.0).max_excess, 0.9 * kDeg,
              1e-9);
}

}  // namespace
}  // namespace fedsim::flight::nasa
