// The QTG library alone: test-file validation (file:line: field errors), the measures on
// synthetic signals with known period and damping (and signals without an oscillation, the
// negative controls), the comparison and the report.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

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
  const auto has = [&](const std::string& k, const std::string& v) {
    for (std::size_t i = 0; i + 1 < a.size(); ++i)
      if (a[i] == k && a[i + 1] == v) return true;
    return false;
  };
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
  const auto files = find_tests(FEDSIM_QTG_DATA_DIR);
  EXPECT_FALSE(files.empty());
  for (const auto& f : files) EXPECT_NO_THROW(load_test(f)) << f;
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
