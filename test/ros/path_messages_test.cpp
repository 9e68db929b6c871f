// A robot's timeline as a nav_msgs/Path: a pose per step, stamped with its planned time, its yaw
// as a quaternion; topic names that ROS accepts whatever the robot's id.
#include <gtest/gtest.h>

#include <cmath>

#include "fleet_planner/ros/path_messages.h"

namespace fleet_planner::test {
namespace {

TEST(PathMessages, OnePoseStampedPerStepWithItsYaw) {
  fleet_planner::RobotTimeline timeline;
  timeline.robot_id = "amr_1";
  for (int t = 0; t < 3; ++t) {
    fleet_planner::TimedState s;
    s.step = t;
    s.x = 1.0 + t;
    s.y = 2.0;
    s.yaw = t == 2 ? 1.2 : 0.0;
    timeline.states.push_back(s);
  }
  const ros::Time start(100.0);
  const nav_msgs::Path path = toPathMessage(timeline, "map", start, 0.5);
  EXPECT_EQ(path.header.frame_id, "map");
  ASSERT_EQ(path.poses.size(), 3u);
  EXPECT_DOUBLE_EQ((path.poses[2].header.stamp - start).toSec(), 1.0);
  EXPECT_DOUBLE_EQ(path.poses[1].pose.position.x, 2.0);
  const auto& q = path.poses[2].pose.orientation;
  EXPECT_NEAR(2 * std::atan2(q.z, q.w), 1.2, 1e-12);
}

TEST(PathMessages, TopicNamesAreLegalForAnyId) {
  EXPECT_EQ(planTopicName("amr_1"), "plans/amr_1");
  EXPECT_EQ(planTopicName("fork-lift 2"), "plans/fork_lift_2");
  EXPECT_EQ(planTopicName("7"), "plans/r7");
}

}  // namespace
}  // namespace fleet_planner::test
