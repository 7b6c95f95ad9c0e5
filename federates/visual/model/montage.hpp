// Channel pictures side by side: the left, centre and right projectors' frames put together as
// the pilot sees them (channels that meet edge to edge make one continuous panorama).
#pragma once

#include "common/picture/image.hpp"

#include <vector>

namespace fedsim::visual {

/// The images left to right in one picture, `gap_px` columns of `gap` colour between them.
/// Every image must have the same height (the channels of one projector row do); throws
/// std::invalid_argument naming the first that differs, or for an empty list.
picture::Image side_by_side(const std::vector<picture::Image>& images, int gap_px = 0, picture::Rgba8 gap = {0, 0, 0, 255});

}  // namespace fedsim::visual
