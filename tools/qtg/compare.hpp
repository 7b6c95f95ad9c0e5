// Comparing a flown run with its reference: each check of a test gives a pass/fail, the measured
// and reference values and the worst excursion, plus what the report plots.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tools/qtg/channels.hpp"
#include "tools/qtg/measures.hpp"
#include "tools/qtg/qtg_test.hpp"

namespace fedsim::qtg {

struct CheckResult {
  Check check;
  bool passed = false;
  std::string problem;            // why it could not be measured (then passed is false)
  std::optional<double> measured;  // derived measures
  std::optional<double> reference;
  double band = 0;                 // the allowed deviation at the reference value
  double worst_excursion = 0;      // signed simulator - reference where |dev| / band is largest
  double worst_time_s = 0;         // time of the worst excursion (time histories), or of the measure
  double worst_ratio = 0;          // |worst excursion| / band: <= 1 passes
  // for the plot
  Series simulated;                // the channel over the run
  Series reference_series;         // time histories: the reference column
  std::vector<Extremum> marks;     // extrema used (oscillations) or the measured point
};

/// Evaluates one check against the flown channels; `reference_series` is the reference column
/// for a time-history check (ignored otherwise). Never throws for a bad run: a check that
/// cannot be measured fails with `problem` set.
CheckResult evaluate_check(const Check& check, const Channels& flown, const Series* reference_series,
                           double duration_s);

struct TestResult {
  QtgTest test;
  bool ran = false;       // fedsim-fly or the federation flew it (or its recording was read)
  std::string problem;    // why it did not run (exit code and message)
  std::vector<CheckResult> checks;
  double wall_s = 0;
  std::string out_dir;         // the recording's folder
  bool from_recording = false;  // evaluated from an existing recording (--recording), not flown
  bool passed() const;
};

/// Evaluates every check of a test against the channels recorded for it (reading the
/// reference CSV for time-history checks; a bad CSV fails that check with its message).
std::vector<CheckResult> evaluate_test(const QtgTest& test, const Channels& flown);

}  // namespace fedsim::qtg
