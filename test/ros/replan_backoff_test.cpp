#include "fleet_planner/ros/replan_backoff.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fleet_planner {
namespace {

TEST(ReplanBackoff, ANewKeyIsDueAndTriedAtMostOncePerBaseInterval) {
  ReplanBackoff backoff(3.0, 12.0);
  EXPECT_TRUE(backoff.due("amr_1 blocked", 0.0, "tug_2@4"));
  backoff.record("amr_1 blocked", 0.0, "tug_2@4", /*merged=*/true);
  EXPECT_FALSE(backoff.due("amr_1 blocked", 2.9, "tug_2@4"));
  EXPECT_TRUE(backoff.due("amr_1 blocked", 3.0, "tug_2@4"));
  // Keys are independent: the same robot off its path is due at once.
  EXPECT_TRUE(backoff.due("amr_1 off path", 0.5, "7"));
}

TEST(ReplanBackoff, EachRefusalDoublesTheWaitUpToTheMaximum) {
  ReplanBackoff backoff(3.0, 12.0);
  double now = 0.0;
  for (double expected : {6.0, 12.0, 12.0}) {
    backoff.record("amr_1 blocked", now, "tug_2@4", /*merged=*/false);
    EXPECT_DOUBLE_EQ(backoff.wait("amr_1 blocked"), expected);
    EXPECT_FALSE(backoff.due("amr_1 blocked", now + expected - 0.1, "tug_2@4"));
    EXPECT_TRUE(backoff.due("amr_1 blocked", now + expected, "tug_2@4"));
    now += expected;
  }
}

TEST(ReplanBackoff, AChangedCauseOrAMergeBringsTheBaseIntervalBack) {
  ReplanBackoff backoff(3.0, 12.0);
  backoff.record("amr_1 blocked", 0.0, "tug_2@4", false);
  backoff.record("amr_1 blocked", 6.0, "tug_2@4", false);  // waits 12 s now
  // The robot it waits for has moved on: tried again after the base interval.
  EXPECT_FALSE(backoff.due("amr_1 blocked", 8.9, "tug_2@5"));
  EXPECT_TRUE(backoff.due("amr_1 blocked", 9.0, "tug_2@5"));
  EXPECT_FALSE(backoff.due("amr_1 blocked", 9.0, "tug_2@4"));
  // A refusal with the new cause doubles from the base, not from the old cause's wait.
  backoff.record("amr_1 blocked", 9.0, "tug_2@5", false);
  EXPECT_DOUBLE_EQ(backoff.wait("amr_1 blocked"), 6.0);
  backoff.record("amr_1 blocked", 15.0, "tug_2@5", true);
  EXPECT_DOUBLE_EQ(backoff.wait("amr_1 blocked"), 3.0);
  backoff.clear();
  EXPECT_TRUE(backoff.due("amr_1 blocked", 15.1, "tug_2@5"));
}

TEST(ReplanBackoff, RefusesIntervalsThatCannotWork) {
  EXPECT_THROW(ReplanBackoff(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ReplanBackoff(2.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace fleet_planner
