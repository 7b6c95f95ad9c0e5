// The head-up display (seed 5.9: drawn as an overlay on the visual system, so that it is
// focused at infinity with the outside world): green symbology, conformal where a HUD is
// conformal (the horizon line, the pitch ladder every 5 deg, the flight-path vector, the
// boresight symbol and the flight director's guidance cue), fixed elsewhere (speed and altitude
// boxes, vertical speed, a heading scale along the top).
//
// Conformal means: drawn where the visual channel's camera projects the same direction. This
// library does not build the image generator's ChannelCamera (that needs the scene frame and a
// geodetic eye); HudProjection is its pinhole for directions (points at infinity) derived from
// the same view::ChannelConfig and the same chain of frames: NED <- body (3-2-1 roll, pitch,
// true heading, common/math dcm_from_euler) <- channel C (the channel's heading/pitch/roll
// offsets; x boresight, y right, z down), then x_px = W/2 (1 + (y_C/x_C) / tan(hfov/2)),
// y_px = H/2 (1 + (z_C/x_C) / tan(vfov/2)) (federates/visual/model/channel_camera.hpp). The
// image generator's tests (federates/visual/model/test/hud_camera_test.cpp), where the two meet,
// check it against ChannelCamera to 1e-3 px and the drawn symbols against ChannelCamera to 1 px.
// The horizon line is the zero-pitch line (the local horizontal through the eye), as on a HUD;
// the visual's earth horizon dips below it by sqrt(2 h / R) (6 mrad at 120 m, 35 mrad at 4000 m).
// The flight-path vector is the direction of the velocity over the ground; it is drawn when the
// speed is at least 2 m/s (a HUD removes it when the velocity is unknown).
#pragma once

#include "common/hud/hud_inputs.hpp"
#include "common/symbology/canvas.hpp"
#include "common/view/channel_config.hpp"

#include <Eigen/Core>

#include <optional>

namespace fedsim::hud {

class HudProjection {
 public:
  HudProjection(const view::ChannelConfig& channel, double roll_rad, double pitch_rad,
                double heading_true_rad);

  /// Pixel position of a direction given in NED; std::nullopt when it is not in front of the
  /// eye (x_C below 1e-3 of its length).
  std::optional<symbology::Vec2> project(const Eigen::Vector3d& direction_ned) const;
  /// The unit direction of elevation `elevation_rad` and true azimuth `azimuth_rad`, NED.
  static Eigen::Vector3d direction(double azimuth_rad, double elevation_rad);
  /// Pixels per radian near the boresight, vertically.
  double pixels_per_rad() const;
  const Eigen::Matrix3d& channel_from_ned() const { return channel_from_ned_; }

 private:
  Eigen::Matrix3d channel_from_ned_;
  double half_width_px_;
  double half_height_px_;
  double tan_half_h_;
  double tan_half_v_;
};

/// Draws the HUD for the channel into `canvas` (reset to the channel's size first).
void draw_hud(symbology::Canvas& canvas, const HudInputs& in, const view::ChannelConfig& channel);

}  // namespace fedsim::hud
