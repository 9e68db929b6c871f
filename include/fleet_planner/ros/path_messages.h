#pragma once
/// A robot's planned timeline as a nav_msgs/Path: one pose per plan step, in the map frame,
/// stamped with the time it is planned for (the plan's start plus step x seconds_per_step), for
/// the node's latched ~plans/<robot_id> topics and any consumer that follows a path in time.
#include <string>

#include <fleet_planner/RobotTimeline.h>
#include <nav_msgs/Path.h>

#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

/// A robot's path as its timeline: a state per step (every `seconds_per_step`), in the map frame
/// of `grid`, beginning and ending at its true start and target yaws; cost from its plan target.
/// Its subproblem is left at -1.
fleet_planner::RobotTimeline robotTimeline(const Robot& robot, const Path& path, const GridMap& grid,
                                           double seconds_per_step);

nav_msgs::Path toPathMessage(const fleet_planner::RobotTimeline& timeline, const std::string& frame,
                             const ros::Time& start, double seconds_per_step);

/// The topic name of a robot's path under the node's namespace: "plans/<robot_id>", with every
/// character a ROS name does not allow replaced by '_' (ids from the registry may hold any).
std::string planTopicName(const std::string& robot_id);
/// "<prefix>/<robot_id>" with the robot id made a ROS name likewise (e.g. "execution/amr_1").
std::string robotTopicName(const std::string& prefix, const std::string& robot_id);

}  // namespace fleet_planner
