// A GPS receiver (seed 6.11): each update measures the pseudoranges of the satellites above the
// mask (pseudorange_model.hpp) at the true antenna position and solves for position and clock
// (least_squares_fix.hpp), starting from the last valid fix or, without one, from the earth's
// centre.
//
// Inputs per update: time since the constellation epoch [s], the true antenna position (ECEF,
// m; the CG's position_ecef_m of the AircraftState), and whether GPS is denied.
// Output: a GpsFix. valid is true only for a solution of this epoch from 4 or more
// satellites; otherwise (denied, too few satellites, singular geometry, no convergence) valid is
// false and every position field is NaN: a stale fix is never passed on as valid.
// Receiver clock: bias(t) = clock_bias_s + clock_drift_sps * t (deterministic).
#pragma once

#include "common/geodesy/wgs84.hpp"
#include "federates/nav/model/gps/gps_constellation.hpp"
#include "federates/nav/model/gps/least_squares_fix.hpp"
#include "federates/nav/model/gps/pseudorange_model.hpp"

#include <optional>

namespace fedsim::nav {

struct GpsReceiverConfig {
  PseudorangeConfig pseudoranges;
  double clock_bias_s = 1e-4;       // receiver clock offset at t = 0 [s], |.| <= 0.1
  double clock_drift_sps = 0.0;     // [s/s], |.| <= 1e-5
  LeastSquaresSettings solver;

  void check() const;
};

struct GpsFix {
  bool valid = false;
  FixStatus status = FixStatus::kTooFewSatellites;
  int satellites_visible = 0;       // above the mask
  int satellites_used = 0;          // in the solution (0 unless valid)
  Eigen::Vector3d position_ecef_m;  // NaN unless valid
  GeodeticPosition position;        // NaN unless valid
  double clock_bias_s = 0.0;        // estimated receiver clock bias (NaN unless valid) [s]
  DilutionOfPrecision dop;          // NaN unless valid
  double residual_rms_m = 0.0;      // NaN unless valid
  int iterations = 0;
};

class GpsReceiver {
 public:
  explicit GpsReceiver(GpsConstellation constellation, const GpsReceiverConfig& config = {});

  GpsFix update(double time_since_epoch_s, const Eigen::Vector3d& true_position_ecef_m,
                bool denied = false);

  /// The true receiver clock bias at t [s].
  double true_clock_bias_s(double time_since_epoch_s) const;
  const GpsConstellation& constellation() const { return constellation_; }
  const PseudorangeModel& pseudorange_model() const { return pseudoranges_; }

 private:
  GpsConstellation constellation_;
  GpsReceiverConfig config_;
  PseudorangeModel pseudoranges_;
  std::optional<LeastSquaresFix> last_valid_;
};

}  // namespace fedsim::nav
