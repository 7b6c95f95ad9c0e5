// The R*Tree search boxes: sizes against the ellipsoid's radii, the antimeridian split, the
// poles, and the argument checks.
#include "common/navdb/search_box.hpp"

#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <gtest/gtest.h>

#include <stdexcept>

namespace fedsim::nav {
namespace {

using units::kDegToRad;

bool box_holds(const SearchBoxes& boxes, double lat_deg, double lon_deg) {
  for (std::size_t i = 0; i < boxes.count; ++i) {
    const LatLonBox& b = boxes.boxes[i];
    if (lat_deg >= b.min_lat_deg && lat_deg <= b.max_lat_deg && lon_deg >= b.min_lon_deg &&
        lon_deg <= b.max_lon_deg) {
      return true;
    }
  }
  return false;
}

TEST(SearchBox, HoldsTheCircleAndIsNotMuchLarger) {
  const auto& geodesic = GeographicLib::Geodesic::WGS84();
  const double radius_m = 100e3;
  const SearchBoxes boxes = search_boxes(45.0 * kDegToRad, 10.0 * kDegToRad, radius_m);
  ASSERT_EQ(boxes.count, 1u);
  // Points on the circle (GeographicLib direct problem) lie inside the box...
  for (double azimuth = 0.0; azimuth < 360.0; azimuth += 5.0) {
    double lat = 0.0, lon = 0.0;
    geodesic.Direct(45.0, 10.0, azimuth, radius_m, lat, lon);
    EXPECT_TRUE(box_holds(boxes, lat, lon)) << azimuth;
  }
  // ...and the box is at most a few per cent larger than the circle's extent north-south.
  double north_lat = 0.0, north_lon = 0.0;
  geodesic.Direct(45.0, 10.0, 0.0, radius_m, north_lat, north_lon);
  EXPECT_LT(boxes.boxes[0].max_lat_deg - 45.0, 1.02 * (north_lat - 45.0));
}

TEST(SearchBox, SplitsAtTheAntimeridian) {
  const SearchBoxes east = search_boxes(0.0, 179.9 * kDegToRad, 50e3);
  ASSERT_EQ(east.count, 2u);
  EXPECT_TRUE(box_holds(east, 0.0, -179.9));  // 22 km across the antimeridian
  EXPECT_TRUE(box_holds(east, 0.0, 179.6));
  EXPECT_FALSE(box_holds(east, 0.0, 0.0));
  const SearchBoxes west = search_boxes(10.0 * kDegToRad, -179.95 * kDegToRad, 50e3);
  ASSERT_EQ(west.count, 2u);
  EXPECT_TRUE(box_holds(west, 10.0, 179.9));
  // Negative control: far from the antimeridian one box does.
  EXPECT_EQ(search_boxes(0.0, 170.0 * kDegToRad, 50e3).count, 1u);
}

TEST(SearchBox, TakesEveryLongitudeAtAPole) {
  const SearchBoxes boxes = search_boxes(89.8 * kDegToRad, 0.0, 50e3);
  ASSERT_EQ(boxes.count, 1u);
  EXPECT_DOUBLE_EQ(boxes.boxes[0].max_lat_deg, 90.0);
  EXPECT_DOUBLE_EQ(boxes.boxes[0].min_lon_deg, -180.0);
  EXPECT_DOUBLE_EQ(boxes.boxes[0].max_lon_deg, 180.0);
  EXPECT_TRUE(box_holds(boxes, 89.9, 179.0));  // across the pole, 33 km away
  const SearchBoxes south = search_boxes(-90.0 * kDegToRad, 0.0, 1e3);
  EXPECT_DOUBLE_EQ(south.boxes[0].min_lat_deg, -90.0);
}

TEST(SearchBox, RejectsBadArguments) {
  EXPECT_THROW(search_boxes(std::nan(""), 0.0, 1e3), std::invalid_argument);
  EXPECT_THROW(search_boxes(0.0, INFINITY, 1e3), std::invalid_argument);
  EXPECT_THROW(search_boxes(1.6, 0.0, 1e3), std::invalid_argument);
  EXPECT_THROW(search_boxes(0.0, 3.2, 1e3), std::invalid_argument);
  EXPECT_THROW(search_boxes(0.0, 0.0, -1.0), std::invalid_argument);
  EXPECT_THROW(search_boxes(0.0, 0.0, 3e7), std::invalid_argument);
  EXPECT_THROW(search_boxes(0.0, 0.0, std::nan("")), std::invalid_argument);
  EXPECT_NO_THROW(search_boxes(0.0, 0.0, 0.0));
}

}  // namespace
}  // namespace fedsim::nav
