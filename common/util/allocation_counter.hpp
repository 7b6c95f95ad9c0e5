// Counts heap allocations made by the current thread, so that tests and benchmarks can show a
// per-step function allocates nothing. Linking the fedsim_allocation_counter library replaces the
// global operator new/delete (allocation_counter.cpp) in that program: link it only into test and
// benchmark executables, and do not define another replacement there.
#pragma once

#include <cstddef>

namespace fedsim::util {

/// Allocations made by this thread since it started.
std::size_t allocation_count();

/// Allocations made by this thread while the scope is alive.
class AllocationScope {
 public:
  AllocationScope() : start_(allocation_count()) {}
  std::size_t allocations() const { return allocation_count() - start_; }

 private:
  std::size_t start_;
};

}  // namespace fedsim::util
