// Which "slot" of a lower-rate task a frame falls in (pure, no DDS): a federate that draws or
// streams `hz` times a second runs its task in frame N when N's slot differs from the last one.
#pragma once

#include <cstdint>

namespace fedsim::timing {

/// floor(frame x period_s x hz), the product taken as an integer when it lies within 1e-6 of one.
/// Without that tolerance, frame x 0.02 x 50 falls just short of the frame number for some
/// frames (29, 58, 116, 205, ...), so a task at the frame rate skipped those frames (found by
/// `fedsim latency --axis roll`: the picture of state frame 902 was never drawn).
std::int64_t rate_slot(std::uint64_t frame, double period_s, double hz);

}  // namespace fedsim::timing
