#include "visual/model/runway_markings.hpp"

#include "common/util/input_checks.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::visual {

namespace {

constexpr double kStripeStartM = 6.0;               // 5.2.4.5
constexpr double kStripeLengthM = 30.0;             // 5.2.4.5
constexpr double kEdgeClearanceM = 3.0;             // 5.2.4.7: to within 3 m of the edge
constexpr double kMaxHalfSpanM = 27.0;              // 5.2.4.7: or 27 m from the centreline
constexpr double kDesignationGapM = 12.0;           // beyond the stripes (Figure 5-2)
constexpr double kLetterNumberGapM = 3.0;           // between the letter and the number
constexpr double kGlyphGapM = 0.75 * kGlyphWidthM;  // between the two digits
constexpr double kCentrelineStripeM = 30.0;         // 5.2.3.4
constexpr double kCentrelineGapM = 20.0;            // 5.2.3.4
constexpr double kCentrelineClearanceM = 12.0;      // from a designation to the first stripe
constexpr double kTdzLengthM = 22.5;                // 5.2.6.5 pattern A
constexpr double kTdzWidthM = 3.0;                  // 5.2.6.5 pattern A
constexpr double kTdzIntervalM = 150.0;             // 5.2.6.3
constexpr double kTdzAimingClearanceM = 50.0;       // 5.2.6.3
constexpr double kTransverseStripeM = 1.8;          // Figure 5-4
constexpr double kPieceM = 50.0;                    // longest quad laid on the curved earth

Quad2 rect(double x0, double y0, double x1, double y1) {
  return {{Eigen::Vector2d(x0, y0), Eigen::Vector2d(x1, y0), Eigen::Vector2d(x1, y1),
           Eigen::Vector2d(x0, y1)}};
}

// A pair of rectangles symmetric about the centreline, inner sides `inner` apart.
void add_pair(std::vector<Quad2>& out, double x0, double length, double width, double inner) {
  const double a = 0.5 * inner;
  out.push_back(rect(x0, a, x0 + length, a + width));
  out.push_back(rect(x0, -a - width, x0 + length, -a));
}

// Threshold stripes; returns the stripe width.
double add_threshold_stripes(std::vector<Quad2>& out, double width_m, int count) {
  const double half_span = std::min(0.5 * width_m - kEdgeClearanceM, kMaxHalfSpanM);
  // count stripes and count gaps (count - 2 single ones and one double one) across the span.
  const double w = 2.0 * half_span / (2.0 * count);
  for (int i = 0; i < count / 2; ++i) {
    const double inner = w + 2.0 * i * w;  // the double gap: w either side of the centreline
    out.push_back(rect(kStripeStartM, inner, kStripeStartM + kStripeLengthM, inner + w));
    out.push_back(rect(kStripeStartM, -inner - w, kStripeStartM + kStripeLengthM, -inner));
  }
  return w;
}

// Characters centred on the centreline, bottom (nearest the threshold) at x0: glyph u maps to
// +y (the reader's right) and v to +x (away from the reader on the approach).
void add_text(std::vector<Quad2>& out, const std::string& text, double x0) {
  const double n = static_cast<double>(text.size());
  const double total = n * kGlyphWidthM + (n - 1.0) * kGlyphGapM;
  double left = -0.5 * total;
  for (char c : text) {
    for (const Quad2& q : glyph_quads(c)) {
      Quad2 placed;
      for (int k = 0; k < 4; ++k) {
        placed.corners[k] = Eigen::Vector2d(x0 + q.corners[k].y(), left + q.corners[k].x());
      }
      out.push_back(placed);
    }
    left += kGlyphWidthM + kGlyphGapM;
  }
}

// Displaced threshold (Figure 5-4): a transverse stripe across the runway at the threshold and
// arrows along the centreline of the displaced part pointing at it.
void add_displaced_threshold(std::vector<Quad2>& out, double width_m, double displaced_m) {
  out.push_back(rect(0.0, -0.5 * width_m + 1.0, kTransverseStripeM, 0.5 * width_m - 1.0));
  constexpr double kArrowLengthM = 30.0, kHeadLengthM = 9.0, kHeadWidthM = 4.5, kShaftWidthM = 0.9,
                   kArrowIntervalM = 45.0;
  for (double tip = -10.0; tip - kArrowLengthM > -displaced_m + 5.0; tip -= kArrowIntervalM) {
    out.push_back(
        rect(tip - kArrowLengthM, -0.5 * kShaftWidthM, tip - kHeadLengthM, 0.5 * kShaftWidthM));
    out.push_back(
        {{Eigen::Vector2d(tip - kHeadLengthM, -0.5 * kHeadWidthM), Eigen::Vector2d(tip, 0.0),
          Eigen::Vector2d(tip, 0.0), Eigen::Vector2d(tip - kHeadLengthM, 0.5 * kHeadWidthM)}});
  }
}

}  // namespace

int threshold_stripe_count(double width_m) {
  if (width_m >= 60.0) return 16;
  if (width_m >= 45.0) return 12;
  if (width_m >= 30.0) return 8;
  if (width_m >= 23.0) return 6;
  return 4;
}

AimingPointLayout aiming_point_layout(double lda) {
  if (lda < 800.0) return {150.0, 30.0, 4.0, 6.0};
  if (lda < 1200.0) return {250.0, 30.0, 6.0, 9.0};
  if (lda < 2400.0) return {300.0, 45.0, 6.0, 18.0};
  return {400.0, 45.0, 6.0, 18.0};
}

int touchdown_zone_pair_count(double lda) {
  if (lda < 900.0) return 1;
  if (lda < 1200.0) return 2;
  if (lda < 1500.0) return 3;
  if (lda < 2400.0) return 4;
  return 6;
}

double centreline_width_m(ApproachCategory category) {
  switch (category) {
    case ApproachCategory::kPrecisionCatIIorIII:
      return 0.90;
    case ApproachCategory::kPrecisionCatI:
    case ApproachCategory::kNonPrecision:
      return 0.45;
    default:
      return 0.30;
  }
}

EndMarkings end_markings(const EndMarkingInput& in) {
  const std::string where = "runway markings " + in.designator.text();
  util::require_in_range(in.width_m, 5.0, 200.0, where, "width_m", "m");
  util::require_in_range(in.landing_distance_m, 100.0, 10000.0, where, "landing_distance_m", "m");
  util::require_in_range(in.displaced_threshold_m, 0.0, 5000.0, where, "displaced_threshold_m", "m");
  EndMarkings m;
  m.threshold_stripes = threshold_stripe_count(in.width_m);
  m.threshold_stripe_width_m = add_threshold_stripes(m.quads, in.width_m, m.threshold_stripes);

  double x = kStripeStartM + kStripeLengthM + kDesignationGapM;
  if (in.designator.letter != 0) {
    add_text(m.quads, std::string(1, in.designator.letter), x);
    x += kGlyphHeightM + kLetterNumberGapM;
  }
  add_text(m.quads, in.designator.painted_number(), x);
  m.designation_end_m = x + kGlyphHeightM;

  const bool instrument = in.category != ApproachCategory::kVisual;
  const bool precision = in.category == ApproachCategory::kPrecisionCatI ||
                         in.category == ApproachCategory::kPrecisionCatIIorIII;
  const AimingPointLayout aim = aiming_point_layout(in.landing_distance_m);
  if (instrument) {
    m.aiming_point = aim;
    add_pair(m.quads, aim.start_m, aim.length_m, aim.width_m, aim.inner_spacing_m);
  }
  if (precision) {
    const int pairs = touchdown_zone_pair_count(in.landing_distance_m);
    for (int k = 1; k <= pairs; ++k) {
      const double start = k * kTdzIntervalM;
      if (std::abs(start - aim.start_m) <= kTdzAimingClearanceM) continue;
      if (start + kTdzLengthM > 0.5 * in.landing_distance_m) break;
      m.touchdown_zone_starts_m.push_back(start);
      add_pair(m.quads, start, kTdzLengthM, kTdzWidthM, aim.inner_spacing_m);
    }
  }
  if (in.displaced_threshold_m > 0.0) {
    add_displaced_threshold(m.quads, in.width_m, in.displaced_threshold_m);
  }
  return m;
}

std::vector<Quad2> centreline_stripes(double from_m, double to_m, double width_m) {
  std::vector<Quad2> out;
  const double span = to_m - from_m;
  const double period = kCentrelineStripeM + kCentrelineGapM;
  const int n = static_cast<int>(std::floor((span + kCentrelineGapM) / period));
  if (n <= 0) return out;
  const double start = from_m + 0.5 * (span - (n * period - kCentrelineGapM));
  for (int i = 0; i < n; ++i) {
    const double x0 = start + i * period;
    out.push_back(rect(x0, -0.5 * width_m, x0 + kCentrelineStripeM, 0.5 * width_m));
  }
  return out;
}

std::vector<Quad2> side_stripes(double from_m, double to_m, double runway_width_m) {
  std::vector<Quad2> out;
  const double w = runway_width_m >= 30.0 ? 0.90 : 0.45;
  const double half = 0.5 * runway_width_m;
  const int pieces = std::max(1, static_cast<int>(std::ceil((to_m - from_m) / kPieceM)));
  const double step = (to_m - from_m) / pieces;
  for (int i = 0; i < pieces; ++i) {
    const double x0 = from_m + i * step;
    out.push_back(rect(x0, half - w, x0 + step, half));
    out.push_back(rect(x0, -half, x0 + step, -half + w));
  }
  return out;
}

// Where the centreline begins beyond a designation (used by the scene builder).
double centreline_clearance_m() { return kCentrelineClearanceM; }

}  // namespace fedsim::visual
