#include "fedsim/latency_detect.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::latency {

void validate(const OnsetOptions& o) {
  if (o.baseline_points < 3) throw std::invalid_argument("onset: baseline_points must be at least 3");
  if (!std::isfinite(o.noise_factor) || o.noise_factor < 0.0) {
    throw std::invalid_argument("onset: noise_factor must be a finite number >= 0");
  }
  if (o.trend_degree < 0 || o.trend_degree > 2) throw std::invalid_argument("onset: trend_degree must be 0, 1 or 2");
  if (o.baseline_points < static_cast<std::size_t>(o.trend_degree) + 2) {
    throw std::invalid_argument("onset: baseline_points must exceed trend_degree + 1 (a residual to measure)");
  }
  if (!std::isfinite(o.min_threshold) || o.min_threshold < 0.0) {
    throw std::invalid_argument("onset: min_threshold must be a finite number >= 0");
  }
}

namespace {

// The series without repeated frames (a resent tick, a sample seen twice): the first one stays.
std::vector<Point> first_per_frame(const std::vector<Point>& series) {
  std::vector<Point> out;
  out.reserve(series.size());
  for (const Point& p : series) {
    if (!out.empty() && p.frame < out.back().frame) throw std::invalid_argument("onset: series not sorted by frame");
    if (out.empty() || p.frame != out.back().frame) out.push_back(p);
  }
  return out;
}

// A polynomial trend of degree 0, 1 or 2 in the frame, measured from `origin` (the last
// baseline frame: well conditioned), fitted by least squares (normal equations, 3x3 at most).
struct Trend {
  double origin = 0.0;
  double c[3] = {0.0, 0.0, 0.0};
  double at(std::uint64_t frame) const {
    const double x = static_cast<double>(frame) - origin;
    return c[0] + x * (c[1] + x * c[2]);
  }
};

Trend fit_trend(const std::vector<Point>& points, int degree) {
  Trend t;
  t.origin = static_cast<double>(points.back().frame);
  const int n = degree + 1;
  double a[3][4] = {};  // augmented normal equations
  for (const Point& p : points) {
    const double x = static_cast<double>(p.frame) - t.origin;
    const double pw[3] = {1.0, x, x * x};
    for (int r = 0; r < n; ++r) {
      for (int k = 0; k < n; ++k) a[r][k] += pw[r] * pw[k];
      a[r][n] += pw[r] * p.value;
    }
  }
  // Gaussian elimination with partial pivoting; a singular system (repeated frames) keeps 0s.
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r) {
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    }
    if (std::abs(a[pivot][col]) < 1e-300) return t;
    for (int k = 0; k <= n; ++k) std::swap(a[col][k], a[pivot][k]);
    for (int r = 0; r < n; ++r) {
      if (r == col) continue;
      const double f = a[r][col] / a[col][col];
      for (int k = col; k <= n; ++k) a[r][k] -= f * a[col][k];
    }
  }
  for (int r = 0; r < n; ++r) t.c[r] = a[r][n] / a[r][r];
  return t;
}

}  // namespace

Onset find_onset(const std::vector<Point>& series_in, std::uint64_t last_quiet_frame, const OnsetOptions& options) {
  validate(options);
  const std::vector<Point> series = first_per_frame(series_in);
  Onset result;
  const auto after = std::upper_bound(series.begin(), series.end(), last_quiet_frame,
                                      [](std::uint64_t f, const Point& p) { return f < p.frame; });
  const auto baseline_count = static_cast<std::size_t>(after - series.begin());
  if (baseline_count < options.baseline_points) {
    result.problem = "only " + std::to_string(baseline_count) + " samples before the step (need " +
                     std::to_string(options.baseline_points) + ")";
    return result;
  }
  const std::vector<Point> baseline(after - static_cast<std::ptrdiff_t>(options.baseline_points), after);
  for (const Point& p : baseline) {
    if (!std::isfinite(p.value)) {
      result.problem = "a non-finite sample before the step (frame " + std::to_string(p.frame) + ")";
      return result;
    }
  }
  const Trend trend = fit_trend(baseline, options.trend_degree);
  for (const Point& p : baseline) result.noise = std::max(result.noise, std::abs(p.value - trend.at(p.frame)));
  // The further the trend is carried past the baseline, the less it is worth: the tolerance
  // grows by the baseline's residual for every baseline length carried.
  const auto threshold_at = [&](std::uint64_t frame) {
    const double carried = static_cast<double>(frame - last_quiet_frame) / static_cast<double>(options.baseline_points);
    return std::max(options.min_threshold, options.noise_factor * result.noise * (1.0 + carried));
  };
  result.threshold = threshold_at(last_quiet_frame + 1);
  for (auto it = after; it != series.end() && it->frame <= last_quiet_frame + options.max_frames; ++it) {
    if (!std::isfinite(it->value)) {
      result.problem = "a non-finite sample after the step (frame " + std::to_string(it->frame) + ")";
      return result;
    }
    const double deviation = std::abs(it->value - trend.at(it->frame));
    result.threshold = threshold_at(it->frame);
    if (deviation > result.threshold) {
      result.frame = it->frame;
      result.deviation = deviation;
      return result;
    }
    result.deviation = std::max(result.deviation, deviation);
  }
  return result;
}

ChannelOnset earliest_onset(const std::vector<std::vector<Point>>& channels, std::uint64_t last_quiet_frame,
                            const std::vector<OnsetOptions>& options) {
  if (channels.empty() || channels.size() != options.size()) {
    throw std::invalid_argument("onset: one options entry per channel, at least one channel");
  }
  ChannelOnset best{0, find_onset(channels[0], last_quiet_frame, options[0])};
  for (std::size_t c = 1; c < channels.size(); ++c) {
    Onset onset = find_onset(channels[c], last_quiet_frame, options[c]);
    if (!onset.frame) continue;
    if (!best.onset.frame || *onset.frame < *best.onset.frame) {
      best = {c, std::move(onset)};
    }
  }
  return best;
}

double blueness(const picture::Image& image, double first_column, double end_column) {
  const std::size_t pixels = static_cast<std::size_t>(image.width_px) * static_cast<std::size_t>(image.height_px);
  if (pixels == 0 || image.rgba.size() < pixels * 4) throw std::invalid_argument("blueness: empty image");
  if (!(first_column >= 0.0 && first_column < end_column && end_column <= 1.0)) {
    throw std::invalid_argument("blueness: columns must satisfy 0 <= first < end <= 1");
  }
  const int c0 = static_cast<int>(std::floor(first_column * image.width_px));
  const int c1 = std::max(c0 + 1, static_cast<int>(std::ceil(end_column * image.width_px)));
  long long sum = 0;
  for (int row = 0; row < image.height_px; ++row) {
    const std::uint8_t* px = &image.rgba[(static_cast<std::size_t>(row) * image.width_px + c0) * 4];
    for (int c = c0; c < c1; ++c, px += 4) sum += static_cast<int>(px[2]) - px[0];
  }
  return static_cast<double>(sum) / (255.0 * static_cast<double>(c1 - c0) * image.height_px);
}

namespace {

// The mean of max(blue - red, 0) / 255 over columns [c0, c1) and rows [r0, r1): the sky's
// blueness alone.
double sky_blueness(const picture::Image& image, int c0, int c1, int r0, int r1) {
  long long sum = 0;
  for (int row = r0; row < r1; ++row) {
    const std::uint8_t* px = &image.rgba[(static_cast<std::size_t>(row) * image.width_px + c0) * 4];
    for (int c = c0; c < c1; ++c, px += 4) sum += std::max(0, static_cast<int>(px[2]) - px[0]);
  }
  return static_cast<double>(sum) / (255.0 * static_cast<double>(c1 - c0) * (r1 - r0));
}

bool region_valid(const Region& g) {
  return g.first_column >= 0.0 && g.first_column < g.end_column && g.end_column <= 1.0 && g.first_row >= 0.0 &&
         g.first_row < g.end_row && g.end_row <= 1.0;
}

}  // namespace

double blueness_tilt(const picture::Image& image, const Region& region) {
  const std::size_t pixels = static_cast<std::size_t>(image.width_px) * static_cast<std::size_t>(image.height_px);
  if (pixels == 0 || image.rgba.size() < pixels * 4) throw std::invalid_argument("blueness_tilt: empty image");
  if (!region_valid(region)) throw std::invalid_argument("blueness_tilt: the region must lie within 0..1, first < end");
  const int c0 = static_cast<int>(std::floor(region.first_column * image.width_px));
  const int c2 = std::min(image.width_px, static_cast<int>(std::ceil(region.end_column * image.width_px)));
  const int r0 = static_cast<int>(std::floor(region.first_row * image.height_px));
  const int r1 = std::max(r0 + 1, std::min(image.height_px, static_cast<int>(std::ceil(region.end_row * image.height_px))));
  if (c2 - c0 < 2) throw std::invalid_argument("blueness_tilt: fewer than two columns");
  const int c1 = (c0 + c2) / 2;
  return sky_blueness(image, c0, c1, r0, r1) - sky_blueness(image, c1, c2, r0, r1);
}

Luma luminance(const picture::Image& image) {
  const std::size_t pixels = static_cast<std::size_t>(image.width_px) * static_cast<std::size_t>(image.height_px);
  if (pixels == 0 || image.rgba.size() < pixels * 4) throw std::invalid_argument("luminance: empty image");
  Luma l{image.width_px, image.height_px, std::vector<float>(pixels)};
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint8_t* px = &image.rgba[i * 4];
    l.value[i] = static_cast<float>(0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2]);
  }
  return l;
}

namespace {

// previous(x, y) by bilinear interpolation, clamped to the picture.
double bilinear(const Luma& l, double x, double y) {
  x = std::clamp(x, 0.0, l.width_px - 1.0);
  y = std::clamp(y, 0.0, l.height_px - 1.0);
  const int x0 = std::min(static_cast<int>(x), l.width_px - 2), y0 = std::min(static_cast<int>(y), l.height_px - 2);
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * l.at(x0, y0) + fx * l.at(x0 + 1, y0)) +
         fy * ((1 - fx) * l.at(x0, y0 + 1) + fx * l.at(x0 + 1, y0 + 1));
}

}  // namespace

std::optional<Shift> image_shift(const Luma& previous, const Luma& current, const Region& region) {
  if (!region_valid(region)) throw std::invalid_argument("image_shift: the region must lie within 0..1, first < end");
  if (previous.width_px != current.width_px || previous.height_px != current.height_px || previous.width_px < 3 ||
      previous.height_px < 3) {
    return std::nullopt;
  }
  constexpr int kMargin = 4;  // keeps the gradient's and the warp's neighbours inside the picture
  const int c0 = std::max(kMargin, static_cast<int>(std::floor(region.first_column * current.width_px)));
  const int c1 = std::min(current.width_px - kMargin, static_cast<int>(std::ceil(region.end_column * current.width_px)));
  const int r0 = std::max(kMargin, static_cast<int>(std::floor(region.first_row * current.height_px)));
  const int r1 = std::min(current.height_px - kMargin, static_cast<int>(std::ceil(region.end_row * current.height_px)));
  if (c1 - c0 < 3 || r1 - r0 < 3) return std::nullopt;
  Shift d;
  for (int iteration = 0; iteration < 10; ++iteration) {
    // current(x) ~ previous(x - d - delta) ~ warped(x) - gradient . delta: least squares in delta.
    double gxx = 0, gxy = 0, gyy = 0, bx = 0, by = 0;
    for (int r = r0; r < r1; ++r) {
      for (int c = c0; c < c1; ++c) {
        const double x = c - d.dx_px, y = r - d.dy_px;
        const double warped = bilinear(previous, x, y);
        const double gx = 0.5 * (bilinear(previous, x + 1, y) - bilinear(previous, x - 1, y));
        const double gy = 0.5 * (bilinear(previous, x, y + 1) - bilinear(previous, x, y - 1));
        const double e = current.at(c, r) - warped;
        gxx += gx * gx;
        gxy += gx * gy;
        gyy += gy * gy;
        bx += gx * e;
        by += gy * e;
      }
    }
    const double det = gxx * gyy - gxy * gxy;
    // No texture to register (both gradients nil, or all along one direction).
    if (!(det > 1e-9 * (gxx + gyy) * (gxx + gyy)) || gxx + gyy <= 0.0) return std::nullopt;
    const double ddx = -(gyy * bx - gxy * by) / det;
    const double ddy = -(gxx * by - gxy * bx) / det;
    d.dx_px += ddx;
    d.dy_px += ddy;
    if (std::abs(ddx) < 1e-5 && std::abs(ddy) < 1e-5) break;
  }
  return d;
}

std::optional<std::uint64_t> frame_at(const std::vector<TickSeen>& ticks, std::int64_t arrival_ns) {
  const auto it = std::upper_bound(ticks.begin(), ticks.end(), arrival_ns,
                                   [](std::int64_t t, const TickSeen& tick) { return t < tick.arrival_ns; });
  if (it == ticks.begin()) return std::nullopt;
  return std::prev(it)->frame;
}

Summary summarise(std::vector<double> values) {
  Summary s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  s.min = values.front();
  s.max = values.back();
  const std::size_t mid = values.size() / 2;
  s.median = values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
  return s;
}

}  // namespace fedsim::latency
