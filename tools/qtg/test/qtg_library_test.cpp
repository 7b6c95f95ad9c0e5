// The QTG library alone: test-file validation (file:line: field errors), the measures on
// synthetic signals with known period and damping (and signals without an oscillation, the
// negative controls), the comparison and the report.
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "common/airports/runway_centreline.hpp"
#include "common/util/config_node.hpp"
#include "tools/qtg/channels.hpp"
#include "tools/qtg/compare.hpp"
#include "tools/qtg/measures.hpp"
#include "tools/qtg/qtg_test.hpp"
#include "tools/qtg/report.hpp"
#include "tools/qtg/runner.hpp"

namespace fs = std::filesystem;
using namespace fedsim::qtg;

namespace {

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("qtg_tests_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return p.string();
}

const char* kValid = R"(fedsim_qtg_test: 1
title: C172 phugoid
part60_item: "2.c.4 phugoid dynamics"
aircraft: c172
start: {trim: level, alt_ft: 4000, ktas: 100}
duration_s: 120
rate_hz: 50
reference:
  kind: analytic
  source: "Lanchester's approximation T = pi sqrt(2) V / g"
checks:
  - name: phugoid period
    channel: tas_kt
    measure: period
    from_s: 5
    reference_formula: lanchester_period
    tolerance: {percent: 10}
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

/// Whether the argument list has option `key` followed by `value`.
bool has_option(const std::vector<std::string>& a, const std::string& key, const std::string& value) {
  for (std::size_t i = 0; i + 1 < a.size(); ++i)
    if (a[i] == key && a[i + 1] == value) return true;
  return false;
}

/// The error load_test gives, or "" if it loaded.
std::string load_error(const std::string& text) {
  try {
    load_test(write("t.yaml", text));
    return "";
  } catch (const fedsim::util::ConfigError& e) {
    return e.what();
  }
}

/// x(t) = c + A e^(-zeta wn t) cos(wd t), sampled at `rate`.
Series damped(double period_s, double zeta, double rate, double duration, double offset = 3.0) {
  const double wd = 2 * M_PI / period_s;
  const double wn = wd / std::sqrt(1 - zeta * zeta);
  Series s;
  for (int i = 0; i <= static_cast<int>(duration * rate); ++i) {
    const double t = i / rate;
    s.t.push_back(t);
    s.x.push_back(offset + 5.0 * std::exp(-zeta * wn * t) * std::cos(wd * t + 0.3));
  }
  return s;
}

}  // namespace

TEST(QtgTestFile, ValidFileLoadsWithLanchesterPeriod) {
  const QtgTest t = load_test(write("c172_phugoid.yaml", kValid));
  EXPECT_EQ(t.name, "c172_phugoid");
  ASSERT_EQ(t.checks.size(), 1u);
  // pi sqrt(2) * 51.444 m/s / 9.80665 = 23.31 s
  EXPECT_NEAR(*t.checks[0].reference_value, 23.31, 0.01);
  EXPECT_EQ(t.checks[0].line, 12);
  EXPECT_EQ(t.checks[0].tolerance.text(), "±10 %");
}

TEST(QtgTestFile, ErrorsNameFileLineAndField) {
  const std::string nan_error = load_error(replace(kValid, "duration_s: 120", "duration_s: .nan"));
  EXPECT_NE(nan_error.find("t.yaml:6: duration_s"), std::string::npos) << nan_error;
  EXPECT_NE(load_error(replace(kValid, "duration_s: 120", "duration_s: .inf")), "");
  EXPECT_NE(load_error(replace(kValid, "rate_hz: 50", "rate_hz: 0")).find("rate_hz"), std::string::npos);
  EXPECT_NE(load_error(replace(kValid, "ktas: 100", "ktas: 100, kcas: 90")).find("exactly one"),
            std::string::npos);
  EXPECT_NE(load_error(replace(kValid, "channel: tas_kt", "channel: tas_mph")).find("unknown channel"),
            std::string::npos);
  EXPECT_NE(load_error(replace(kValid, "kind: analytic", "kind: gospel")).find("kind"), std::string::npos);
  EXPECT_NE(load_error(replace(kValid, "from_s: 5", "from_s: 500")).find("from_s"), std::string::npos);
  EXPECT_NE(load_error(replace(kValid, "from_s: 5", "form_s: 5")).find("form_s"), std::string::npos);
  EXPECT_NE(load_error(replace(kValid, "source: \"Lanchester's approximation T = pi sqrt(2) V / g\"",
                               "source: x")).find("source"), std::string::npos);
}

TEST(QtgTestFile, ToleranceUnitMustMatchTheComparedQuantity) {
  // a period is in seconds: "±3 kt" on it is a mistake
  const std::string e = load_error(replace(kValid, "{percent: 10}", "{plus_minus: 3, unit: kt}"));
  EXPECT_NE(e.find("tolerance.unit"), std::string::npos) << e;
  EXPECT_EQ(load_error(replace(kValid, "{percent: 10}", "{plus_minus: 2, unit: s}")), "");
  EXPECT_NE(load_error(replace(kValid, "{percent: 10}", "{percent: -1}")), "");
  EXPECT_NE(load_error(replace(kValid, "{percent: 10}", "{plus_minus: .nan, unit: s}")), "");
}

TEST(QtgTestFile, TimeHistoryNeedsAReferenceFile) {
  std::string text = replace(kValid, "measure: period", "measure: time_history");
  text = replace(text, "    reference_formula: lanchester_period\n", "");
  text = replace(text, "{percent: 10}", "{plus_minus: 3, unit: kt}");
  EXPECT_NE(load_error(text).find("reference.file"), std::string::npos);
  text = replace(text, "  source:", "  file: ref.csv\n  source:");
  EXPECT_EQ(load_error(text), "");
}

TEST(QtgTestFile, MissingProfileIsNamed) {
  const std::string e = load_error(replace(kValid, "duration_s:", "inputs: {profile: nope.csv}\nduration_s:"));
  EXPECT_NE(e.find("inputs.profile"), std::string::npos) << e;
}

TEST(QtgTestFile, FlyArgumentsMapTheStart) {
  const QtgTest t = load_test(write("c172_phugoid.yaml", kValid));
  const auto a = fly_arguments(t, "/tmp/x");
  const auto has = [&](const std::string& k, const std::string& v) { return has_option(a, k, v); };
  EXPECT_TRUE(has("--aircraft", "c172"));
  EXPECT_TRUE(has("--trim", "level"));
  EXPECT_TRUE(has("--ktas", "100"));
  EXPECT_TRUE(has("--duration", "120"));
  EXPECT_TRUE(has("--out", "/tmp/x"));
}

TEST(QtgMeasures, PeriodAndDampingOfADampedSinusoid) {
  for (double zeta : {0.02, 0.1, 0.3}) {
    std::string why;
    const auto o = analyse_oscillation(damped(30, zeta, 50, 200), 0, 200, why);
    ASSERT_TRUE(o) << why;
    EXPECT_NEAR(o->period_s, 30, 0.05) << zeta;
    EXPECT_NEAR(o->damping_ratio, zeta, 0.002) << zeta;
  }
}

TEST(QtgMeasures, OffsetAndCoarseSamplingDoNotBiasThePeriod) {
  std::string why;
  const auto o = analyse_oscillation(damped(2.5, 0.15, 20, 20, -40), 0, 20, why);
  ASSERT_TRUE(o) << why;
  EXPECT_NEAR(o->period_s, 2.5, 0.03);
  EXPECT_NEAR(o->damping_ratio, 0.15, 0.01);
}

TEST(QtgMeasures, NoOscillationIsReportedNotInvented) {
  Series ramp, decay;
  for (int i = 0; i < 1000; ++i) {
    ramp.t.push_back(i * 0.1), ramp.x.push_back(i * 0.1);
    decay.t.push_back(i * 0.1), decay.x.push_back(std::exp(-i * 0.01));
  }
  std::string why;
  EXPECT_FALSE(analyse_oscillation(ramp, 0, 100, why));
  EXPECT_NE(why.find("no oscillation"), std::string::npos);
  EXPECT_FALSE(analyse_oscillation(decay, 0, 100, why));
  // a tiny ripple on a ramp is not an oscillation of the mode
  Series rippled = ramp;
  for (std::size_t i = 0; i < rippled.x.size(); ++i) rippled.x[i] += 1e-4 * std::sin(i * 1.0);
  EXPECT_FALSE(analyse_oscillation(rippled, 0, 100, why));
}

TEST(QtgMeasures, CrossingAndExtremes) {
  Series s;
  for (int i = 0; i <= 100; ++i) s.t.push_back(i * 0.1), s.x.push_back(3.0 * i * 0.1);  // 3/s
  EXPECT_NEAR(*first_crossing(s, 15.0, 0, 10), 5.0, 1e-9);
  EXPECT_FALSE(first_crossing(s, 100.0, 0, 10));
  EXPECT_FALSE(first_crossing(s, 15.0, 6, 10));  // already past it
  EXPECT_NEAR(window_max(s, 0, 4)->x, 12.0, 1e-9);
  EXPECT_NEAR(window_min(s, 2, 4)->t, 2.0, 1e-9);
  EXPECT_NEAR(lanchester_period_s(100.0), M_PI * std::sqrt(2.0) * 100 / 9.80665, 1e-12);
}

/// A synthetic 1 g stall entry: V falls 1 kt/s from 80 kt with n_z = 1 while the lift
/// coefficient (n_z / V^2) can follow, up to C_Lmax at `stall_kt`; then the lift breaks (n_z falls
/// with the lift coefficient held at 85 % of its maximum) and the speed keeps falling.
Channels stall_entry(double stall_kt, double nz_at_peak = 1.0) {
  Channels c;
  for (int i = 0; i <= 600; ++i) {
    const double t = i * 0.1, v = 80.0 - t;
    double nz = 1.0;
    if (v <= stall_kt) nz = 0.85 * nz_at_peak * (v * v) / (stall_kt * stall_kt);
    if (std::fabs(v - stall_kt) < 1e-9) nz = nz_at_peak;
    c["cas_kt"].t.push_back(t), c["cas_kt"].x.push_back(v);
    c["nz_g"].t.push_back(t), c["nz_g"].x.push_back(nz);
  }
  return c;
}

TEST(QtgMeasures, StallSpeedIsTheSpeedAtTheFirstMaximumOfTheCorrectedLift) {
  std::string why;
  const Channels flown = stall_entry(50.0);
  const auto s = stall_speed_1g(flown.at("cas_kt"), flown.at("nz_g"), 0, 60, why);
  ASSERT_TRUE(s) << why;
  EXPECT_NEAR(s->cas_kt, 50.0, 1e-9);
  EXPECT_NEAR(s->t, 30.0, 1e-9);
  EXPECT_NEAR(s->vs1g_kt, 50.0, 1e-9);
  // At 1.21 g at the peak (a pull), the 1 g speed is V / 1.1: the load-factor correction.
  const Channels pulled = stall_entry(55.0, 1.21);
  const auto p = stall_speed_1g(pulled.at("cas_kt"), pulled.at("nz_g"), 0, 60, why);
  ASSERT_TRUE(p) << why;
  EXPECT_NEAR(p->vs1g_kt, 55.0 / 1.1, 1e-6);
  // Negative controls: an entry that never stalls (n_z = 1 throughout) has no maximum that
  // falls away, and a window ending before the break finds none.
  Channels steady = stall_entry(5.0);
  EXPECT_FALSE(stall_speed_1g(steady.at("cas_kt"), steady.at("nz_g"), 0, 60, why));
  EXPECT_NE(why.find("no stall in the window"), std::string::npos) << why;
  EXPECT_FALSE(stall_speed_1g(flown.at("cas_kt"), flown.at("nz_g"), 0, 29, why));
  EXPECT_FALSE(stall_speed_1g(flown.at("cas_kt"), Series{}, 0, 60, why));
  EXPECT_NE(why.find("nz_g"), std::string::npos) << why;
}

TEST(QtgTestFile, TheStallEntryPilotAndTheStallMeasure) {
  const std::string stall = replace(replace(kValid, "duration_s:", "inputs: {pilot: stall_entry, entry_rate_kt_per_s: 0.8, throttle: 0.1}\nduration_s:"),
                                    R"(  - name: phugoid period
    channel: tas_kt
    measure: period
    from_s: 5
    reference_formula: lanchester_period
    tolerance: {percent: 10})",
                                    R"(  - name: stall speed
    channel: cas_kt
    measure: stall_speed_1g
    from_s: 10
    reference_value: 40
    tolerance: {plus_minus: 3, unit: kt})");
  const QtgTest t = load_test(write("stall.yaml", replace(stall, "ktas: 100}", "ktas: 100, gear_down: true}")));
  EXPECT_EQ(t.pilot, "stall_entry");
  EXPECT_FALSE(t.inputs_relative);
  EXPECT_TRUE(t.start.gear_down);
  const auto a = fly_arguments(t, "/tmp/x");
  const auto has = [&](const std::string& k, const std::string& v) { return has_option(a, k, v); };
  EXPECT_TRUE(has("--pilot", "stall-entry"));
  const auto number_after = [&](const std::string& k) {
    const auto at = std::find(a.begin(), a.end(), k);
    return at == a.end() || at + 1 == a.end() ? -1.0 : std::stod(*(at + 1));
  };
  EXPECT_DOUBLE_EQ(number_after("--entry-rate-kt-s"), 0.8);
  EXPECT_DOUBLE_EQ(number_after("--pilot-throttle"), 0.1);
  EXPECT_NE(std::find(a.begin(), a.end(), "--gear-down"), a.end());
  EXPECT_EQ(std::find(a.begin(), a.end(), "--inputs-relative"), a.end());
  // Refusals, by name.
  std::string e = load_error(replace(stall, "pilot: stall_entry", "pilot: autopilot"));
  EXPECT_NE(e.find("inputs.pilot"), std::string::npos) << e;
  e = load_error(replace(stall, "entry_rate_kt_per_s: 0.8", "entry_rate_kt_per_s: .nan"));
  EXPECT_NE(e.find("entry_rate_kt_per_s"), std::string::npos) << e;
  e = load_error(replace(stall, "throttle: 0.1}", "throttle: 0.1, relative: true}"));
  EXPECT_NE(e.find("absolute controls"), std::string::npos) << e;
  e = load_error(replace(stall, "channel: cas_kt", "channel: tas_kt"));
  EXPECT_NE(e.find("stall_speed_1g is a calibrated airspeed"), std::string::npos) << e;
  e = load_error(replace(kValid, "duration_s:", "inputs: {throttle: 0}\nduration_s:"));
  EXPECT_NE(e.find("needs pilot: stall_entry"), std::string::npos) << e;
}

TEST(QtgCompare, TimeHistoryPassesInsideTheBandAndFailsOutside) {
  Check c;
  c.name = "airspeed";
  c.channel = "tas_kt";
  c.tolerance = {Tolerance::Kind::absolute, 3.0, "kt"};
  Channels flown;
  Series ref;
  for (int i = 0; i <= 100; ++i) {
    flown["tas_kt"].t.push_back(i * 0.1);
    flown["tas_kt"].x.push_back(100 + (i == 50 ? 2.5 : 0.0));
  }
  ref.t = {0, 10};
  ref.x = {100, 100};
  auto r = evaluate_check(c, flown, &ref, 10);
  EXPECT_TRUE(r.passed);
  EXPECT_NEAR(r.worst_excursion, 2.5, 1e-12);
  EXPECT_NEAR(r.worst_time_s, 5.0, 1e-12);
  flown["tas_kt"].x[50] = 103.5;  // the negative control: one sample out of the band
  r = evaluate_check(c, flown, &ref, 10);
  EXPECT_FALSE(r.passed);
  EXPECT_NEAR(r.worst_ratio, 3.5 / 3.0, 1e-12);
}

TEST(QtgCompare, DerivedMeasureAgainstAReferenceValue) {
  Check c;
  c.name = "period";
  c.channel = "tas_kt";
  c.measure = Measure::period;
  c.tolerance = {Tolerance::Kind::percent, 10.0, ""};
  Channels flown{{"tas_kt", damped(30, 0.05, 50, 200)}};
  c.reference_value = 32.0;  // 6.7 % off: passes
  EXPECT_TRUE(evaluate_check(c, flown, nullptr, 200).passed);
  c.reference_value = 35.0;  // 14 % off: fails
  EXPECT_FALSE(evaluate_check(c, flown, nullptr, 200).passed);
  Channels flat{{"tas_kt", Series{{0, 1, 2}, {1, 1, 1}}}};
  const auto r = evaluate_check(c, flat, nullptr, 2);
  EXPECT_FALSE(r.passed);  // nothing to measure is a failure, not a pass
  EXPECT_FALSE(r.problem.empty());
}

TEST(QtgReport, HtmlHasSummaryPlotsAndEscapes) {
  QtgTest t = load_test(write("c172_phugoid.yaml", kValid));
  t.title = "a <b> title";
  TestResult tr;
  tr.test = t;
  tr.ran = true;
  Channels flown{{"tas_kt", damped(23.3, 0.05, 50, 120, 100)}};
  tr.checks = evaluate_test(t, flown);
  ASSERT_EQ(tr.checks.size(), 1u);
  EXPECT_TRUE(tr.checks[0].passed) << tr.checks[0].problem;
  const std::string html = html_report({tr}, {"2026-01-01T00:00:00Z", "data/qtg", 1.0});
  EXPECT_NE(html.find("1 of 1 tests passed"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("a &lt;b&gt; title"), std::string::npos);
  EXPECT_EQ(html.find("a <b> title"), std::string::npos);
}

TEST(QtgGuide, EveryTestFileInTheRepositoryLoads) {
  const auto files = find_tests(fedsim::util::data_dir() + "/qtg");
  EXPECT_FALSE(files.empty());
  // deployments and scenarios are named from the source tree, as fedsim-qtg looks them up
  for (const auto& f : files) EXPECT_NO_THROW(load_test(f, {fedsim::util::source_dir()})) << f;
}

TEST(QtgChannels, ReferenceCsvRoundTripAndUnitsInHeaders) {
  Channels c;
  for (int i = 0; i <= 10; ++i) {
    c["tas_kt"].t.push_back(i * 0.5), c["tas_kt"].x.push_back(100 + i);
    c["pitch_deg"].t.push_back(i * 0.5), c["pitch_deg"].x.push_back(-i * 0.25);
  }
  const std::string path = (scratch() / "ref.csv").string();
  write_reference_csv(path, c, {"tas_kt", "pitch_deg"}, "REGRESSION: test", 2);
  const Series s = read_reference_column(path, "pitch_deg");
  ASSERT_EQ(s.t.size(), 6u);  // every 2nd of 11 samples, the last always
  EXPECT_DOUBLE_EQ(s.x.back(), -2.5);
  EXPECT_DOUBLE_EQ(interpolate(s, 0.5), -0.25);  // between two kept samples
  // a header without a unit (not a channel name) is refused, naming the column
  const std::string bad = write("bad.csv", "time_s, airspeed\n0, 100\n1, 101\n");
  try {
    read_reference_column(bad, "airspeed");
    FAIL() << "accepted a column without a unit";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("airspeed"), std::string::npos) << e.what();
  }
  const std::string nan = write("nan.csv", "time_s, tas_kt\n0, 100\n1, nan\n");
  EXPECT_THROW(read_reference_column(nan, "tas_kt"), std::exception);
}

// ---- Federation tests: the ILS approach and autoland (docs/qtg.md) ----

namespace {

const char* kFederation = R"yaml(fedsim_qtg_test: 1
title: 737 autoland
part60_item: "autoland"
aircraft: b737
federation:
  deployment: deploy/qtg/b737-ils-autoland.yaml
runway: {airport: KSFO, runway: 28R}
duration_s: 400
rate_hz: 50
reference:
  kind: criteria
  source: "AC 120-28D touchdown criteria (test data)"
checks:
  - name: localizer
    channel: loc_dots
    measure: max_abs
    while: {channel: height_above_runway_ft, min: 100, max: 1000}
    limits: {max: 1, unit: dots}
  - name: touchdown distance
    channel: beyond_threshold_ft
    measure: value_when
    when_channel: on_ground
    threshold: 0.5
    limits: {min: 200, max: 2700, unit: ft}
)yaml";

std::string federation_error(const std::string& text) {
  try {
    load_test(write("f.yaml", text), {fedsim::util::source_dir()});
    return "";
  } catch (const fedsim::util::ConfigError& e) {
    return e.what();
  }
}

}  // namespace

TEST(QtgFederation, FileLoadsWithLimitsAndWhile) {
  const QtgTest t = load_test(write("f.yaml", kFederation), {fedsim::util::source_dir()});
  ASSERT_TRUE(t.federation);
  EXPECT_NE(t.federation->deployment.find("deploy/qtg/b737-ils-autoland.yaml"), std::string::npos);
  ASSERT_TRUE(t.runway);
  ASSERT_EQ(t.checks.size(), 2u);
  EXPECT_TRUE(t.checks[0].is_limit());
  EXPECT_FALSE(t.checks[0].limit_min);  // one-sided: at most 1 dot
  ASSERT_TRUE(t.checks[0].while_condition);
  EXPECT_EQ(t.checks[0].while_condition->channel, "height_above_runway_ft");
  EXPECT_DOUBLE_EQ(*t.checks[1].limit_min, 200);
  EXPECT_DOUBLE_EQ(*t.checks[1].limit_max, 2700);
  const auto a = federation_arguments(t, "/tmp/x");
  ASSERT_GE(a.size(), 3u);
  EXPECT_EQ(a[0], "run");
  EXPECT_NE(std::find(a.begin(), a.end(), "--in-process"), a.end());
  EXPECT_EQ(std::find(a.begin(), a.end(), "--scenario"), a.end());
  const auto sources = sources_needed(t);
  EXPECT_TRUE(sources.count(ChannelSource::navigation_state));
  EXPECT_TRUE(sources.count(ChannelSource::runway));
  EXPECT_FALSE(sources.count(ChannelSource::autopilot_state));
}

TEST(QtgFederation, FormatErrorsAreNamed) {
  // a federation test takes no start; a fedsim-fly test records no navigation state
  EXPECT_NE(federation_error(replace(kFederation, "runway: {", "start: {trim: level, ktas: 100}\nrunway: {"))
                .find("start"), std::string::npos);
  EXPECT_NE(load_error(replace(kValid, "channel: tas_kt", "channel: loc_dots")).find("federation test only"),
            std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "runway: {airport: KSFO, runway: 28R}\n", ""))
                .find("give runway"), std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "runway: 28R}", "runway: 27X}")).find("runway"), std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "deploy/qtg/b737-ils-autoland.yaml", "deploy/nope.yaml"))
                .find("federation.deployment"), std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "max: 2700, unit: ft", "max: 100, unit: ft")).find("above min"),
            std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "max: 2700, unit: ft", "max: 2700, unit: m")).find("unit"),
            std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "max: 2700, unit: ft", "max: .nan, unit: ft")), "");
  EXPECT_NE(federation_error(replace(kFederation, "{max: 1, unit: dots}", "{max: -1, unit: dots}")).find("above 0"),
            std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "limits: {min: 200", "tolerance: {percent: 5}\n    limits: {min: 200"))
                .find("either limits"), std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "measure: value_when", "measure: value_when\n    while: {channel: on_ground, min: 0, max: 1}"))
                .find("only for the measures"), std::string::npos);
}

TEST(QtgFederation, TheRunwayChannelsMeasureFromTheRunwayCentreline) {
  // The runway channels are fedsim::RunwayCentreline's (common/airports, as fedsim-autoland-mc
  // and the AFCS's landing figures measure; its own tests: runway_centreline_test.cpp).
  // KSFO 28R (data/nav/runways.csv): runway end 37.613538 N 122.35716 W, 4 m, threshold
  // displaced 91 m; 10L's end 37.628742 N 122.39341 W: 3618 m end to end, so the centreline
  // from the 28R threshold is 3527 m (11,572 ft), heading 297.8 deg true
  const fedsim::RunwayTable table = fedsim::RunwayTable::load_default();
  const auto frame = fedsim::RunwayCentreline::from_table(table, "KSFO", "28R");
  const double d2r = M_PI / 180;
  EXPECT_NEAR(frame.length_m(), 3527, 2);
  EXPECT_NEAR(table.at("KSFO", "28R").elevation_m, 4.0, 1e-9);  // height_above_runway_ft's zero
  EXPECT_NEAR(frame.beyond_threshold_m(37.613538 * d2r, -122.35716 * d2r), -91, 0.5);
  EXPECT_NEAR(frame.left_m(37.613538 * d2r, -122.35716 * d2r), 0, 0.5);
  EXPECT_NEAR(frame.beyond_threshold_m(37.628742 * d2r, -122.39341 * d2r), frame.length_m(), 1e-6);
  EXPECT_NEAR(frame.left_m(37.628742 * d2r, -122.39341 * d2r), 0, 1e-6);
  // 100 m north of the centreline is right of it, landing on 298 deg: the left normal points to
  // 298 - 90 = 208 deg, whose north component is cos(208 deg) = -0.883
  const double north = 100.0 / 6378137.0 / d2r;  // about 100 m of latitude
  EXPECT_NEAR(frame.left_m((37.613538 + north) * d2r, -122.35716 * d2r), -100 * 0.883, 2);
  // KSFO has no 27; KCOS has 17L but not 35R (the table's): the centreline needs both ends, and
  // the test file's runway field says which is missing
  EXPECT_THROW(fedsim::RunwayCentreline::from_table(table, "KSFO", "27"), std::invalid_argument);
  EXPECT_THROW(fedsim::RunwayCentreline::from_table(table, "KCOS", "17L"), std::invalid_argument);
  EXPECT_NE(federation_error(replace(kFederation, "runway: 28R}", "runway: 27}")).find("has no runway '27'"),
            std::string::npos);
  EXPECT_NE(federation_error(replace(kFederation, "{airport: KSFO, runway: 28R}", "{airport: KCOS, runway: 17L}"))
                .find("KCOS 17L: no opposite end 35R"),
            std::string::npos);
}

TEST(QtgFederation, LimitsMaxAbsAndWhileCondition) {
  // a deviation that is 0.3 dots on the approach and 2 dots on the ground roll (height 0)
  Channels flown;
  for (int i = 0; i <= 100; ++i) {
    const double t = i;
    flown["height_above_runway_ft"].t.push_back(t);
    flown["height_above_runway_ft"].x.push_back(t < 80 ? 2000 - 25 * t : 0);
    flown["loc_dots"].t.push_back(t);
    flown["loc_dots"].x.push_back(t < 80 ? (t == 60 ? -0.3 : 0.1) : 2.0);
  }
  Check c;
  c.name = "localizer";
  c.channel = "loc_dots";
  c.measure = Measure::max_abs;
  c.limit_max = 1.0;  // at most 1 dot
  c.tolerance.unit = "dots";
  c.while_condition = Condition{"height_above_runway_ft", 100, 1000};
  auto r = evaluate_check(c, flown, nullptr, 100);
  EXPECT_TRUE(r.passed) << r.problem;
  EXPECT_NEAR(*r.measured, 0.3, 1e-12);  // |-0.3| at 60 s (height 500 ft); the ground roll left out
  EXPECT_NEAR(r.worst_time_s, 60, 1e-12);
  EXPECT_NEAR(r.worst_ratio, 0.3, 1e-12);  // 30 % of the limit used
  // the negative controls: without the condition the ground roll's 2 dots break the limit; a
  // tighter limit fails; a condition no sample meets is a problem, not a pass
  c.while_condition.reset();
  EXPECT_FALSE(evaluate_check(c, flown, nullptr, 100).passed);
  c.while_condition = Condition{"height_above_runway_ft", 100, 1000};
  c.limit_max = 0.2;
  EXPECT_FALSE(evaluate_check(c, flown, nullptr, 100).passed);
  c.while_condition = Condition{"height_above_runway_ft", 5000, 6000};
  r = evaluate_check(c, flown, nullptr, 100);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.problem.find("no sample while"), std::string::npos) << r.problem;
  c.while_condition = Condition{"gs_dots", 0, 1};
  r = evaluate_check(c, flown, nullptr, 100);
  EXPECT_NE(r.problem.find("gs_dots"), std::string::npos) << r.problem;
}

TEST(QtgFederation, LimitReportShowsTheRange) {
  QtgTest t = load_test(write("f.yaml", kFederation), {fedsim::util::source_dir()});
  Channels flown;
  for (int i = 0; i <= 400; ++i) {
    const double t_s = i;
    flown["on_ground"].t.push_back(t_s), flown["on_ground"].x.push_back(t_s >= 300 ? 1 : 0);
    flown["beyond_threshold_ft"].t.push_back(t_s), flown["beyond_threshold_ft"].x.push_back(230 * (t_s - 295));
    flown["height_above_runway_ft"].t.push_back(t_s), flown["height_above_runway_ft"].x.push_back(std::max(0.0, 3000 - 10 * t_s));
    flown["loc_dots"].t.push_back(t_s), flown["loc_dots"].x.push_back(0.05);
  }
  TestResult tr;
  tr.test = t;
  tr.ran = true;
  tr.checks = evaluate_test(t, flown);
  ASSERT_EQ(tr.checks.size(), 2u);
  EXPECT_TRUE(tr.checks[1].passed);
  EXPECT_NEAR(*tr.checks[1].measured, 230 * 4.5, 1e-9);  // on_ground crosses 0.5 at 299.5 s
  const std::string html = html_report({tr}, {"2026-01-01T00:00:00Z", "data/qtg", 1.0});
  EXPECT_NE(html.find("200 .. 2700 ft"), std::string::npos);
  EXPECT_NE(html.find("≤ 1 dots"), std::string::npos);
  EXPECT_NE(html.find("inside, "), std::string::npos);
  EXPECT_NE(html.find("fedsim run "), std::string::npos);
  EXPECT_NE(html.find("KSFO 28R"), std::string::npos);
}
