// The live picture's JPEG: a rendered-like picture survives the round trip within JPEG's
// error, the downscale is the block mean, and bad options are refused.
#include "common/picture/jpeg_encoder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace fedsim::picture {
namespace {

Image gradient(int w, int h) {
  Image image(w, h);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      image.set(c, r, {static_cast<std::uint8_t>(c * 255 / (w - 1)), static_cast<std::uint8_t>(r * 255 / (h - 1)),
                       static_cast<std::uint8_t>(r < h / 2 ? 200 : 40), 255});
    }
  }
  return image;
}

TEST(Jpeg, RoundTripKeepsThePicture) {
  const Image image = gradient(160, 120);
  std::vector<std::uint8_t> bytes;
  encode_jpeg(image, {90, 1}, bytes);
  ASSERT_GT(bytes.size(), 100u);
  EXPECT_EQ(bytes[0], 0xFF);
  EXPECT_EQ(bytes[1], 0xD8);  // SOI
  const Image back = decode_jpeg(bytes.data(), bytes.size());
  ASSERT_EQ(back.width_px, 160);
  ASSERT_EQ(back.height_px, 120);
  double error = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    for (int k = 0; k < 3; ++k) error += std::abs(int(image.rgba[i + k]) - int(back.rgba[i + k]));
  }
  EXPECT_LT(error / (160 * 120 * 3), 3.0);
  // Negative control: another picture decodes differently.
  std::vector<std::uint8_t> other;
  Image flat(160, 120);
  encode_jpeg(flat, {90, 1}, other);
  EXPECT_NE(decode_jpeg(other.data(), other.size()).at(150, 10).r, back.at(150, 10).r);
}

TEST(Jpeg, DownscaleIsTheBlockMean) {
  Image image(4, 2);
  image.set(0, 0, {0, 0, 0, 255});
  image.set(1, 0, {100, 10, 0, 255});
  image.set(0, 1, {200, 20, 0, 255});
  image.set(1, 1, {100, 10, 4, 255});
  const Image half = downscale(image, 2);
  ASSERT_EQ(half.width_px, 2);
  ASSERT_EQ(half.height_px, 1);
  EXPECT_EQ(half.at(0, 0).r, 100);
  EXPECT_EQ(half.at(0, 0).g, 10);
  EXPECT_EQ(half.at(0, 0).b, 1);
  EXPECT_THROW(downscale(image, 3), std::invalid_argument);
}

TEST(Jpeg, BadOptionsAndDataAreRefused) {
  std::vector<std::uint8_t> bytes;
  EXPECT_THROW(encode_jpeg(gradient(32, 32), {0, 1}, bytes), std::invalid_argument);
  EXPECT_THROW(encode_jpeg(gradient(32, 32), {75, 9}, bytes), std::invalid_argument);
  const std::uint8_t junk[] = {0xFF, 0xD8, 0x00, 0x01, 0x02};
  EXPECT_THROW(decode_jpeg(junk, sizeof junk), std::runtime_error);
}

}  // namespace
}  // namespace fedsim::picture
