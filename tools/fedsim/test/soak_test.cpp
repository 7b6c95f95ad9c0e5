// `fedsim soak`'s pure parts: VmRSS parsing, frame-gap counting, the verdict and its report, the
// option checks; and that deploy/soak.yaml stays the default federation.
#include "fedsim/deployment.hpp"
#include "common/util/build_paths.hpp"
#include "fedsim/soak.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace fedsim::launcher {
namespace {

TEST(SoakRss, ReadsVmRssInKilobytes) {
  const std::string status = "Name:\tfedsim-flight\nVmPeak:\t  900000 kB\nVmRSS:\t   22272 kB\n";
  EXPECT_EQ(parse_vm_rss_kb(status), 22272);
  EXPECT_FALSE(parse_vm_rss_kb("Name:\tzombie\n"));          // a zombie has no VmRSS line
  EXPECT_FALSE(parse_vm_rss_kb("VmRSS:\t   nonsense kB\n"));
  EXPECT_FALSE(parse_vm_rss_kb("VmRSS:\t   12 MB\n"));
}

FrameGaps gaps_of(const std::string& csv) {
  std::istringstream in(csv);
  return count_frame_gaps(in, "test.csv");
}

TEST(SoakFrameGaps, ContinuousFramesLoseNothing) {
  const auto g = gaps_of("sim_time_s,aircraft_id,stamp.frame,x\n0.1,0,5,1\n0.2,0,6,1\n0.3,0,7,1\n");
  EXPECT_EQ(g.samples, 3u);
  EXPECT_EQ(g.lost, 0u);
  EXPECT_EQ(g.first_frame, 5);
  EXPECT_EQ(g.last_frame, 7);
}

TEST(SoakFrameGaps, EachMissingFrameIsOneLostSample) {
  // 516 -> 518 -> 520: frames 517 and 519 missing (as a loaded machine showed); a repeat of
  // 518 is counted as repeated, not lost.
  const auto g =
      gaps_of("stamp.frame\n515\n516\n518\n518\n520\n");
  EXPECT_EQ(g.lost, 2u);
  EXPECT_EQ(g.repeated, 1u);
}

TEST(SoakFrameGaps, InstancesAreCountedApartAndQuotedFieldsKeepTheirCommas) {
  // Two aircraft interleaved: no gap within either; a quoted text field with a comma before
  // the frame column does not shift it.
  const auto g = gaps_of(
      "name,aircraft_id,stamp.frame\n\"a,b\",0,10\n\"c\",1,10\n\"d\",0,11\n\"e\",1,11\n\"f\",1,13\n");
  EXPECT_EQ(g.samples, 5u);
  EXPECT_EQ(g.lost, 1u);  // aircraft 1's frame 12
}

TEST(SoakFrameGaps, RefusesAFileWithoutFrameStamps) {
  EXPECT_THROW(gaps_of("a,b\n1,2\n"), std::runtime_error);
  EXPECT_THROW(gaps_of("stamp.frame\n1\nx2\n"), std::runtime_error);
}

SoakResult healthy_result() {
  SoakResult r;
  r.run_exit = 0;
  r.timing_summary = nlohmann::json{{"frames", 6000}, {"overruns", 3}, {"lost", nlohmann::json::array()},
                                    {"period_error_us", {{"p50", 80.0}}}};
  r.topics["fedsim_aircraft_state.csv"] = FrameGaps{6000, 0, 0, 0, 5999};
  r.rss["flight"] = RssSamples{20000, 20500, 20600};  // +2.5%
  return r;
}

TEST(SoakVerdict, AHealthyRunPasses) {
  SoakOptions o;
  const auto r = healthy_result();
  EXPECT_TRUE(soak_failures(r, o).empty());
  const auto j = soak_report(r, o, {});
  EXPECT_EQ(j["soak"], "ok");
  EXPECT_EQ(j["frames"], 6000);
  EXPECT_EQ(j["lost_samples"], 0);
  EXPECT_EQ(j["rss"]["flight"]["start_kb"], 20000);
  EXPECT_EQ(j["rss"]["flight"]["end_kb"], 20500);
}

TEST(SoakVerdict, LostSamplesOverTheThresholdFail) {
  SoakOptions o;
  auto r = healthy_result();
  r.topics["fedsim_pilot_controls.csv"] = FrameGaps{5998, 2, 0, 0, 5999};
  auto failures = soak_failures(r, o);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0], "lost_samples: 2 > 0");
  o.max_lost = 2;
  EXPECT_TRUE(soak_failures(r, o).empty());
  EXPECT_EQ(soak_report(r, o, {})["lost_samples"], 2);
}

TEST(SoakVerdict, RssGrowthOverTheThresholdFailsNamingTheFederate) {
  SoakOptions o;
  auto r = healthy_result();
  r.rss["visual"] = RssSamples{100000, 106000, 106000};  // +6%
  auto failures = soak_failures(r, o);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0], "rss_growth: visual +6.0% > 5.0%");
  o.max_rss_growth_pct = 10;
  EXPECT_TRUE(soak_failures(r, o).empty());
}

TEST(SoakVerdict, AFailedRunALostFederateOrNothingMeasuredFail) {
  SoakOptions o;
  auto r = healthy_result();
  r.run_exit = 1;
  r.timing_summary->at("lost") = nlohmann::json::array({"motion"});
  r.rss["ios"] = RssSamples{};  // gone before the warm-up ended
  const auto failures = soak_failures(r, o);
  ASSERT_EQ(failures.size(), 3u);
  EXPECT_NE(failures[0].find("run_failed: fedsim run exit 1"), std::string::npos);
  EXPECT_EQ(failures[1], "federates_lost: [\"motion\"]");
  EXPECT_NE(failures[2].find("rss_unmeasured: ios"), std::string::npos);
  EXPECT_FALSE(soak_failures(SoakResult{}, o).empty());
}

TEST(SoakOptions, AreChecked) {
  SoakOptions o;
  o.duration_s = 180;
  EXPECT_NO_THROW(check_soak_options(o));
  o.duration_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(check_soak_options(o), std::invalid_argument);
  o.duration_s = 60;  // the default 60 s warm-up leaves nothing to measure
  EXPECT_THROW(check_soak_options(o), std::invalid_argument);
  o.warmup_s = 30;
  EXPECT_NO_THROW(check_soak_options(o));
  o.max_rss_growth_pct = std::numeric_limits<double>::infinity();
  EXPECT_THROW(check_soak_options(o), std::invalid_argument);
}

TEST(SoakDeployment, IsTheDefaultFederationInRealtime) {
  const auto def = load_deployment(fedsim::util::source_dir() + "/deploy/default.yaml");
  const auto soak = load_deployment(fedsim::util::source_dir() + "/deploy/soak.yaml");
  EXPECT_EQ(soak.mode, "realtime");
  EXPECT_EQ(soak.rate_hz, def.rate_hz);
  EXPECT_TRUE(soak.after.empty());
  ASSERT_EQ(soak.federates.size(), def.federates.size());
  for (std::size_t i = 0; i < def.federates.size(); ++i) {
    EXPECT_EQ(soak.federates[i].name, def.federates[i].name);
    EXPECT_EQ(soak.federates[i].binary, def.federates[i].binary);
    auto expected_args = def.federates[i].args;
    // The one difference: a replay ring that is full before the warm-up ends (soak.yaml says why).
    if (def.federates[i].name == "ios") expected_args.insert(expected_args.end(), {"--ring-minutes", "0.5"});
    EXPECT_EQ(soak.federates[i].args, expected_args) << def.federates[i].name;
    EXPECT_EQ(soak.federates[i].lockstep, def.federates[i].lockstep);
    EXPECT_EQ(soak.federates[i].required, def.federates[i].required);
  }
}

}  // namespace
}  // namespace fedsim::launcher
