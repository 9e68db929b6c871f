#pragma once
/// The planner node's own inputs without ROS: the footprint registry's fleet file and the demo
/// client's tasks file, on a map_server map, as an instance (for `fleet_planner_cli solve --fleet
/// F --tasks T`). Formats: docs/file_formats.md (src/fleet_planner/fleet_config.py and
/// tasks_config.py read the same files for the rospy nodes).
///
/// - Fleet: `robots: [{id, robot_radius | footprint: [[x, y], ...] | block: {min_x, max_x,
///   min_y, max_y}, footprint_padding}]`, metres, costmap_2d conventions (padding as
///   costmap_2d's padFootprint applies it); scaled to the map's cells.
/// - Tasks: `tasks: [{id, start: [x, y, yaw], goal: [x, y, yaw]}]`, metres and radians in the map
///   frame; a pose is snapped to its cell and the nearest grid heading, and a yaw farther than
///   `heading_tolerance` from it is kept as the robot's start or target yaw (the plan turns in
///   place from or to it). `start_from_tf` needs TF, which only the node has.
#include <string>

#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"

namespace fleet_planner {

/// The robots of the tasks file, in its order, with the fleet file's footprints. Throws
/// ParseError naming the file and line, InvalidInput naming the robot (a task whose robot the
/// fleet lacks, a pose off the map).
Instance loadFleetTasks(const GridMap& map, const std::string& fleet_path, const std::string& tasks_path,
                        double heading_tolerance = 0.2);

}  // namespace fleet_planner
