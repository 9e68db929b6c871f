#pragma once
// Building a PlanFleet response: statuses (fleet and per robot), and a planning result turned
// into subproblems, timelines and statistics. Private to the ROS layer.
#include <cstdint>
#include <string>

#include "fleet_planner/planning/plan_fleet.h"
#include "fleet_planner/ros/fleet_planning_service.h"

namespace fleet_planner {

/// Sets the fleet status and message.
void fail(PlanCall& call, std::uint8_t status, const std::string& message);

/// Marks every robot without an error NOT_PLANNED and sets the fleet status from the first robot
/// error, most fundamental kind first (returns false if there were none).
bool failOnRobotErrors(PlanCall& call);

/// Robots still OK after a failure that is not theirs (a limit, the deadline) were not planned.
void markNotPlanned(PlanCall& call);

/// The response status of a planning status.
std::uint8_t responseStatus(SolveStatus status);

/// Fills the response from a planning call that passed the pre-check: subproblems and
/// statistics, then the timelines (every `seconds_per_step`) on success or the status, reason,
/// step-asides and merges on failure.
void fillResponse(const Instance& instance, const GridMap& grid, const PlanningResult& result,
                  double seconds_per_step, bool cancelled, PlanCall& call);

}  // namespace fleet_planner
