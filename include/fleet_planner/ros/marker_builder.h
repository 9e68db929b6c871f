#pragma once
/// RViz markers of a plan: start and goal footprints coloured by subproblem, paths, labels naming
/// the subproblem, cluster and level, and (when playback runs) each footprint in its
/// <robot>/planned frame, so RViz shows the fleet moving.
#include <string>
#include <vector>

#include <fleet_planner/FleetExecution.h>
#include <fleet_planner/RobotTimeline.h>
#include <fleet_planner/SubproblemInfo.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include "fleet_planner/ros/fleet_planning_service.h"

namespace fleet_planner {

struct MarkerStyle {
  std::string map_frame = "map";
  std::string planned_frame_suffix;  ///< non-empty: footprints in "<robot>/<suffix>" too
  double line_width = 0.03;          ///< metres
  double text_height = 0.25;         ///< metres
};

/// The markers of one call: a DELETEALL first (so old robots disappear), then per placed robot
/// namespaces "start", "goal", "heading", "label", "path" (from its timeline, if any) and
/// "planned". Marker ids are the robot's index in `placements`.
visualization_msgs::MarkerArray buildPlanMarkers(const std::vector<RobotPlacement>& placements,
                                                 const std::vector<fleet_planner::RobotTimeline>& timelines,
                                                 const std::vector<fleet_planner::SubproblemInfo>& subproblems,
                                                 const MarkerStyle& style);

/// The execution's state over each robot (namespace "execution", frame-locked to
/// "<robot_id>/<base_frame>"): nothing while it drives on time; "waits for <robot>" (orange),
/// "BLOCKED by <robot>" (red), "late N s" (orange), "NO POSE" / "OFF PATH" (red), "arrived"
/// (green). Marker ids are the robots' indices; a DELETEALL first.
visualization_msgs::MarkerArray buildExecutionMarkers(const fleet_planner::FleetExecution& execution,
                                                      const std::string& base_frame, double late_warning);

/// The outline of a footprint (metres, robot frame), closed: first point repeated at the end.
/// Circles become 32-gons.
std::vector<geometry_msgs::Point> footprintOutline(const fleet_planner::RobotFootprint& footprint);

/// A distinct, stable colour per subproblem index (-1: grey).
std_msgs::ColorRGBA subproblemColour(int subproblem, double alpha = 1.0);

}  // namespace fleet_planner
