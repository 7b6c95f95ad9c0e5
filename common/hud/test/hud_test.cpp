// The HUD on its own: transparent (premultiplied) away from the symbology, every drawn pixel
// green; composite_over() blends premultiplied alpha; a bad input names its field. Where the
// symbols fall against the image generator's camera is federates/visual/model/test/
// hud_camera_test.cpp.
#include "common/hud/composite.hpp"
#include "common/hud/test/hud_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::hud::test {
namespace {

using picture::Image;
using picture::Rgba8;
using units::kDegToRad;

TEST(Hud, TransparentAwayFromTheSymbology) {
  const view::ChannelConfig channel = channel_400x300();
  HudInputs in;
  in.pitch_rad = 2.0 * kDegToRad;
  in.velocity_ned_mps = {70.0, 0.0, 3.0};
  in.ias_mps = 70.0;
  Image image;
  renderer().render(in, channel, image);
  int clear = 0, green = 0;
  for (int row = 0; row < image.height_px; ++row) {
    for (int col = 0; col < image.width_px; ++col) {
      const Rgba8 p = image.at(col, row);
      if (p.a == 0) {
        ++clear;
        EXPECT_EQ(p.r + p.g + p.b, 0);  // premultiplied: no colour without alpha
      } else if (p.g >= p.r && p.g >= p.b) {
        ++green;
      }
    }
  }
  const int total = image.width_px * image.height_px;
  EXPECT_GT(clear, 0.9 * total);
  EXPECT_EQ(clear + green, total) << "every drawn pixel is green";
  for (int corner : {0, 1, 2, 3}) {
    EXPECT_EQ(image.at(corner % 2 ? 399 : 0, corner / 2 ? 299 : 0).a, 0);
  }
  // Negative control: the symbology is there.
  EXPECT_GT(total - clear, 1000);
}

TEST(Hud, CompositeOverBlendsPremultipliedAlpha) {
  Image channel(2, 1), hud(2, 1);
  channel.set(0, 0, {200, 100, 50, 255});
  channel.set(1, 0, {200, 100, 50, 255});
  hud.set(0, 0, {0, 128, 0, 128});  // half-covering green, premultiplied
  hud.set(1, 0, {0, 0, 0, 0});
  composite_over(channel, hud);
  const Rgba8 a = channel.at(0, 0), b = channel.at(1, 0);
  // out = hud + channel (255 - 128) / 255: 200*127/255 = 99.6, 128 + 49.8, 24.9.
  EXPECT_EQ(a.r, 100);
  EXPECT_EQ(a.g, 178);
  EXPECT_EQ(a.b, 25);
  EXPECT_EQ(a.a, 255);
  EXPECT_EQ(b.r, 200);  // transparent: the channel unchanged
  EXPECT_EQ(b.g, 100);
  EXPECT_EQ(b.b, 50);
  // Negative control: straight-alpha blending would give g = 128*0.5 + 100*0.5 = 114.
  EXPECT_NE(a.g, 114);
  Image small(1, 1);
  EXPECT_THROW(composite_over(small, hud), std::invalid_argument);
}

TEST(Hud, RenderedHudOverAPicture) {
  const view::ChannelConfig channel = channel_400x300();
  HudInputs in;
  in.velocity_ned_mps = {70.0, 0.0, 3.0};
  in.ias_mps = 70.0;
  Image hud;
  renderer().render(in, channel, hud);
  Image picture(400, 300);
  for (std::size_t i = 0; i < picture.rgba.size(); i += 4) {
    picture.rgba[i] = 90, picture.rgba[i + 1] = 120, picture.rgba[i + 2] = 200,
    picture.rgba[i + 3] = 255;
  }
  const Image before = picture;
  composite_over(picture, hud);
  for (int row = 0; row < 300; ++row) {
    for (int col = 0; col < 400; ++col) {
      const Rgba8 h = hud.at(col, row), p = picture.at(col, row), o = before.at(col, row);
      if (h.a == 0) {
        ASSERT_EQ(p.r, o.r);
        ASSERT_EQ(p.g, o.g);
      } else if (h.a == 255) {
        ASSERT_EQ(p.g, h.g);
      }
    }
  }
}

TEST(Hud, BadInputsNameTheField) {
  HudInputs in;
  in.velocity_ned_mps.z() = NAN;
  Image image;
  try {
    renderer().render(in, channel_400x300(), image);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("field 'velocity_ned_mps[2]'"), std::string::npos);
  }
  in.velocity_ned_mps.z() = 0.0;
  view::ChannelConfig bad = channel_400x300();
  bad.horizontal_fov_rad = -1.0;
  EXPECT_THROW(renderer().render(in, bad, image), std::invalid_argument);
  EXPECT_NO_THROW(renderer().render(in, channel_400x300(), image));
}

}  // namespace
}  // namespace fedsim::hud::test
