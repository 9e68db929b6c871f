#pragma once
/// Where a timeline puts its robot at any time: the playback of a plan as moving TF frames.
#include <fleet_planner/RobotTimeline.h>
#include <geometry_msgs/Pose2D.h>

namespace fleet_planner {

/// The robot's pose `seconds` after the plan's start: its state at each step's time, linear in
/// between (a quarter turn turns at constant rate the shorter way); before 0 the first state,
/// after the last step the last one. The timeline must not be empty.
geometry_msgs::Pose2D poseAt(const fleet_planner::RobotTimeline& timeline, double seconds);

/// Seconds until the last state of the last robot (the plan's duration).
double planDuration(const std::vector<fleet_planner::RobotTimeline>& timelines);

}  // namespace fleet_planner
