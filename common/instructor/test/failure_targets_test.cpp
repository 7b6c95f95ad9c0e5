// Every failure target has one owner; a typo has none (the command line refuses it).
#include "common/instructor/failure_targets.hpp"

#include <gtest/gtest.h>

namespace fedsim::instructor {
namespace {

TEST(FailureTargets, EachHasItsOwnerAndATypoHasNone) {
  EXPECT_EQ(failure_target_owner("engine1"), FailureOwner::kFlight);
  EXPECT_EQ(failure_target_owner("engine4"), FailureOwner::kFlight);
  EXPECT_EQ(failure_target_owner("autopilot"), FailureOwner::kFlight);
  EXPECT_EQ(failure_target_owner("autothrottle"), FailureOwner::kFlight);
  EXPECT_EQ(failure_target_owner("nav1"), FailureOwner::kNavigation);
  EXPECT_EQ(failure_target_owner("gps"), FailureOwner::kNavigation);
  EXPECT_EQ(failure_target_owner("station-gs:IGWQ"), FailureOwner::kNavigation);
  EXPECT_EQ(failure_target_owner("motion"), FailureOwner::kMotion);
  EXPECT_EQ(failure_target_owner("control_loading"), FailureOwner::kControlLoading);
  for (const char* typo : {"engine5", "engine0", "engine", "autopilots", "nav3", "station:", "station-gs:", "Motion", ""}) {
    EXPECT_FALSE(failure_target_owner(typo).has_value()) << typo;
  }
}

}  // namespace
}  // namespace fedsim::instructor
