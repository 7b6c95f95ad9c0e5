// Flying a QTG test: fedsim-fly as a child process (its own batch program, so a QTG run flies
// exactly what a user can fly by hand), its arguments built from the validated test.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "tools/qtg/compare.hpp"

namespace fedsim::qtg {

/// fedsim-fly's argument list (after the program name) for a test, recording into `out_dir`.
std::vector<std::string> fly_arguments(const QtgTest& test, const std::string& out_dir);

/// `fedsim`'s argument list (after the program name) for a federation test: its deployment run
/// in-process (with its scenario), recording into `out_dir`.
std::vector<std::string> federation_arguments(const QtgTest& test, const std::string& out_dir);

/// The programs a QTG run starts.
struct Programs {
  std::string fly;     // fedsim-fly: the fedsim-fly tests
  std::string fedsim;  // fedsim: `fedsim run --in-process` for the federation tests
};

/// Flies the test (fedsim-fly, or its federation in-process through fedsim) into `out_dir` and
/// evaluates it. Never throws for the test's own failures (they are in the result); the
/// program's output goes to `out_dir`.log.
TestResult run_test(const QtgTest& test, const Programs& programs, const std::string& out_dir);

/// Evaluates the test's checks against the recording in `dir` (fedsim-fly's, or a `fedsim run`
/// recorder's CSVs) without flying. The result names a missing or bad file, and fails a
/// recording that is not the test's run: one that starts after 1 s, ends before duration_s, or
/// whose frames are not 1 / rate_hz apart.
TestResult evaluate_recording(const QtgTest& test, const std::string& dir);

/// The recorded sources the test's checks read (channels, when and while channels).
std::set<ChannelSource> sources_needed(const QtgTest& test);

/// Writes the time-history reference of a regression test from its flown channels (every
/// `every`-th frame): the columns its time_history checks compare. Returns the file written,
/// or "" when the test has no such check.
std::string record_regression(const TestResult& result, const Channels& flown, int every);

}  // namespace fedsim::qtg
