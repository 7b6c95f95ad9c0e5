// Malformed channel configurations, eye poses and environments give clear errors naming the
// field; PNG files round-trip and bad ones are reported with their path.
#include "common/picture/image.hpp"
#include "common/view/channel_config.hpp"
#include "visual/model/environment.hpp"
#include "visual/model/eye_pose.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace fedsim::visual {
namespace {

template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ChannelConfig, MalformedConfigsNameTheField) {
  view::ChannelConfig c;
  EXPECT_EQ(error_of([&] { validate(c, "visual.yaml"); }), "");
  c.horizontal_fov_rad = std::nan("");
  EXPECT_EQ(error_of([&] { validate(c, "visual.yaml"); }),
            "visual.yaml (channel 'centre'): field 'horizontal_fov_rad': not a finite number");
  c = view::ChannelConfig{};
  c.width_px = 0;
  EXPECT_NE(error_of([&] { validate(c, "x"); }).find("field 'width_px': 0 is outside [16, 8192]"),
            std::string::npos);
  c = view::ChannelConfig{};
  c.vertical_fov_rad = 3.0;  // 172 deg
  EXPECT_NE(error_of([&] { validate(c, "x"); }).find("'vertical_fov_rad'"), std::string::npos);
  c = view::ChannelConfig{};
  c.samples = 3;
  EXPECT_NE(error_of([&] { validate(c, "x"); }).find("'samples': 3 is not 1, 2 or 4"),
            std::string::npos);
  c = view::ChannelConfig{};
  c.eye_offset_body_m.y() = INFINITY;
  EXPECT_NE(error_of([&] { validate(c, "x"); }).find("'eye_offset_body_m.y'"), std::string::npos);
  c = view::ChannelConfig{};
  c.pitch_offset_rad = 2.0;
  EXPECT_NE(error_of([&] { validate(c, "x"); }).find("'pitch_offset_rad'"), std::string::npos);
}

TEST(EyePose, BadPosesNameTheField) {
  EyePose p;
  p.lat_rad = 2.0;
  EXPECT_NE(error_of([&] { validate(p, "eye"); }).find("eye: field 'lat_rad'"), std::string::npos);
  p = EyePose{};
  p.alt_msl_m = std::nan("");
  EXPECT_NE(error_of([&] { validate(p, "eye"); }).find("'alt_msl_m': not a finite number"),
            std::string::npos);
  p = EyePose{};
  p.theta_rad = -1.7;
  EXPECT_NE(error_of([&] { validate(p, "eye"); }).find("'theta_rad'"), std::string::npos);
}

TEST(Environment, BadEnvironmentsNameTheField) {
  Environment e;
  EXPECT_EQ(error_of([&] { validate(e, "env"); }), "");
  e.visibility_m = 0.0;
  EXPECT_NE(error_of([&] { validate(e, "env"); }).find("'visibility_m'"), std::string::npos);
  e = Environment{};
  e.cloud = CloudLayer{500.0, 400.0, 60.0};
  EXPECT_NE(error_of([&] { validate(e, "env"); }).find("'cloud.top_agl_m'"), std::string::npos);
  e = Environment{};
  e.sun_elevation_rad = std::nan("");
  EXPECT_NE(error_of([&] { validate(e, "env"); }).find("'sun_elevation_rad'"), std::string::npos);
}

TEST(Png, RoundTripAndErrors) {
  picture::Image image(17, 9);
  for (int row = 0; row < 9; ++row) {
    for (int col = 0; col < 17; ++col) {
      image.set(col, row,
                {static_cast<std::uint8_t>(col * 15), static_cast<std::uint8_t>(row * 28),
                 static_cast<std::uint8_t>((col * row) % 256), 255});
    }
  }
  const auto path = (test::output_dir() / "round_trip.png").string();
  picture::write_png(image, path);
  const picture::Image back = picture::read_png(path);
  ASSERT_EQ(back.width_px, 17);
  ASSERT_EQ(back.height_px, 9);
  EXPECT_EQ(back.rgba, image.rgba);
  const auto missing = (test::output_dir() / "no_such.png").string();
  try {
    picture::read_png(missing);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos);
  }
  const auto text = (test::output_dir() / "not_a.png").string();
  std::ofstream(text) << "not a png";
  EXPECT_THROW(picture::read_png(text), std::runtime_error);
  EXPECT_THROW(picture::write_png(picture::Image{}, path), std::invalid_argument);
  EXPECT_THROW(picture::write_png(image, "/nonexistent/dir/x.png"), std::runtime_error);
  EXPECT_THROW(image.at(17, 0), std::out_of_range);
}

}  // namespace
}  // namespace fedsim::visual
