// A runway's centreline in runway-relative coordinates: distance beyond the landing threshold
// and distance left of the centreline, in the local tangent plane at the landing threshold. The
// one measure of "where on the runway" that the AFCS's landing figures, fedsim-autoland-mc and
// the QTG's runway channels share (so their numbers agree to the bit).
#pragma once

#include "common/airports/runway_table.hpp"

#include <string>

namespace fedsim {

/// The designator of a runway's other end, without a leading zero: 28R -> 10L, 01 -> 19,
/// 9C -> 27C, 19R -> 1L (numbers differ by 18, L and R swap, C stays). Throws
/// std::invalid_argument for a designator that is not 1..36 with an optional L, C or R.
std::string reciprocal_runway(const std::string& designator);

/// A runway's centreline: from its landing threshold to the opposite end's threshold, in the
/// local tangent plane at the landing threshold (GeographicLib LocalCartesian, height 0).
class RunwayCentreline {
 public:
  /// Throws std::invalid_argument when the two points coincide.
  RunwayCentreline(double threshold_lat_rad, double threshold_lon_rad, double far_lat_rad, double far_lon_rad);
  /// The landing end `runway` of `airport` and its opposite end in the table (KSFO 28R and 10L;
  /// a one-digit end may be spelt 1L or 01L). Throws std::invalid_argument naming what is
  /// missing: the landing end (RunwayTable::at's message), or the opposite end ("KSFO 27: no
  /// opposite end 9 in the runway table (the centreline needs both ends)").
  static RunwayCentreline from_table(const RunwayTable& table, const std::string& airport, const std::string& runway);
  /// Threshold to the far end's threshold [m].
  double length_m() const { return length_m_; }
  /// Distance beyond the threshold along the centreline [m].
  double beyond_threshold_m(double lat_rad, double lon_rad) const;
  /// Distance left of the centreline, seen landing [m].
  double left_m(double lat_rad, double lon_rad) const;

 private:
  void plane_coordinates(double lat_rad, double lon_rad, double& east_m, double& north_m) const;
  double lat0_deg_ = 0.0, lon0_deg_ = 0.0;
  double along_east_ = 0.0, along_north_ = 0.0;  // unit vector of the landing direction
  double length_m_ = 0.0;
};

}  // namespace fedsim
