#pragma once
// A PlanFleet request's tasks placed on the map: each robot's footprint from the registry, its
// start (from the request or TF) and goal as grid states, every problem named per robot.
// Private to the ROS layer (fleet_planning_service.cpp).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fleet_planner/ros/fleet_planning_service.h"

namespace fleet_planner {

/// One task after its checks.
struct TaskState {
  Footprint footprint;  // cells
  GridPose start, goal;
  std::optional<double> start_yaw, goal_yaw;  ///< grid frame, when off the grid headings (Robot)
  RobotPlacement placement;
};

/// Places every task of `request` on `grid`. A robot that cannot be placed gets its status and
/// message in call.response.robots (UNKNOWN_ROBOT, INVALID_FOOTPRINT, NO_TRANSFORM,
/// INVALID_START, INVALID_GOAL); the others are OK and listed in call.placements.
std::vector<TaskState> placeTasks(const fleet_planner::PlanFleet::Request& request, const GridMap& grid,
                                  const std::map<std::string, fleet_planner::RobotFootprint>& registry,
                                  const PlannerConfig& config, const StartLookup& lookup, PlanCall& call);

}  // namespace fleet_planner
