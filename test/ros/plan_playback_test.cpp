// Playback: poses between plan steps.
#include <gtest/gtest.h>

#include <cmath>

#include "fleet_planner/ros/plan_playback.h"

namespace fleet_planner::test {
namespace {

fleet_planner::TimedState state(double t, double x, double y, double yaw) {
  fleet_planner::TimedState s;
  s.time = t, s.x = x, s.y = y, s.yaw = yaw;
  return s;
}

TEST(PlanPlayback, InterpolatesPositionAndTurnsTheShortWay) {
  fleet_planner::RobotTimeline t;
  t.states = {state(0, 0, 0, 3.0), state(1, 0, 0, -3.0), state(2, 1, 0, -3.0)};
  auto p = poseAt(t, -1.0);
  EXPECT_DOUBLE_EQ(p.theta, 3.0);
  p = poseAt(t, 0.5);  // from 3.0 to -3.0 through pi, not through 0
  EXPECT_NEAR(std::abs(p.theta), M_PI, 1e-9);
  p = poseAt(t, 1.25);
  EXPECT_NEAR(p.x, 0.25, 1e-12);
  p = poseAt(t, 99.0);
  EXPECT_DOUBLE_EQ(p.x, 1.0);
  EXPECT_DOUBLE_EQ(planDuration({t}), 2.0);
}

}  // namespace
}  // namespace fleet_planner::test
