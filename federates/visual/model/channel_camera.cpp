#include "visual/model/channel_camera.hpp"

#include "common/math/rotation.hpp"

#include <cmath>

namespace fedsim::visual {

namespace {

// G from C: x_G = y_C, y_G = -z_C, z_G = -x_C.
Eigen::Matrix3d gl_from_channel() {
  Eigen::Matrix3d m;
  m << 0, 1, 0, 0, 0, -1, -1, 0, 0;
  return m;
}

}  // namespace

int PixelPoint::column() const { return static_cast<int>(std::floor(x_px)); }
int PixelPoint::row() const { return static_cast<int>(std::floor(y_px)); }

ChannelCamera::ChannelCamera(const SceneFrame& frame, const view::ChannelConfig& config,
                             const EyePose& pose)
    : config_(config) {
  validate(config, "ChannelCamera");
  validate(pose, "ChannelCamera eye pose");
  const GeodeticPosition eye{pose.lat_rad, pose.lon_rad, pose.alt_msl_m};
  const Eigen::Matrix3d scene_from_body =
      frame.scene_from_local_ned(pose.lat_rad, pose.lon_rad) *
      dcm_from_euler({pose.phi_rad, pose.theta_rad, pose.psi_rad});
  const Eigen::Matrix3d body_from_channel =
      dcm_from_euler({config.roll_offset_rad, config.pitch_offset_rad, config.heading_offset_rad});
  scene_from_channel_ = scene_from_body * body_from_channel;
  eye_scene_m_ = frame.position_scene_m(eye) + scene_from_body * config.eye_offset_body_m;
  tan_half_h_ = std::tan(0.5 * config.horizontal_fov_rad);
  tan_half_v_ = std::tan(0.5 * config.vertical_fov_rad);
  const Eigen::Vector3d centre(0.0, 0.0, frame.ground_radius_m());
  eye_height_above_ground_m_ = (eye_scene_m_ - centre).norm() - frame.ground_radius_m();
}

std::optional<PixelPoint> ChannelCamera::project(const Eigen::Vector3d& point_scene_m) const {
  const Eigen::Vector3d c = scene_from_channel_.transpose() * (point_scene_m - eye_scene_m_);
  if (c.x() < config_.near_m) return std::nullopt;
  PixelPoint p;
  p.x_px = 0.5 * config_.width_px * (1.0 + c.y() / c.x() / tan_half_h_);
  p.y_px = 0.5 * config_.height_px * (1.0 + c.z() / c.x() / tan_half_v_);
  p.forward_m = c.x();
  return p;
}

bool ChannelCamera::in_picture(const PixelPoint& p) const {
  return p.x_px >= 0.0 && p.x_px < config_.width_px && p.y_px >= 0.0 && p.y_px < config_.height_px;
}

Eigen::Vector3d ChannelCamera::ray_scene(double x_px, double y_px) const {
  const double u = (2.0 * x_px / config_.width_px - 1.0) * tan_half_h_;
  const double v = (2.0 * y_px / config_.height_px - 1.0) * tan_half_v_;
  return (scene_from_channel_ * Eigen::Vector3d(1.0, u, v)).normalized();
}

Eigen::Matrix4f ChannelCamera::view_rotation_gl() const {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.topLeftCorner<3, 3>() = (gl_from_channel() * scene_from_channel_.transpose()).cast<float>();
  return m;
}

Eigen::Matrix4f ChannelCamera::projection_gl() const {
  // clip = (x_G / tan_h, y_G / tan_v, near, -z_G): depth = near / (-z_G), 1 at the near plane,
  // 0 at infinity; GL clips to 0 <= z_clip <= w_clip, i.e. -z_G >= near.
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = static_cast<float>(1.0 / tan_half_h_);
  m(1, 1) = static_cast<float>(1.0 / tan_half_v_);
  m(2, 3) = static_cast<float>(config_.near_m);
  m(3, 2) = -1.0f;
  return m;
}

}  // namespace fedsim::visual
