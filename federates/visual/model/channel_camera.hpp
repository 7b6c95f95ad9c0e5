// The pinhole camera of one channel for one eye pose: the eye point and the boresight in the
// scene frame, the projection of scene points to pixels, and the OpenGL matrices.
//
// Chain of frames: scene S (NED at the airport reference point) <- local NED at the eye (exact
// rotation, common/geodesy) <- body B (the pose's 3-2-1 angles, seed eq. 3.63) <- channel C (the
// channel's heading/pitch/roll offsets) <- GL eye G (x right, y up, z back: x_G = y_C,
// y_G = -z_C, z_G = -x_C). The eye point is the pose's position plus the channel's eye offset
// (body axes).
//
// Pixels: x_px from the left edge, y_px from the top edge of the picture; pixel (i, j) covers
// [i, i+1) x [j, j+1), so its centre is (i + 0.5, j + 0.5). For a point at (x_C, y_C, z_C) in C
// with x_C > 0 (the analytic pinhole):
//   x_px = W/2 * (1 + (y_C / x_C) / tan(hfov/2)),   y_px = H/2 * (1 + (z_C / x_C) / tan(vfov/2)).
// Depth: reversed-Z with an infinite far plane (depth = near / x_C, GL_ZERO_TO_ONE): a 32-bit
// float depth buffer then resolves 1 mm at 20 km, so lights 0.3 m above a runway 10 km away
// are depth-tested correctly.
#pragma once

#include "common/view/channel_config.hpp"
#include "visual/model/eye_pose.hpp"
#include "visual/model/scene_frame.hpp"

#include <Eigen/Core>

#include <optional>

namespace fedsim::visual {

struct PixelPoint {
  double x_px = 0.0;       // from the left edge of the picture [px]
  double y_px = 0.0;       // from the top edge [px]
  double forward_m = 0.0;  // distance along the boresight (x_C) [m]
  /// The pixel (column, row) the point falls in.
  int column() const;
  int row() const;
};

class ChannelCamera {
 public:
  /// Validates the config and the pose (std::invalid_argument naming the field).
  ChannelCamera(const SceneFrame& frame, const view::ChannelConfig& config, const EyePose& pose);

  const view::ChannelConfig& config() const { return config_; }
  /// The channel's eye point in S [m].
  const Eigen::Vector3d& eye_scene_m() const { return eye_scene_m_; }
  /// Rotation taking channel components (x boresight, y right, z down) to scene components.
  const Eigen::Matrix3d& scene_from_channel() const { return scene_from_channel_; }
  /// Height of the eye above the ground sphere [m] (negative: below it).
  double eye_height_above_ground_m() const { return eye_height_above_ground_m_; }

  /// Pixel position of a scene point; std::nullopt when it is behind the near plane. The point
  /// may fall outside the picture (check with in_picture()).
  std::optional<PixelPoint> project(const Eigen::Vector3d& point_scene_m) const;
  bool in_picture(const PixelPoint& p) const;
  /// Unit direction in S of the ray through a pixel position.
  Eigen::Vector3d ray_scene(double x_px, double y_px) const;

  /// GL eye from scene rotation (3x3 in a 4x4, no translation: the shaders subtract the eye so
  /// that float positions stay small), column-major as GL wants it.
  Eigen::Matrix4f view_rotation_gl() const;
  /// Reversed-Z infinite perspective for glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE).
  Eigen::Matrix4f projection_gl() const;
  double tan_half_horizontal() const { return tan_half_h_; }
  double tan_half_vertical() const { return tan_half_v_; }

 private:
  view::ChannelConfig config_;
  Eigen::Vector3d eye_scene_m_;
  Eigen::Matrix3d scene_from_channel_;
  double tan_half_h_;
  double tan_half_v_;
  double eye_height_above_ground_m_;
};

}  // namespace fedsim::visual
