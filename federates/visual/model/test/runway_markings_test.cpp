// Runway markings against ICAO Annex 14 Vol I Chapter 5.2's figures (the numbers below are the
// standard's, not the code's): stripes by width, aiming point and touchdown zone by landing
// distance, designations, centreline pattern.
#include "visual/model/runway_markings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fedsim::visual {
namespace {

struct Extent {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
};

Extent extent_of(const Quad2& q) {
  Extent e;
  for (const auto& c : q.corners) {
    e.x0 = std::min(e.x0, c.x());
    e.x1 = std::max(e.x1, c.x());
    e.y0 = std::min(e.y0, c.y());
    e.y1 = std::max(e.y1, c.y());
  }
  return e;
}

TEST(RunwayMarkings, ThresholdStripeCountByWidth) {  // 5.2.4.6
  EXPECT_EQ(threshold_stripe_count(18.0), 4);
  EXPECT_EQ(threshold_stripe_count(23.0), 6);
  EXPECT_EQ(threshold_stripe_count(30.0), 8);
  EXPECT_EQ(threshold_stripe_count(45.0), 12);
  EXPECT_EQ(threshold_stripe_count(60.0), 16);
  EXPECT_EQ(threshold_stripe_count(61.0), 16);  // KSFO's 200 ft runways
}

TEST(RunwayMarkings, ThresholdStripesFillTheSpanWithADoubleCentreGap) {
  EndMarkingInput in;
  in.designator = parse_designator("28R", "test");
  in.width_m = 45.0;
  in.landing_distance_m = 3000.0;
  const EndMarkings m = end_markings(in);
  std::vector<Extent> stripes;
  for (const auto& q : m.quads) {
    const Extent e = extent_of(q);
    if (std::abs(e.x0 - 6.0) < 1e-9 && std::abs(e.x1 - 36.0) < 1e-9) stripes.push_back(e);
  }
  ASSERT_EQ(stripes.size(), 12u);
  std::sort(stripes.begin(), stripes.end(), [](auto& a, auto& b) { return a.y0 < b.y0; });
  // Within 3 m of the 45 m runway's edges (19.5 m < 27 m from the centreline).
  EXPECT_NEAR(stripes.front().y0, -19.5, 1e-9);
  EXPECT_NEAR(stripes.back().y1, 19.5, 1e-9);
  const double w = stripes[0].y1 - stripes[0].y0;
  EXPECT_NEAR(w, 1.625, 1e-9);  // "approximately 1.80 m", equal stripes and gaps
  for (std::size_t i = 0; i + 1 < stripes.size(); ++i) {
    const double gap = stripes[i + 1].y0 - stripes[i].y1;
    EXPECT_NEAR(gap, i == 5 ? 2.0 * w : w, 1e-9) << "gap " << i;  // double at the centreline
  }
  EXPECT_EQ(m.threshold_stripes, 12);
}

TEST(RunwayMarkings, AimingPointByLandingDistance) {  // Table 5-1
  EXPECT_DOUBLE_EQ(aiming_point_layout(700.0).start_m, 150.0);
  EXPECT_DOUBLE_EQ(aiming_point_layout(1000.0).start_m, 250.0);
  EXPECT_DOUBLE_EQ(aiming_point_layout(2000.0).start_m, 300.0);
  EXPECT_DOUBLE_EQ(aiming_point_layout(2400.0).start_m, 400.0);
  EXPECT_DOUBLE_EQ(aiming_point_layout(3500.0).inner_spacing_m, 18.0);
  EXPECT_DOUBLE_EQ(aiming_point_layout(1000.0).inner_spacing_m, 9.0);
}

TEST(RunwayMarkings, TouchdownZonePairsSkipTheAimingPoint) {  // Table 5-2, 5.2.6.3
  EXPECT_EQ(touchdown_zone_pair_count(800.0), 1);
  EXPECT_EQ(touchdown_zone_pair_count(1000.0), 2);
  EXPECT_EQ(touchdown_zone_pair_count(1400.0), 3);
  EXPECT_EQ(touchdown_zone_pair_count(2000.0), 4);
  EXPECT_EQ(touchdown_zone_pair_count(3000.0), 6);
  EndMarkingInput in;
  in.designator = parse_designator("28R", "test");
  in.width_m = 61.0;
  in.landing_distance_m = 3527.0;
  in.category = ApproachCategory::kPrecisionCatIIorIII;
  const EndMarkings m = end_markings(in);
  // 150..900 m every 150 m, less the pair at 450 m (within 50 m of the aiming point at 400 m).
  EXPECT_EQ(m.touchdown_zone_starts_m, (std::vector<double>{150.0, 300.0, 600.0, 750.0, 900.0}));
  ASSERT_TRUE(m.aiming_point.has_value());
  EXPECT_DOUBLE_EQ(m.aiming_point->start_m, 400.0);
  // A visual runway has neither (negative control).
  in.category = ApproachCategory::kVisual;
  const EndMarkings visual = end_markings(in);
  EXPECT_FALSE(visual.aiming_point.has_value());
  EXPECT_TRUE(visual.touchdown_zone_starts_m.empty());
}

TEST(RunwayMarkings, DesignationLetterNearerTheThresholdThanTheNumber) {
  EndMarkingInput in;
  in.designator = parse_designator("28R", "test");
  const EndMarkings with_letter = end_markings(in);
  in.designator = parse_designator("28", "test");
  const EndMarkings without = end_markings(in);
  // 36 m of stripes + 12 m: the letter 48..57 m, the number from 60 m, 9 m high.
  EXPECT_DOUBLE_EQ(with_letter.designation_end_m, 69.0);
  EXPECT_DOUBLE_EQ(without.designation_end_m, 57.0);
  EXPECT_GT(with_letter.quads.size(), without.quads.size());
}

TEST(RunwayDesignator, ParsesAndFindsTheReciprocal) {
  EXPECT_EQ(parse_designator("28R", "t").reciprocal(), "10L");
  EXPECT_EQ(parse_designator("1L", "t").reciprocal(), "19R");
  EXPECT_EQ(parse_designator("09", "t").reciprocal(), "27");
  EXPECT_EQ(parse_designator("36", "t").reciprocal(), "18");
  EXPECT_EQ(parse_designator("18C", "t").reciprocal(), "36C");
  EXPECT_EQ(parse_designator("1L", "t").painted_number(), "01");  // Annex 14 5.2.2.4
  EXPECT_THROW(parse_designator("H1", "KSFO"), std::invalid_argument);
  EXPECT_THROW(parse_designator("37", "KSFO"), std::invalid_argument);
  EXPECT_THROW(parse_designator("28X", "KSFO"), std::invalid_argument);
  try {
    parse_designator("NW", "runway end KXXX NW");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("runway end KXXX NW: field 'runway'"), std::string::npos);
  }
}

TEST(RunwayMarkings, CentrelineStripesAndGapsPerAnnex14) {  // 5.2.3.4
  const auto stripes =
      centreline_stripes(80.0, 3400.0, centreline_width_m(ApproachCategory::kPrecisionCatIIorIII));
  ASSERT_GT(stripes.size(), 60u);
  for (std::size_t i = 0; i < stripes.size(); ++i) {
    const Extent e = extent_of(stripes[i]);
    EXPECT_NEAR(e.x1 - e.x0, 30.0, 1e-9);
    EXPECT_NEAR(e.y1 - e.y0, 0.90, 1e-9);
    EXPECT_GE(e.x0, 80.0);
    EXPECT_LE(e.x1, 3400.0);
    if (i > 0) {
      EXPECT_NEAR(e.x0 - extent_of(stripes[i - 1]).x1, 20.0, 1e-9);
    }
  }
  EXPECT_DOUBLE_EQ(centreline_width_m(ApproachCategory::kPrecisionCatI), 0.45);
  EXPECT_DOUBLE_EQ(centreline_width_m(ApproachCategory::kVisual), 0.30);
}

TEST(RunwayMarkings, RejectsABadWidth) {
  EndMarkingInput in;
  in.designator = parse_designator("28R", "test");
  in.width_m = std::nan("");
  EXPECT_THROW(end_markings(in), std::invalid_argument);
  in.width_m = 2.0;
  EXPECT_THROW(end_markings(in), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::visual
