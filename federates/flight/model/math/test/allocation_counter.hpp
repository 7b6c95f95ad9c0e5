// Counts heap allocations made by the current thread (the replacement operator new lives in
// allocation_counter_test.cpp), so tests can assert that a per-step function does not allocate.
#pragma once

#include <cstddef>

namespace fedsim::flight::testing {

/// Allocations made by this thread since it started.
std::size_t allocation_count();

/// Allocations made while the scope is alive.
class AllocationScope {
 public:
  AllocationScope() : start_(allocation_count()) {}
  std::size_t allocations() const { return allocation_count() - start_; }

 private:
  std::size_t start_;
};

}  // namespace fedsim::flight::testing
