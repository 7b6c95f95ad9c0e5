// Lights that lie on paint are not hidden by it: from the 28R threshold at a pilot's eye height
// at night, each of the first centreline and touchdown-zone lights ahead (on the centreline
// stripes and the touchdown-zone markings) lights its own pixel.
#include "visual/model/renderer.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

TEST(LightVisibility, InsetLightsOnMarkingsAreSeen) {
  Renderer renderer(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options()));
  const auto& end = test::ksfo_end("28R");
  // On the threshold, 4 m above the runway, looking 6 deg down the runway.
  const EyePose eye = test::approach_eye(end, 0.0, 4.0, -6.0 * kDegToRad);
  view::ChannelConfig channel;
  channel.width_px = 640;
  channel.height_px = 480;
  Environment night;
  night.sun_elevation_rad = -20.0 * kDegToRad;
  const RenderedFrame f = renderer.render(channel, eye, night);
  picture::write_png(f.image, (test::output_dir() / "inset_lights_night.png").string());
  const ChannelCamera camera = renderer.camera(channel, eye);
  const Scene& scene = renderer.scene();
  const int index = scene.find_end("28R");
  for (LightRole role : {LightRole::kRunwayCentreline, LightRole::kTouchdownZone}) {
    int checked = 0;
    for (const auto& l : scene.lights_of(index, role)) {
      const auto p = camera.project(l.position_scene_m.cast<double>());
      if (!p || !camera.in_picture(*p) || p->forward_m > 200.0) continue;
      ++checked;
      EXPECT_GT(f.image.at(p->column(), p->row()).luminance(), 0.3)
          << "light " << static_cast<int>(role) << " at " << p->forward_m << " m";
    }
    EXPECT_GT(checked, 5) << static_cast<int>(role);
  }
}

}  // namespace
}  // namespace fedsim::visual
