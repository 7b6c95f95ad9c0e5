// One image-generator channel (one projector of the seed's nodes 5-7): where its eye point is
// relative to the pilot's eye, where its boresight points, how wide it sees and how many pixels.
//
// Frames (docs/frames.md): the channel frame C has x along the boresight, y to the right of the
// picture, z down the picture; it is the body frame B rotated by the 3-2-1 sequence heading,
// pitch, roll offset (yaw right, nose up, right wing down positive). The frustum is symmetric
// about the boresight: the picture spans +-horizontal_fov/2 and +-vertical_fov/2. Pixels need
// not be square (tan(hfov/2)/tan(vfov/2) need not equal width/height, as with some projectors).
//
// Three channels side by side at heading offsets -hfov, 0, +hfov share the edge planes of their
// frusta, so they meet edge to edge with neither gap nor overlap (three_channel_layout()).
#pragma once

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace fedsim::view {

struct ChannelConfig {
  std::string name = "centre";
  Eigen::Vector3d eye_offset_body_m = Eigen::Vector3d::Zero();  // from the pose's eye point, B [m]
  double heading_offset_rad = 0.0;  // boresight yaw from the body x axis, right positive [rad]
  double pitch_offset_rad = 0.0;    // boresight pitch, up positive [rad]
  double roll_offset_rad = 0.0;     // roll of the picture about the boresight [rad]
  double horizontal_fov_rad = 0.6981317007977318;  // full angle, 40 deg [rad]
  double vertical_fov_rad = 0.5235987755982988;    // full angle, 30 deg [rad]
  int width_px = 320;                              // [px]
  int height_px = 240;                             // [px]
  double near_m = 0.5;                             // nearest distance drawn along the boresight [m]
  int samples = 1;  // multisample anti-aliasing: 1 (off), 2 or 4 samples/pixel
};

/// Throws std::invalid_argument "<where>: field '<field>': <problem>" for a NaN, an infinity or
/// a value out of range: fov in [1, 150] deg, width/height 16..8192 px, near 0.01..100 m, eye
/// offset within 100 m, heading and roll offsets within +-180 deg, pitch within +-90 deg,
/// samples 1, 2 or 4.
void validate(const ChannelConfig& config, std::string_view where);

/// Left, centre and right channels from the centre one: heading offsets -hfov, 0, +hfov, the
/// centre's everything else, names "left", "centre", "right".
std::vector<ChannelConfig> three_channel_layout(const ChannelConfig& centre);

}  // namespace fedsim::view
