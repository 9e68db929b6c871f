// Timelines as nav_msgs/Path; see path_messages.h.
#include "fleet_planner/ros/path_messages.h"

#include <cctype>
#include <cmath>

namespace fleet_planner {

nav_msgs::Path toPathMessage(const fleet_planner::RobotTimeline& timeline, const std::string& frame,
                             const ros::Time& start, double seconds_per_step) {
  nav_msgs::Path path;
  path.header.frame_id = frame;
  path.header.stamp = start;
  for (const auto& state : timeline.states) {
    geometry_msgs::PoseStamped pose;
    pose.header.frame_id = frame;
    pose.header.stamp = start + ros::Duration(state.step * seconds_per_step);
    pose.pose.position.x = state.x;
    pose.pose.position.y = state.y;
    pose.pose.orientation.z = std::sin(state.yaw / 2);
    pose.pose.orientation.w = std::cos(state.yaw / 2);
    path.poses.push_back(pose);
  }
  return path;
}

std::string robotTopicName(const std::string& prefix, const std::string& robot_id) {
  std::string name;
  for (char c : robot_id) name += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) name = "r" + name;
  return prefix + "/" + name;
}

std::string planTopicName(const std::string& robot_id) { return robotTopicName("plans", robot_id); }

}  // namespace fleet_planner
