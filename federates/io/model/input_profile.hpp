// A scripted input profile: a CSV time series of named control channels.
//
//   # comments and blank lines are ignored
//   time_s, elevator, throttle
//   0.0,    0.0,      0.7
//   2.0,    0.0,      0.7     <- values are interpolated linearly between rows (ramps)
//   2.0,    0.1,      0.7     <- a repeated time is a step
//   3.0,    0.1,      0.7
//   3.0,   -0.1,      0.7     <- step down: together a doublet
//
// Before the first row the first row's values hold; after the last row the last values hold.
// Validation on load: every problem is reported as "file:line: ..." and nothing is flown.
#pragma once

#include "common/csv/csv_reader.hpp"
#include "io/model/input_source.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::io {

class ProfileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InputProfile : public InputSource {
 public:
  static InputProfile load_file(const std::string& path);
  /// `origin` names the text in error messages.
  static InputProfile parse(const std::string& text, const std::string& origin);
  /// Reads a profile from an open CSV reader (throws csv::CsvError naming file and line).
  static InputProfile parse(csv::CsvReader& reader);

  void sample(double sim_time_s, ControlInputs& controls) override;
  std::string describe() const override;

  /// Value of one column at time t (linear interpolation, steps at repeated times).
  double value(std::size_t column, double t) const;
  /// Adds the profile's values to `base` instead of replacing (for --inputs-relative).
  void sample_relative(double sim_time_s, const ControlInputs& base, ControlInputs& out) const;

  const std::vector<std::string>& column_names() const { return names_; }
  bool drives(Channel channel) const;
  double end_time_s() const { return times_.empty() ? 0.0 : times_.back(); }

 private:
  std::string origin_;
  std::vector<std::string> names_;                 // column names after time_s
  std::vector<std::vector<Channel>> targets_;      // channels each column drives
  std::vector<double> times_;                      // row times, non-decreasing
  std::vector<std::vector<double>> rows_;          // [row][column]
  mutable std::size_t cursor_ = 0;                 // search hint: time mostly moves forward
};

}  // namespace fedsim::io
