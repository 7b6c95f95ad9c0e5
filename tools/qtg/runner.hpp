// Flying a QTG test: fedsim-fly as a child process (its own batch program, so a QTG run flies
// exactly what a user can fly by hand), its arguments built from the validated test.
#pragma once

#include <string>
#include <vector>

#include "tools/qtg/compare.hpp"

namespace fedsim::qtg {

/// fedsim-fly's argument list (after the program name) for a test, recording into `out_dir`.
std::vector<std::string> fly_arguments(const QtgTest& test, const std::string& out_dir);

/// Flies the test with `fly_program` into `out_dir` and evaluates it. Never throws for the
/// test's own failures (they are in the result); `log` gets fedsim-fly's output.
TestResult run_test(const QtgTest& test, const std::string& fly_program, const std::string& out_dir);

/// Writes the time-history reference of a regression test from its flown channels (every
/// `every`-th frame): the columns its time_history checks compare. Returns the file written,
/// or "" when the test has no such check.
std::string record_regression(const TestResult& result, const Channels& flown, int every);

}  // namespace fedsim::qtg
