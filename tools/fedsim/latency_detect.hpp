// The pure half of `fedsim latency` (transport delay, Part 60 / seed 7.3): no DDS, no clock.
// It finds the first sample of an output that departs from what the output did before the step,
// reduces a picture to one number that moves with its horizon, places an arrival time in the
// frame it happened in, and summarises delays. tools/fedsim/latency.cpp runs the federation and
// feeds it; tools/fedsim/test/latency_detect_test.cpp tests it directly.
//
// Onset detection: a trend (a parabola by default) fitted by least squares to the last few
// samples before the step predicts each later sample; the first sample after the step whose
// distance from the prediction exceeds max(min_threshold, noise_factor x the largest residual of
// the fit x (1 + frames past the baseline / baseline length)) is the response: a trend carried
// further is trusted less. A trend, not a constant, because the output may be moving before
// the step (the phugoid after an earlier step, the platform's washout settling after it
// engaged); with nothing moving, the residuals are 0 and min_threshold alone decides.
#pragma once

#include "common/picture/image.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::latency {

/// One sample of one output channel: the frame it is keyed by and its value.
struct Point {
  std::uint64_t frame = 0;
  double value = 0.0;
};

struct OnsetOptions {
  std::size_t baseline_points = 10;  // samples before the step the trend is fitted to (>= 3)
  int trend_degree = 2;              // the trend: 0 constant, 1 straight line, 2 parabola
  double noise_factor = 5.0;         // threshold = noise_factor x the fit's largest residual ...
  double min_threshold = 0.0;        // ... and at least this (the channel's unit)
  std::uint64_t max_frames = 15;     // look this many frames past the step, no further
};

struct Onset {
  std::optional<std::uint64_t> frame;  // the responding sample's frame; empty: no response
  double threshold = 0.0;            // the distance from the trend that counted (at the responding or last frame)
  double noise = 0.0;                // the largest residual of the baseline fit
  double deviation = 0.0;            // the responding sample's distance from the trend (else the largest seen)
  std::string problem;               // why there is no answer ("" when frame is set or nothing moved)
};

/// Throws std::invalid_argument for options out of range (fewer than 3 baseline points, a
/// negative or non-finite factor or threshold).
void validate(const OnsetOptions& options);

/// The first sample keyed after `last_quiet_frame` (the last frame that cannot show the step)
/// and at most max_frames after it that leaves the trend of the baseline samples (keyed at or
/// before last_quiet_frame). The series must be sorted by frame; a repeated frame keeps its
/// first sample. A non-finite value in the baseline or the window is a problem, by name.
Onset find_onset(const std::vector<Point>& series, std::uint64_t last_quiet_frame, const OnsetOptions& options);

/// The earliest onset over several channels of one output (e.g. a platform's six jacks): the
/// channel index and its onset; the first channel's onset (no response) when none responds.
struct ChannelOnset {
  std::size_t channel = 0;
  Onset onset;
};
ChannelOnset earliest_onset(const std::vector<std::vector<Point>>& channels, std::uint64_t last_quiet_frame,
                            const std::vector<OnsetOptions>& options);

/// How blue the picture is: the mean of (blue - red) / 255, in -1..1, over the columns from
/// first_column to end_column (fractions of the width; all by default). A sky (or an attitude
/// indicator's blue half) above a ground (green, brown) makes this the fraction of the picture
/// above the horizon, scaled: it moves when the horizon does (pitch), smoothly with the
/// anti-aliased edge, and hardly when the ground texture scrolls. Throws for an empty image or
/// a column range outside 0..1.
double blueness(const picture::Image& image, double first_column = 0.0, double end_column = 1.0);

/// A rectangle of a picture as fractions of its width and height (0..1, first < end).
struct Region {
  double first_column = 0.0, end_column = 1.0, first_row = 0.0, end_row = 1.0;
};

/// How tilted the horizon is: the sky's blueness, the mean of max(blue - red, 0) / 255, of the
/// left half of the region minus that of its right half. A
/// level horizon gives the two halves the same sky; the aircraft rolling right turns the horizon
/// anticlockwise on the picture, raising its right end (less sky on the right): the figure grows
/// with the tilt, and a pitch (both halves alike) leaves it. Only what is bluer than red counts,
/// so that the ground texture's colours (green and brown: red above blue), which flow past with
/// the aircraft and differ between the halves, add nothing. Throws for an empty image or a
/// region outside 0..1 or less than two columns wide.
double blueness_tilt(const picture::Image& image, const Region& region = {});

/// A picture's luminance (BT.709, 0..255) as floats, rows from the top: what image_shift compares.
struct Luma {
  int width_px = 0;
  int height_px = 0;
  std::vector<float> value;  // width_px * height_px
  float at(int column, int row) const { return value[static_cast<std::size_t>(row) * width_px + column]; }
};
Luma luminance(const picture::Image& image);

/// How far the content of `current` moved from where it was in `previous` [px; + right, + down]:
/// the translation d with current(x) ~ previous(x - d) over `region` (less a margin of 4 px),
/// found by Lucas-Kanade least squares on the luminance gradients, iterated with a bilinear warp
/// of `previous` (exact to a small fraction of a pixel for shifts up to about a pixel on a
/// smooth texture). A heading change moves a view of the ground (or a heading scale)
/// sideways: dx, accumulated frame to frame, is then the heading in pixels. Empty when the
/// region has no gradient to register (a uniform picture) or the two pictures differ in size.
struct Shift {
  double dx_px = 0.0, dy_px = 0.0;
};
std::optional<Shift> image_shift(const Luma& previous, const Luma& current, const Region& region);

/// A tick as a monitor saw it: frame number and the monotonic time it arrived [ns].
struct TickSeen {
  std::uint64_t frame = 0;
  std::int64_t arrival_ns = 0;
};
/// The frame an event at `arrival_ns` happened in: the last tick (sorted by arrival) that had
/// arrived by then; empty before the first.
std::optional<std::uint64_t> frame_at(const std::vector<TickSeen>& ticks, std::int64_t arrival_ns);

struct Summary {
  std::size_t count = 0;
  double min = 0.0, median = 0.0, max = 0.0;
};
/// Count, min, median (mean of the middle two for an even count) and max; all 0 when empty.
Summary summarise(std::vector<double> values);

}  // namespace fedsim::latency
