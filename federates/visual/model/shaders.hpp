// GLSL 3.30 core sources of the renderer's three passes (environment, surfaces, light points)
// and the atmosphere functions they share. See renderer.hpp for what each pass draws.
#pragma once

namespace fedsim::visual::shaders {

extern const char* const kEnvironmentVertex;
extern const char* const kEnvironmentFragment;
extern const char* const kSurfaceVertex;
extern const char* const kSurfaceFragment;
extern const char* const kLightVertex;
extern const char* const kLightFragment;

}  // namespace fedsim::visual::shaders
