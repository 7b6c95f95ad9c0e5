#include "visual/model/montage.hpp"

#include <gtest/gtest.h>

namespace fedsim::visual {
namespace {

picture::Image filled(int width, int height, picture::Rgba8 colour) {
  picture::Image image(width, height);
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) image.set(column, row, colour);
  }
  return image;
}

bool same(picture::Rgba8 a, picture::Rgba8 b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

TEST(Montage, PutsTheChannelsSideBySideInOrderWithTheGapBetween) {
  const picture::Rgba8 red{255, 0, 0, 255}, green{0, 255, 0, 255}, blue{0, 0, 255, 255}, grey{9, 9, 9, 255};
  const picture::Image out = side_by_side({filled(3, 2, red), filled(4, 2, green), filled(2, 2, blue)}, 1, grey);
  ASSERT_EQ(out.width_px, 3 + 1 + 4 + 1 + 2);
  ASSERT_EQ(out.height_px, 2);
  EXPECT_TRUE(same(out.at(0, 1), red));
  EXPECT_TRUE(same(out.at(2, 0), red));
  EXPECT_TRUE(same(out.at(3, 0), grey));  // the gap
  EXPECT_TRUE(same(out.at(4, 1), green));
  EXPECT_TRUE(same(out.at(7, 0), green));
  EXPECT_TRUE(same(out.at(8, 1), grey));
  EXPECT_TRUE(same(out.at(9, 0), blue));
  EXPECT_TRUE(same(out.at(10, 1), blue));
  // Without a gap the channels meet edge to edge.
  const picture::Image joined = side_by_side({filled(3, 2, red), filled(2, 2, blue)});
  EXPECT_EQ(joined.width_px, 5);
  EXPECT_TRUE(same(joined.at(2, 0), red));
  EXPECT_TRUE(same(joined.at(3, 0), blue));
}

TEST(Montage, RefusesImagesOfDifferentHeightsAndAnEmptyList) {
  try {
    side_by_side({picture::Image(4, 3), picture::Image(4, 3), picture::Image(4, 2)});
    FAIL() << "heights differ";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "montage: image 3 is 2 px high, the first 3 px");
  }
  EXPECT_THROW(side_by_side({}), std::invalid_argument);
  EXPECT_THROW(side_by_side({picture::Image(1, 1)}, -1), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::visual
