#include "timing/model/ack_tracker.hpp"

#include <gtest/gtest.h>

namespace fedsim::timing {
namespace {

TEST(AckTracker, CompletesWhenEveryExpectedFederateAcknowledged) {
  AckTracker t({"io", "flight", "nav"});
  t.start_frame(7);
  EXPECT_FALSE(t.acknowledge("io", 7));
  EXPECT_FALSE(t.acknowledge("flight", 7));
  EXPECT_FALSE(t.complete());
  EXPECT_EQ(t.missing(), std::vector<std::string>{"nav"});
  EXPECT_TRUE(t.acknowledge("nav", 7));
  EXPECT_TRUE(t.complete());
}

TEST(AckTracker, IgnoresStaleDuplicateAndUnknownAcknowledgements) {
  AckTracker t({"io", "flight"});
  t.start_frame(3);
  EXPECT_FALSE(t.acknowledge("io", 2));       // previous frame
  EXPECT_FALSE(t.acknowledge("visual", 3));   // not expected
  EXPECT_FALSE(t.acknowledge("io", 3));
  EXPECT_FALSE(t.acknowledge("io", 3));       // duplicate must not count twice
  EXPECT_FALSE(t.complete());
  EXPECT_TRUE(t.acknowledge("flight", 3));
}

TEST(AckTracker, RemovingALostFederateCompletesTheFrame) {
  AckTracker t({"io", "flight"});
  t.start_frame(1);
  EXPECT_FALSE(t.acknowledge("io", 1));
  EXPECT_TRUE(t.remove("flight"));
  EXPECT_TRUE(t.complete());
  t.start_frame(2);
  EXPECT_TRUE(t.acknowledge("io", 2));  // flight no longer expected
  EXPECT_FALSE(t.expects("flight"));
}

TEST(AckTracker, EmptyFederationIsAlwaysComplete) {
  AckTracker t;
  t.start_frame(0);
  EXPECT_TRUE(t.complete());
}

TEST(AckTracker, RejectsDuplicateNames) {
  EXPECT_THROW(AckTracker({"io", "io"}), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::timing
