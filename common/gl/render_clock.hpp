// The clock a renderer times its frames with, lent by its caller (the adapter's monotonic clock,
// a test's fake one), so that no rendering library reads a clock itself.
#pragma once

#include <cstdint>
#include <functional>

namespace fedsim::gl {

/// A monotonic clock [ns] (e.g. std::chrono::steady_clock's count).
using RenderClock = std::function<std::int64_t()>;

}  // namespace fedsim::gl
