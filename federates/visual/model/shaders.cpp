#include "visual/model/shaders.hpp"

namespace fedsim::visual::shaders {

// The atmosphere (environment.hpp): a haze/fog layer from below the ground up to u_haze_top and
// a cloud layer [u_cloud_base, u_cloud_top], heights above the ground sphere; Koschmieder's
// attenuation exp(-tau) towards the layers' airlight. Heights of scene points use the sphere's
// drop d^2 / 2R so that the ground far away is not "below" the haze.
#define FEDSIM_ATMOSPHERE                                                                  \
  "uniform vec3 u_eye;\n"                                                                  \
  "uniform float u_eye_height;\n"                                                          \
  "uniform float u_ground_radius;\n"                                                       \
  "uniform float u_sigma_haze;\n"                                                          \
  "uniform float u_haze_top;\n"                                                            \
  "uniform float u_sigma_cloud;\n"                                                         \
  "uniform float u_cloud_base;\n"                                                          \
  "uniform float u_cloud_top;\n"                                                           \
  "uniform vec3 u_haze_colour;\n"                                                          \
  "uniform vec3 u_cloud_colour;\n"                                                         \
  "float height_above_ground(vec3 p) {\n"                                                  \
  "  return -p.z + dot(p.xy, p.xy) / (2.0 * u_ground_radius);\n"                           \
  "}\n"                                                                                    \
  "float layer_length(float h0, float h1, float d, float bottom, float top) {\n"           \
  "  float lo = min(h0, h1), hi = max(h0, h1);\n"                                          \
  "  if (hi - lo < 0.01) return (lo >= bottom && lo <= top) ? d : 0.0;\n"                  \
  "  return d * max(0.0, min(hi, top) - max(lo, bottom)) / (hi - lo);\n"                   \
  "}\n"                                                                                    \
  "vec2 optical_depths(vec3 p, float d) {\n"                                               \
  "  float h1 = height_above_ground(p);\n"                                                 \
  "  return vec2(u_sigma_haze * layer_length(u_eye_height, h1, d, -1.0e9, u_haze_top),\n"  \
  "              u_sigma_cloud * layer_length(u_eye_height, h1, d, u_cloud_base, u_cloud_top));\n" \
  "}\n"                                                                                    \
  "vec3 through(vec3 c, vec2 tau) {\n"                                                     \
  "  float total = tau.x + tau.y;\n"                                                       \
  "  float t = exp(-total);\n"                                                             \
  "  vec3 air = total > 1.0e-6 ? (tau.x * u_haze_colour + tau.y * u_cloud_colour) / total\n" \
  "                            : u_haze_colour;\n"                                         \
  "  return c * t + air * (1.0 - t);\n"                                                    \
  "}\n"

const char* const kEnvironmentVertex = R"(#version 330 core
void main() {
  // One triangle that covers the viewport.
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Sky and ground by ray casting: every pixel's ray meets the ground sphere (an infinite textured
// ground with the true horizon dip) or goes to the sky.
const char* const kEnvironmentFragment = "#version 330 core\n" FEDSIM_ATMOSPHERE R"(
uniform mat3 u_scene_from_gl;
uniform vec2 u_tan_half;
uniform vec2 u_viewport;
uniform vec3 u_eye_up;
uniform vec3 u_sun;
uniform vec3 u_sun_horizontal;
uniform vec3 u_zenith;
uniform vec3 u_horizon;
uniform vec3 u_horizon_sun;
uniform vec3 u_sun_rgb;
uniform vec3 u_ambient;
uniform sampler2D u_ground_texture;
out vec4 colour;

// Length of a ray from height h0 with sine of elevation s inside [bottom, top].
float ray_length(float h0, float s, float bottom, float top) {
  if (s > 1.0e-5) { float a = max(h0, bottom); return top > a ? (top - a) / s : 0.0; }
  if (s < -1.0e-5) { float a = min(h0, top); return a > bottom ? (a - bottom) / -s : 0.0; }
  return (h0 >= bottom && h0 <= top) ? 1.0e9 : 0.0;
}

vec3 sky(vec3 dir, float s) {
  // Towards the sun in azimuth: cosine between the horizontal parts of the ray and the sun
  // direction (u_sun_horizontal is unit, or zero with the sun overhead).
  vec3 dir_h = dir - s * u_eye_up;
  float towards = max(dot(dir_h, u_sun_horizontal), 0.0) * inversesqrt(max(dot(dir_h, dir_h), 1.0e-8));
  vec3 horizon = mix(u_horizon, u_horizon_sun, towards * towards * towards);
  vec3 c = mix(horizon, u_zenith, sqrt(clamp(s, 0.0, 1.0)));
  float cos_sun = max(dot(dir, u_sun), 0.0);
  float halo = cos_sun * cos_sun;  // cos^64 by squaring
  halo *= halo; halo *= halo; halo *= halo; halo *= halo; halo *= halo;
  c += u_sun_rgb * (smoothstep(0.99997, 0.999989, cos_sun) + 0.2 * halo);
  vec2 tau = vec2(u_sigma_haze * ray_length(u_eye_height, s, -1.0e9, u_haze_top),
                  u_sigma_cloud * ray_length(u_eye_height, s, u_cloud_base, u_cloud_top));
  return through(c, tau);
}

vec3 ground(vec3 p, float d) {
  vec3 fine = texture(u_ground_texture, p.xy / 150.0).rgb;
  // Field-scale variation from a coarse mip level: bilinear, no derivatives needed.
  vec3 coarse = textureLod(u_ground_texture, p.xy / 1700.0 + vec2(0.31, 0.77), 3.0).rgb;
  return through((0.55 * fine + 0.45 * coarse) * u_ambient, optical_depths(p, d));
}

void main() {
  vec2 ndc = gl_FragCoord.xy / u_viewport * 2.0 - 1.0;
  vec3 dir = normalize(u_scene_from_gl * vec3(ndc * u_tan_half, -1.0));
  float s = dot(dir, u_eye_up);
  float h = max(u_eye_height, 0.05);
  // Ray-sphere in a form that keeps float precision: b = dir.(eye - centre),
  // c = |eye - centre|^2 - R^2 = h (2R + h); the near root is c / (-b + sqrt(b^2 - c)).
  float b = (u_ground_radius + h) * s;
  float c = h * (2.0 * u_ground_radius + h);
  float disc = b * b - c;
  vec3 result;
  if (s < 0.0 && disc > 0.0) {
    float t = c / (-b + sqrt(disc));
    result = ground(u_eye + t * dir, t);
  } else {
    result = sky(dir, s);
  }
  colour = vec4(result, 1.0);
}
)";

const char* const kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_texture;
layout(location = 2) in float a_material;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec3 u_eye;
out vec3 v_position;
out vec2 v_texture;
flat out float v_material;
void main() {
  v_position = a_position;
  v_texture = a_texture;
  v_material = a_material;
  gl_Position = u_projection * (u_view * vec4(a_position - u_eye, 1.0));
}
)";

const char* const kSurfaceFragment = "#version 330 core\n" FEDSIM_ATMOSPHERE R"(
uniform vec3 u_ambient;
uniform sampler2D u_pavement_texture;
in vec3 v_position;
in vec2 v_texture;
flat in float v_material;
out vec4 colour;
void main() {
  vec3 grain = texture(u_pavement_texture, v_texture / 40.0).rgb;
  vec3 albedo = v_material < 0.5 ? grain
                                 : vec3(0.80, 0.80, 0.77) * (0.85 + 0.5 * grain.r);
  float d = length(v_position - u_eye);
  colour = vec4(through(albedo * u_ambient, optical_depths(v_position, d)), 1.0);
}
)";

// Light points (light_point.hpp): the intensity towards the eye from the beam law, Allard's law
// E = I exp(-tau) / d^2 with the same optical depth as the surfaces, seen when E >= E_T.
// Displayed opacity 0.3 at the threshold rising to 1 at 100 E_T; diameter 1 px (never less) up
// to 100 E_T, growing 0.75 px per decade above that (to 6 px): the glare of bright lights.
// With multisampling the least diameter is 2 px, so that a light still covers every sample of
// the pixel it falls in (a 1-px point would be spread, dimmed, over up to four pixels).
const char* const kLightVertex = "#version 330 core\n" FEDSIM_ATMOSPHERE R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_axis;
layout(location = 2) in vec3 a_up;
layout(location = 3) in vec3 a_colour;
layout(location = 4) in vec4 a_beam;  // intensity [cd], a50 [rad], e50 [rad], PAPI transition [rad]
layout(location = 5) in float a_kind; // 0 omnidirectional, 1 unidirectional, 2 PAPI
uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_threshold_lux;
uniform vec3 u_papi_red;
uniform float u_red_filter;
uniform float u_min_size_px;  // 1, or 2 with multisampling (a full pixel's samples covered)
out vec3 v_colour;
out float v_alpha;
out float v_size;
const float kLn2 = 0.693147;
const float kPapiTransition = 8.7266e-4;  // 3 arcmin

void main() {
  vec3 rel = a_position - u_eye;
  float d = max(length(rel), 0.1);
  vec3 to_eye = -rel / d;
  float elevation = asin(clamp(dot(to_eye, a_up), -1.0, 1.0));
  float intensity = a_beam.x;
  vec3 c = a_colour;
  if (a_kind > 0.5) {
    vec3 axis_h = a_axis - dot(a_axis, a_up) * a_up;
    vec3 eye_h = to_eye - dot(to_eye, a_up) * a_up;
    float along = dot(normalize(eye_h), normalize(axis_h));
    float azimuth = acos(clamp(along, -1.0, 1.0));
    float u = azimuth / a_beam.y;
    float v = (elevation - asin(clamp(dot(a_axis, a_up), -1.0, 1.0))) / a_beam.z;
    if (a_kind > 1.5) v = 0.0;  // PAPI: the beam covers the approach's elevations evenly
    intensity *= along > 0.0 ? exp(-kLn2 * (u * u + v * v)) : 0.0;
    if (a_kind > 1.5) {
      float white = clamp((elevation - a_beam.w) / kPapiTransition + 0.5, 0.0, 1.0);
      c = mix(u_papi_red, a_colour, white);
      intensity *= mix(u_red_filter, 1.0, white);
    }
  }
  vec2 tau = optical_depths(a_position, d);
  float illuminance = intensity * exp(-(tau.x + tau.y)) / (d * d);
  float decades = log2(max(illuminance, 1.0e-30) / u_threshold_lux) * 0.30103;
  v_colour = c;
  v_alpha = decades < 0.0 ? 0.0 : clamp(0.3 + 0.35 * decades, 0.0, 1.0);
  v_size = clamp(1.0 + 0.75 * (decades - 2.0), u_min_size_px, 6.0);
  gl_PointSize = v_size;
  gl_Position = v_alpha > 0.0 ? u_projection * (u_view * vec4(rel, 1.0))
                              : vec4(2.0, 2.0, 2.0, 1.0);  // below threshold: outside the clip volume
}
)";

const char* const kLightFragment = R"(#version 330 core
in vec3 v_colour;
in float v_alpha;
in float v_size;
out vec4 colour;
void main() {
  float a = v_alpha;
  if (v_size > 2.5) {  // glare disc: full at the centre, fading to a third at its rim
    vec2 q = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(q, q);
    if (r2 > 1.0) discard;
    a *= exp(-1.1 * r2);
  }
  colour = vec4(v_colour, a);
}
)";

}  // namespace fedsim::visual::shaders
