// Progress from poses: which plan state a robot seen at a pose has reached, and how far it may be
// released so that it is recognised where it stops.
#include <gtest/gtest.h>

#include "fleet_planner/ros/progress_matching.h"

namespace fleet_planner::test {
namespace {

geometry_msgs::Pose2D pose(double x, double y, double theta) {
  geometry_msgs::Pose2D p;
  p.x = x, p.y = y, p.theta = theta;
  return p;
}

constexpr double kQuarter = 1.5707963267948966;

TEST(ProgressMatcher, APoseThePathComesBackToIsReleasedOnlyOnceTheRobotIsBeyondTheTurn) {
  // Turn to +y, turn back, move on: standing at the start it also stands at state 2.
  const ProgressMatcher m({pose(1, 1, 0), pose(1, 1, kQuarter), pose(1, 1, 0), pose(1.5, 1, 0)}, 0.05, 0.2);
  EXPECT_EQ(m.releaseCap(0, 3), 1);
  EXPECT_EQ(m.match(pose(1, 1, 0), 0, 1), 0);
  EXPECT_EQ(m.match(pose(1, 1, 0.8), 0, 1), 0);  // on its way to state 1
  EXPECT_EQ(m.match(pose(1, 1, kQuarter), 0, 1), 1);
  EXPECT_EQ(m.releaseCap(1, 3), 3);
  EXPECT_EQ(m.match(pose(1, 1, 0), 1, 3), 2);
  EXPECT_EQ(m.match(pose(1.25, 1, 0), 1, 3), 2);
  EXPECT_EQ(m.match(pose(1.5, 1, 0), 1, 3), 3);
}

TEST(ProgressMatcher, AShortMoveWithinTheToleranceTellsItsEndsApart) {
  const ProgressMatcher m({pose(0, 0, 0), pose(0.05, 0, 0), pose(0.15, 0, 0)}, 0.05, 0.2);
  EXPECT_EQ(m.releaseCap(0, 2), 2);
  EXPECT_EQ(m.match(pose(0, 0, 0), 0, 2), 0);
  EXPECT_EQ(m.match(pose(0.01, 0, 0), 0, 2), 0);
  EXPECT_EQ(m.match(pose(0.05, 0, 0), 0, 2), 1);
  EXPECT_EQ(m.match(pose(0.15, 0, 0), 0, 2), 2);
}

TEST(ProgressMatcher, WaitsArePassedWhereTheRobotStands) {
  const ProgressMatcher m({pose(0, 0, 0), pose(0, 0, 0), pose(0, 0, 0), pose(0.5, 0, 0), pose(0.5, 0, 0)}, 0.05, 0.2);
  EXPECT_EQ(m.match(pose(0, 0, 0), 0, 2), 2);
  EXPECT_EQ(m.match(pose(0, 0, 0), 0, 1), 1);  // no further than released
  EXPECT_EQ(m.match(pose(0.5, 0, 0), 0, 4), 4);
  EXPECT_EQ(m.releaseCap(0, 4), 4);
}

TEST(ProgressMatcher, ARobotSeenOnItsWayHasReachedTheStateItLeft) {
  const ProgressMatcher m({pose(0, 0, 0), pose(0.5, 0, 0), pose(1.0, 0, 0), pose(1.0, 0, kQuarter)}, 0.05, 0.2);
  EXPECT_EQ(m.match(pose(0.75, 0.01, 0.05), 0, 3), 1);  // passed state 1 between two samples
  EXPECT_EQ(m.match(pose(1.0, 0, 0.7), 0, 3), 2);       // turning after state 2
  EXPECT_EQ(m.match(pose(0.75, 0.2, 0), 0, 3), -1);     // off the path
  EXPECT_EQ(m.match(pose(0.75, 0, 0), 0, 0), -1);       // not released there
}

}  // namespace
}  // namespace fleet_planner::test
