// Channel files: the shipped ones load (centre; left/centre/right meeting edge to edge), angles
// in degrees become radians, and malformed files are refused naming the file, line and field.
#include "common/util/build_paths.hpp"
#include "visual/model/channel_file.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::visual {
namespace {

using units::kDegToRad;

std::string error_of(const std::string& text) {
  try {
    parse_channels(text, "channels.yaml");
  } catch (const util::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ChannelFile, TheShippedFilesLoad) {
  const auto centre = load_channels(fedsim::util::test_data_dir() + "/../../data/visual/channels.yaml");
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_EQ(centre[0].name, "centre");
  EXPECT_EQ(centre[0].width_px, 800);
  EXPECT_EQ(centre[0].height_px, 600);
  const auto three = load_channels(fedsim::util::test_data_dir() + "/../../data/visual/three_channels.yaml");
  ASSERT_EQ(three.size(), 3u);
  // Edge to edge: the side channels turn by one full horizontal field of view.
  EXPECT_NEAR(three[0].heading_offset_rad, -three[1].horizontal_fov_rad, 1e-12);
  EXPECT_NEAR(three[2].heading_offset_rad, three[1].horizontal_fov_rad, 1e-12);
  const view::ChannelConfig right =
      load_channel(fedsim::util::test_data_dir() + "/../../data/visual/three_channels.yaml", "right");
  EXPECT_EQ(right.name, "right");
}

TEST(ChannelFile, DegreesAtTheEdgeRadiansInside) {
  const auto c = parse_channels(
      "channels:\n  - {name: up, pitch_offset_deg: 10, horizontal_fov_deg: 60, vertical_fov_deg: 45,"
      " width_px: 640, height_px: 480, eye_offset_m: [0.1, -0.2, 0.0], samples: 4}\n",
      "channels.yaml");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].pitch_offset_rad, 10 * kDegToRad, 1e-15);
  EXPECT_NEAR(c[0].horizontal_fov_rad, 60 * kDegToRad, 1e-15);
  EXPECT_DOUBLE_EQ(c[0].eye_offset_body_m.y(), -0.2);
  EXPECT_EQ(c[0].samples, 4);
}

TEST(ChannelFile, MalformedFilesNameFileLineAndField) {
  EXPECT_NE(error_of("channels:\n  - {name: c, horizontal_fov_deg: .nan}\n").find("horizontal_fov_deg"),
            std::string::npos);
  EXPECT_NE(error_of("channels:\n  - {name: c, width_px: 10}\n").find("width_px"), std::string::npos);
  EXPECT_NE(error_of("channels:\n  - {name: c, fov_deg: 40}\n").find("fov_deg"), std::string::npos);
  EXPECT_NE(error_of("channels:\n  - {name: c}\n  - {name: c}\n").find("named twice"), std::string::npos);
  EXPECT_NE(error_of("channels:\n  - {name: ../etc}\n").find("[A-Za-z0-9_-]"), std::string::npos);
  EXPECT_NE(error_of("channels: []\n").find("at least one"), std::string::npos);
  EXPECT_NE(error_of("channels:\n  - {name: c, eye_offset_m: [0, 0]}\n").find("eye_offset_m"), std::string::npos);
  const std::string e = error_of("channels:\n  - name: c\n    height_px: 99999\n");
  EXPECT_NE(e.find("channels.yaml:3"), std::string::npos) << e;
  EXPECT_EQ(error_of("channels:\n  - {name: c}\n"), "");  // negative control: a good one passes
  try {
    load_channel(fedsim::util::test_data_dir() + "/../../data/visual/three_channels.yaml", "top");
    FAIL();
  } catch (const util::ConfigError& err) {
    EXPECT_NE(std::string(err.what()).find("left, centre, right"), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace fedsim::visual
