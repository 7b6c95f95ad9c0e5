// The channel camera against the analytic pinhole projection, computed here independently of
// the model: point positions in the eye's own local frame from GeographicLib's LocalCartesian
// (not common/geodesy), the attitude as explicit rotations about z, y, x (not the quaternion
// route of dcm_from_euler), then x_px = W/2 (1 + (y_C/x_C)/tan(hfov/2)), y_px likewise.
// Checked both on the CPU (ChannelCamera::project) and in rendered pictures: single-pixel light
// points must light the pixel that contains their analytic projection (within 0.5 px of its
// centre).
#include "visual/model/renderer.hpp"
#include "visual/model/sky_model.hpp"
#include "visual/model/test/test_support.hpp"

#include <GeographicLib/LocalCartesian.hpp>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

namespace fedsim::visual {
namespace {

using test::kDegToRad;
using units::kRadToDeg;

Eigen::Matrix3d rot(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

// Analytic pinhole: the pixel of a geodetic point for an eye pose and a channel.
Eigen::Vector2d analytic_pixel(const EyePose& eye, const view::ChannelConfig& c, double lat_deg,
                               double lon_deg, double alt_m, double* forward = nullptr) {
  GeographicLib::LocalCartesian local(eye.lat_rad * kRadToDeg, eye.lon_rad * kRadToDeg,
                                      eye.alt_msl_m);
  double east = 0, north = 0, up = 0;
  local.Forward(lat_deg, lon_deg, alt_m, east, north, up);
  const Eigen::Vector3d ned(north, east, -up);
  // NED -> body: 3-2-1 (yaw psi about z, pitch theta about y, roll phi about x).
  const Eigen::Matrix3d ned_from_body = rot(Eigen::Vector3d::UnitZ(), eye.psi_rad) *
                                        rot(Eigen::Vector3d::UnitY(), eye.theta_rad) *
                                        rot(Eigen::Vector3d::UnitX(), eye.phi_rad);
  const Eigen::Matrix3d body_from_channel = rot(Eigen::Vector3d::UnitZ(), c.heading_offset_rad) *
                                            rot(Eigen::Vector3d::UnitY(), c.pitch_offset_rad) *
                                            rot(Eigen::Vector3d::UnitX(), c.roll_offset_rad);
  const Eigen::Vector3d p = (ned_from_body * body_from_channel).transpose() * ned;
  if (forward != nullptr) *forward = p.x();
  return {0.5 * c.width_px * (1.0 + p.y() / p.x() / std::tan(0.5 * c.horizontal_fov_rad)),
          0.5 * c.height_px * (1.0 + p.z() / p.x() / std::tan(0.5 * c.vertical_fov_rad))};
}

struct Marker {
  double lat_deg, lon_deg, alt_m;
  Eigen::Vector2d pixel;
};

class Projection : public ::testing::Test {
 protected:
  Projection() : origin_{37.6188 * kDegToRad, -122.3750 * kDegToRad, 4.0}, frame_(origin_) {
    eye_.lat_rad = 37.6030 * kDegToRad;  // ~2 km south-east of the origin
    eye_.lon_rad = -122.3600 * kDegToRad;
    eye_.alt_msl_m = 250.0;
    eye_.psi_rad = 297.0 * kDegToRad;
    eye_.theta_rad = -4.0 * kDegToRad;
    eye_.phi_rad = 7.0 * kDegToRad;
    channel_.width_px = 320;
    channel_.height_px = 240;
    channel_.horizontal_fov_rad = 40.0 * kDegToRad;
    channel_.vertical_fov_rad = 28.0 * kDegToRad;  // deliberately not square pixels
    channel_.heading_offset_rad = 5.0 * kDegToRad;
    channel_.pitch_offset_rad = -2.0 * kDegToRad;
    channel_.roll_offset_rad = 1.5 * kDegToRad;
  }

  // Seeded random points in the picture at 0.5-6 km, none within 0.05 px of a pixel border.
  std::vector<Marker> markers(int n) const {
    std::mt19937_64 random(20261201);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    GeographicLib::LocalCartesian local(eye_.lat_rad * kRadToDeg, eye_.lon_rad * kRadToDeg,
                                        eye_.alt_msl_m);
    const ChannelCamera camera(frame_, channel_, eye_);
    std::vector<Marker> out;
    while (static_cast<int>(out.size()) < n) {
      const double x = 5.0 + u(random) * 310.0, y = 5.0 + u(random) * 230.0;
      const double range = 500.0 + u(random) * 5500.0;
      const Eigen::Vector3d p = camera.eye_scene_m() + range * camera.ray_scene(x, y);
      const GeodeticPosition g = frame_.geodetic(p);
      Marker m{g.lat_rad * kRadToDeg, g.lon_rad * kRadToDeg, g.alt_m, {}};
      m.pixel = analytic_pixel(eye_, channel_, m.lat_deg, m.lon_deg, m.alt_m);
      const double fx = m.pixel.x() - std::floor(m.pixel.x());
      const double fy = m.pixel.y() - std::floor(m.pixel.y());
      if (fx > 0.05 && fx < 0.95 && fy > 0.05 && fy < 0.95) out.push_back(m);
    }
    return out;
  }

  GeodeticPosition origin_;
  SceneFrame frame_;
  EyePose eye_;
  view::ChannelConfig channel_;
};

TEST_F(Projection, CameraMatchesTheAnalyticPinhole) {
  const ChannelCamera camera(frame_, channel_, eye_);
  for (const Marker& m : markers(200)) {
    const auto p = camera.project(
        frame_.position_scene_m({m.lat_deg * kDegToRad, m.lon_deg * kDegToRad, m.alt_m}));
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x_px, m.pixel.x(), 1e-3);
    EXPECT_NEAR(p->y_px, m.pixel.y(), 1e-3);
  }
}

TEST_F(Projection, AKnownPointOnTheBoresightAndOneAtTheCorner) {
  // A point straight ahead along the boresight is at the picture's centre; one at the
  // half-angles is at the corner (negative control: without the channel offsets it is not).
  const ChannelCamera camera(frame_, channel_, eye_);
  const Eigen::Vector3d ahead = camera.eye_scene_m() + 1000.0 * camera.scene_from_channel().col(0);
  const auto centre = camera.project(ahead);
  ASSERT_TRUE(centre.has_value());
  EXPECT_NEAR(centre->x_px, 160.0, 1e-6);
  EXPECT_NEAR(centre->y_px, 120.0, 1e-6);
  const GeodeticPosition g = frame_.geodetic(ahead);
  const Eigen::Vector2d a =
      analytic_pixel(eye_, channel_, g.lat_rad * kRadToDeg, g.lon_rad * kRadToDeg, g.alt_m);
  EXPECT_NEAR(a.x(), 160.0, 1e-3);
  EXPECT_NEAR(a.y(), 120.0, 1e-3);
  view::ChannelConfig plain = channel_;
  plain.heading_offset_rad = plain.pitch_offset_rad = plain.roll_offset_rad = 0.0;
  const Eigen::Vector2d b =
      analytic_pixel(eye_, plain, g.lat_rad * kRadToDeg, g.lon_rad * kRadToDeg, g.alt_m);
  EXPECT_GT((b - Eigen::Vector2d(160.0, 120.0)).norm(), 20.0);
  const Eigen::Vector3d corner_dir =
      camera.scene_from_channel() *
      Eigen::Vector3d(1.0, std::tan(20.0 * kDegToRad), std::tan(14.0 * kDegToRad));
  const auto corner = camera.project(camera.eye_scene_m() + 800.0 * corner_dir);
  ASSERT_TRUE(corner.has_value());
  EXPECT_NEAR(corner->x_px, 320.0, 1e-6);
  EXPECT_NEAR(corner->y_px, 240.0, 1e-6);
  EXPECT_FALSE(camera.project(camera.eye_scene_m() - 100.0 * camera.scene_from_channel().col(0)));
}

TEST_F(Projection, RenderedLightPointsLightTheAnalyticPixel) {
  const std::vector<Marker> ms = markers(60);
  Scene scene{frame_};
  scene.ground_elevation_m = origin_.alt_m;
  Environment night;
  night.sun_elevation_rad = -30.0 * kDegToRad;
  night.visibility_m = 1.0e6;
  const double threshold =
      light_threshold_lux(sky_state(night.sun_elevation_rad).background_luminance_cd_per_m2);
  const ChannelCamera camera(frame_, channel_, eye_);
  for (const Marker& m : ms) {
    LightPoint l;
    l.position_scene_m =
        frame_.position_scene_m({m.lat_deg * kDegToRad, m.lon_deg * kDegToRad, m.alt_m})
            .cast<float>();
    const double d = (l.position_scene_m.cast<double>() - camera.eye_scene_m()).norm();
    l.intensity_cd = static_cast<float>(20.0 * threshold * d * d);  // 20 E_T: a 1-pixel point
    l.beam = BeamKind::kOmnidirectional;
    scene.lights.push_back(l);
  }
  Renderer renderer(std::move(scene));
  const RenderedFrame frame = renderer.render(channel_, eye_, night);
  int lit = 0;
  for (int row = 0; row < 240; ++row) {
    for (int col = 0; col < 320; ++col)
      lit += test::luminance_at(frame.image, col, row) > 0.3 ? 1 : 0;
  }
  EXPECT_EQ(lit, static_cast<int>(ms.size()));  // one pixel each, nothing else
  for (const Marker& m : ms) {
    const int col = static_cast<int>(std::floor(m.pixel.x()));
    const int row = static_cast<int>(std::floor(m.pixel.y()));
    EXPECT_GT(test::luminance_at(frame.image, col, row), 0.3)
        << "marker at analytic (" << m.pixel.x() << ", " << m.pixel.y() << ")";
    EXPECT_LE(std::abs(col + 0.5 - m.pixel.x()), 0.5);
    EXPECT_LE(std::abs(row + 0.5 - m.pixel.y()), 0.5);
  }
}

TEST_F(Projection, HorizonWhereThePitchPutsIt) {
  // Level wings, pitch -4 deg, no channel offsets, eye 250 m up: the sky/ground boundary lies
  // 4 deg + the dip acos(R/(R+h)) above the centre row (analytic), within a pixel.
  view::ChannelConfig c = channel_;
  c.heading_offset_rad = c.pitch_offset_rad = c.roll_offset_rad = 0.0;
  EyePose level = eye_;
  level.phi_rad = 0.0;
  Scene scene{frame_};
  scene.ground_elevation_m = origin_.alt_m;
  Renderer renderer(std::move(scene));
  Environment clear;
  clear.visibility_m = 1.0e6;
  clear.sun_elevation_rad = 40.0 * kDegToRad;
  const RenderedFrame f = renderer.render(c, level, clear);
  const ChannelCamera camera = renderer.camera(c, level);
  const double h = camera.eye_height_above_ground_m();
  const double radius = frame_.ground_radius_m();
  const double dip = std::acos(radius / (radius + h));
  const double expected_row =
      120.0 * (1.0 - std::tan(4.0 * kDegToRad - dip) / std::tan(0.5 * c.vertical_fov_rad));
  // The boundary: the first row (from the top) whose centre column is green ground.
  int boundary = -1;
  for (int row = 0; row < 240 && boundary < 0; ++row) {
    const picture::Rgba8 p = f.image.at(160, row);
    if (p.g > p.b + 10) boundary = row;
  }
  ASSERT_GE(boundary, 0);
  EXPECT_NEAR(boundary, expected_row, 1.0);
}

}  // namespace
}  // namespace fedsim::visual
