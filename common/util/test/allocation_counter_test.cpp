#include "common/util/allocation_counter.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace fedsim::util {
namespace {

TEST(AllocationCounter, SeesAllocationsOfThisThreadOnly) {
  const AllocationScope scope;
  std::vector<double> v(100);
  v[0] = 1.0;
  EXPECT_GE(scope.allocations(), 1u);
  const AllocationScope quiet;
  std::thread([] { std::vector<int> other(10); other[0] = 1; }).join();
  EXPECT_LE(quiet.allocations(), 1u);  // the thread object itself, at most
}

}  // namespace
}  // namespace fedsim::util
