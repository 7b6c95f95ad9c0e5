// Comparing a rendered picture with a stored one ("golden image") with a perceptual tolerance
// rather than bit for bit: llvmpipe, Mesa versions, LLVM's vector width and multisampling move
// edges by a fraction of a pixel and colours by a few levels, which must not fail a test, while
// a symbol or horizon in a different place must. Two figures, both over the RGB channels:
//   mean_abs_diff     mean |a - b| over every pixel and channel, 0..255 (overall likeness);
//   differing_fraction the fraction of pixels whose largest channel difference exceeds
//                      `pixel_threshold` (how much of the picture changed visibly).
// A picture matches when both are within their limits (ImageTolerance).
#pragma once

#include "common/picture/image.hpp"

#include <string>

namespace fedsim::picture {

struct ImageTolerance {
  double max_mean_abs_diff = 2.0;        // [levels of 255]
  double max_differing_fraction = 0.005; // of the pixels
  int pixel_threshold = 48;              // a pixel differs when a channel is off by more [levels]
};

struct ImageDifference {
  double mean_abs_diff = 0.0;
  double differing_fraction = 0.0;
  bool within(const ImageTolerance& t) const {
    return mean_abs_diff <= t.max_mean_abs_diff && differing_fraction <= t.max_differing_fraction;
  }
  std::string describe() const;  // "mean |diff| 0.41 levels, 0.12 % of pixels differ"
};

/// Throws std::invalid_argument naming both sizes when they differ.
ImageDifference compare_images(const Image& a, const Image& b, int pixel_threshold = ImageTolerance{}.pixel_threshold);

}  // namespace fedsim::picture
