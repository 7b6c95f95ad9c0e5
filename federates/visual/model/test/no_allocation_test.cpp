// A frame allocates nothing on the C++ heap once the channel's framebuffer and the image exist
// (fedsim_allocation_counter counts operator new in this thread; Mesa's own C allocations are not
// counted): the per-frame checks of the config, pose and environment build no strings.
#include "common/util/allocation_counter.hpp"
#include "visual/model/renderer.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

namespace fedsim::visual {
namespace {

TEST(Renderer, AFrameAllocatesNothing) {
  Renderer renderer(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options()));
  std::int64_t now_ns = 0;
  renderer.set_clock([&now_ns] { return now_ns += 1000; });
  view::ChannelConfig channel;
  Environment fog;
  fog.visibility_m = 600.0;
  fog.cloud = CloudLayer{150.0, 900.0, 60.0};
  EyePose eye = test::approach_eye(test::ksfo_end("28R"), 2000.0, 130.0, -3.0 * test::kDegToRad);
  picture::Image image;
  renderer.render(channel, eye, fog, image);  // creates the framebuffer and sizes the image
  eye.alt_msl_m -= 5.0;
  const util::AllocationScope scope;
  renderer.render(channel, eye, fog, image);
  EXPECT_EQ(scope.allocations(), 0u);
}

}  // namespace
}  // namespace fedsim::visual
