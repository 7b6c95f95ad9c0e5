// The eye point a channel draws: the aircraft state (valid at its stamp) carried forward to the
// frame's display time with the state's own rates, so that the picture shows where the aircraft
// is when the picture is seen, not where it was when the flight model computed it (seed 8.4:
// the transport delay of the visual system; Part 60 counts it in the 150 ms budget).
//
// Position: the ground velocity (NED) over the WGS-84 meridian and prime-vertical radii of
// curvature at the state's latitude (geodetic rates). Attitude: the Euler angle rates of the
// body rates (seed eq. 3.48: phi' = p + (q sin phi + r cos phi) tan theta,
// theta' = q cos phi - r sin phi, psi' = (q sin phi + r cos phi) / cos theta), held over the
// span. Both are first order: over the spans a channel uses (<= 0.25 s) the error of a 3 deg/s
// turn is 0.1 mrad, below a pixel of any channel here.
#pragma once

#include "visual/model/eye_pose.hpp"

#include <array>
#include <string_view>

namespace fedsim::visual {

/// The motion of the reference point (the CG the state describes) a channel extrapolates with.
struct MovingPose {
  EyePose pose;                                  // at the state's time
  std::array<double, 3> velocity_ned_mps{};      // over the ground, NED [m/s]
  std::array<double, 3> omega_body_radps{};      // p, q, r [rad/s]
};

/// The longest span extrapolated; a longer age is clamped to it (the state is then stale, and
/// the channel reports its age) [s].
inline constexpr double kMaxExtrapolationS = 0.25;

/// `state` carried forward by span_s (clamped to [0, kMaxExtrapolationS]). Throws
/// std::invalid_argument naming the field for a NaN/infinity (`where` names the source).
EyePose extrapolate(const MovingPose& state, double span_s, std::string_view where);

}  // namespace fedsim::visual
