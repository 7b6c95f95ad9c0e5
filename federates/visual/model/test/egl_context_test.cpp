// EGL headless as a run-time choice of the same renderer: Mesa's surfaceless platform (llvmpipe,
// no GPU needed) renders the KSFO scene the OSMesa context renders, to within the golden-image
// tolerance (the same rasteriser: identical here); --gl names parse; auto takes a hardware EGL
// device where there is one and otherwise falls back to OSMesa, saying why.
#include "common/gl/egl_context.hpp"
#include "common/gl/osmesa_context.hpp"
#include "common/picture/image_compare.hpp"
#include "visual/model/renderer.hpp"
#include "visual/model/test/test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

picture::Image render_with(std::unique_ptr<gl::GlContext> context, std::string* description) {
  Renderer renderer(build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options()), std::move(context));
  *description = renderer.description();
  const auto& end = test::ksfo_end("28R");
  const EyePose eye = test::approach_eye(end, 1852.0, 2252.0 * std::tan(3.0 * kDegToRad), -3.0 * kDegToRad);
  view::ChannelConfig channel;
  channel.width_px = 200;
  channel.height_px = 150;
  Environment day;
  day.sun_elevation_rad = 35.0 * kDegToRad;
  return renderer.render(channel, eye, day).image;
}

TEST(EglContext, SurfacelessMesaRendersWhatOsMesaRenders) {
  std::string egl_text, osmesa_text;
  const picture::Image egl = render_with(std::make_unique<gl::EglContext>(gl::EglContext::Platform::kSurfaceless), &egl_text);
  const picture::Image osmesa = render_with(std::make_unique<gl::OsMesaContext>(), &osmesa_text);
  std::printf("%s\n%s\n", egl_text.c_str(), osmesa_text.c_str());
  EXPECT_NE(egl_text.find("EGL surfaceless"), std::string::npos);
  EXPECT_NE(osmesa_text.find("OSMesa"), std::string::npos);
  const picture::ImageDifference d = picture::compare_images(egl, osmesa);
  std::printf("EGL vs OSMesa: %s\n", d.describe().c_str());
  EXPECT_TRUE(d.within(picture::ImageTolerance{})) << d.describe();
  // Control: the picture is a scene, not an empty buffer that would match any other empty one.
  EXPECT_GT(std::abs(test::mean_luminance(egl, 0, 0, 200, 20) - test::mean_luminance(egl, 0, 130, 200, 20)), 0.05);
}

TEST(EglContext, BackendNamesAndTheAutoFallback) {
  EXPECT_EQ(gl::parse_gl_backend("egl"), gl::GlBackend::kEgl);
  EXPECT_EQ(gl::parse_gl_backend("osmesa"), gl::GlBackend::kOsMesa);
  EXPECT_EQ(gl::parse_gl_backend("auto"), gl::GlBackend::kAuto);
  EXPECT_FALSE(gl::parse_gl_backend("vulkan").has_value());
  std::string note;
  std::unique_ptr<gl::GlContext> context = gl::make_gl_context(gl::GlBackend::kAuto, &note);
  context->make_current();
  const std::string text = context->description();
  std::printf("auto: %s%s%s\n", text.c_str(), note.empty() ? "" : " -- ", note.c_str());
  if (note.empty()) {
    EXPECT_NE(text.find("EGL device"), std::string::npos);  // a GPU machine
  } else {
    EXPECT_NE(text.find("OSMesa"), std::string::npos);  // no hardware device: the fallback, said so
    EXPECT_NE(note.find("OSMesa (llvmpipe) instead"), std::string::npos);
  }
  // --gl egl on this machine: the device if any, else surfaceless Mesa; never OSMesa.
  std::unique_ptr<gl::GlContext> egl = gl::make_gl_context(gl::GlBackend::kEgl);
  egl->make_current();
  EXPECT_EQ(egl->description().rfind("EGL", 0), 0u) << egl->description();
}

}  // namespace
}  // namespace fedsim::visual
