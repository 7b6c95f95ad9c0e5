// JPEG encoding of a rendered frame for the live picture (fedsim/visual_picture), with libjpeg
// (libjpeg62-turbo). The picture may be scaled down by an integer factor first (a box filter:
// the mean of each factor x factor block), so that a 1280x720 channel streams at 640x360 and a
// picture stays well inside one DDS sample.
#pragma once

#include "common/picture/image.hpp"

#include <cstdint>
#include <vector>

namespace fedsim::picture {

struct JpegOptions {
  int quality = 75;     // libjpeg quality 1..100
  int downscale = 1;    // integer reduction factor 1..8 (the size is divided, remainders cut)
};

/// Throws std::invalid_argument for options out of range or an image smaller than the factor.
void validate(const JpegOptions& options);

/// The image reduced by `factor` (box filter, alpha dropped to 255).
Image downscale(const Image& image, int factor);

/// Encodes the image (alpha dropped) as a baseline JPEG into `out` (its storage reused);
/// throws std::runtime_error when libjpeg fails.
void encode_jpeg(const Image& image, const JpegOptions& options, std::vector<std::uint8_t>& out);

/// Decodes a JPEG (tests read back what encode_jpeg wrote); RGBA with alpha 255. Throws
/// std::runtime_error for malformed data.
Image decode_jpeg(const std::uint8_t* data, std::size_t size);

}  // namespace fedsim::picture
