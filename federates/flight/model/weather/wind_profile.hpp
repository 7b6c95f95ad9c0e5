// Steady wind: speed and meteorological "from" direction tabulated against altitude, as a
// north-east-down wind vector.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

/// Steady (mean) wind as a function of altitude (executive step 2).
///
/// Input:  altitude (m; the same reference as the table, normally above mean sea level).
/// Output: wind_ned_mps, the velocity of the air mass over the ground in NED (m/s); the wind
///         speed (m/s) and the direction it blows FROM (rad, true, clockwise from north).
///
/// Meteorological convention: wind "from" psi_w blows toward psi_w + 180 deg, so
///   wind_ned = -V (cos psi_w, sin psi_w, 0).
/// Between table rows speed and direction are interpolated linearly, the direction along the
/// shorter way round (350 deg to 010 deg passes through north). Outside the table the end rows
/// hold (clamped). Consecutive rows are a linear shear layer; an empty table is calm air.
/// Stateless, no allocation after construction.
class WindProfile {
 public:
  struct Params {
    std::vector<double> altitude_m;          ///< strictly increasing (may be empty: calm)
    std::vector<double> speed_mps;           ///< >= 0, one per altitude
    std::vector<double> from_direction_rad;  ///< true, clockwise from north, one per altitude

    /// Throws std::invalid_argument naming the bad field.
    void validate() const;
  };

  struct Outputs {
    Eigen::Vector3d wind_ned_mps = Eigen::Vector3d::Zero();
    double speed_mps = 0.0;
    double from_direction_rad = 0.0;  ///< in [0, 2 pi)
  };

  WindProfile() = default;  ///< calm
  explicit WindProfile(Params params);

  Outputs at(double altitude_m) const;
  const Params& params() const { return params_; }

  /// The NED wind vector of a wind of speed_mps blowing from from_direction_rad.
  static Eigen::Vector3d ned_from(double speed_mps, double from_direction_rad);

 private:
  Params params_;
  Table1D speed_;
  Table1D direction_;  // unwrapped: consecutive rows differ by at most pi
};

}  // namespace fedsim::flight
