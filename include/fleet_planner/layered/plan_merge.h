#pragma once
/// Merging a parallel backend's subproblem plan into the plan so far (paper: Algorithm 5):
/// delay the new paths at their starts, all by the same number of steps, until they conflict
/// with no earlier path.
#include <vector>

#include "fleet_planner/model/fleet_graphs.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

/// Prepends waits to every path of `fresh` (robots `robots`, in that order) so that they do not
/// conflict with the paths of the robots marked in `done` (instance-indexed `merged`), and
/// returns the delay. For each pair, a step at ta of a new path and a step at tm of an earlier
/// path that sweep a common cell forbid the delay tm - ta; a new robot parked at its target
/// forbids every delay that parks it before an earlier robot has passed; the smallest delay
/// forbidden by no pair is taken. A robot of `robots` that is already in `done` (a robot that
/// stepped aside for an earlier subproblem, or steps aside now) continues its path: the delay is
/// at least its last step, and its own earlier path is not an obstacle to it; appendDelayed()
/// joins the two.
int delayToFit(const FleetGraphs& graphs, const std::vector<Path>& merged, const std::vector<char>& done,
               const std::vector<int>& robots, std::vector<Path>& fresh);

/// The path so far (`merged[robot]`, may be empty) continued by `delayed`, a path delayed by
/// delayToFit() to start where and after the path so far ends.
void appendDelayed(std::vector<Path>& merged, int robot, Path delayed);

}  // namespace fleet_planner
