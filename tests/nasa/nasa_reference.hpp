// NASA TM-2015-218675 check-case reference data: loads every simulation tool's time history of a
// case (NASA units, NASA column names) into SI channels and gives their min/max envelope.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "time_history.hpp"

namespace fedsim::flight::nasa {

/// One NASA tool's run of a case, converted to SI.
struct NasaRun {
  std::string name;  // e.g. "sim_04"
  TimeHistory history;
};

/// Range of NASA's answers at one time.
struct Envelope {
  double low = 0.0;
  double high = 0.0;
  int runs = 0;  // number of tools that report the channel
};

class NasaReference {
 public:
  /// Reads every "<case>_sim_NN.csv" in a folder. Throws if there is none.
  static NasaReference load(const std::string& case_folder);
  /// Converts one NASA CSV: ft -> m, deg -> rad, ft/s -> m/s; lat/lon also become north_m and
  /// east_m. Channels a tool did not record are absent from its history.
  static TimeHistory read_nasa_csv(const std::string& path);

  const std::vector<NasaRun>& runs() const { return runs_; }
  /// Sample times of the first run (all NASA runs share the 0.1 s grid).
  const std::vector<double>& times() const { return runs_.front().history.times(); }

  /// Envelope of a channel at time t. For angles every run's value is first wrapped into
  /// (reference - pi, reference + pi], so that +179 deg and -179 deg are 2 deg apart.
  Envelope envelope(const std::string& channel, double t_s, bool is_angle,
                    double angle_reference_rad) const;

  /// Leaves one tool's channel out of the envelope (a documented defect of that tool's output,
  /// e.g. a quantity recorded in another convention). Throws if the run does not exist.
  void exclude(const std::string& run_name, const std::string& channel);
  bool excluded(const std::string& run_name, const std::string& channel) const;

 private:
  std::vector<NasaRun> runs_;
  std::vector<std::pair<std::string, std::string>> exclusions_;  // (run, channel)
};

}  // namespace fedsim::flight::nasa
