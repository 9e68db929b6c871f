// Timelines as nav_msgs/Path; see path_messages.h.
#include "fleet_planner/ros/path_messages.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "fleet_planner/model/robot_cells.h"
#include "fleet_planner/ros/conversions.h"

namespace fleet_planner {

fleet_planner::RobotTimeline robotTimeline(const Robot& robot, const Path& path, const GridMap& grid,
                                           double seconds_per_step) {
  fleet_planner::RobotTimeline timeline;
  timeline.robot_id = robot.id;
  timeline.subproblem = -1;
  timeline.cost = std::max(0, pathCost(path, planTarget(robot, path)));
  for (int t = 0; t < static_cast<int>(path.size()); ++t) {
    fleet_planner::TimedState state;
    state.step = t;
    state.time = t * seconds_per_step;
    const auto pose = toPose2D(grid, path[t]);
    state.x = pose.x, state.y = pose.y, state.yaw = pose.theta;
    // A start or goal off the grid headings: the timeline begins and ends at its true yaw.
    if (t <= robot.start_turn && robot.start_yaw) state.yaw = wrapAngle(*robot.start_yaw + grid.origin().yaw);
    if (t + 1 == static_cast<int>(path.size()) && robot.target_yaw) {
      state.yaw = wrapAngle(*robot.target_yaw + grid.origin().yaw);
    }
    state.cell_x = path[t].x, state.cell_y = path[t].y, state.heading = path[t].heading;
    timeline.states.push_back(state);
  }
  return timeline;
}

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
