#pragma once
/// Timed plans and their metrics (paper: Preliminaries).
///
/// A path lists a robot's state at time steps 0, 1, 2, ...; after its last entry the robot
/// stays there forever. A robot's cost is the time step at which it last arrives at its
/// target; SOC is the sum of costs, makespan their maximum.
#include <vector>

#include "fleet_planner/model/types.h"

namespace fleet_planner {

using Path = std::vector<GridPose>;

struct Plan {
  std::vector<Path> paths;  ///< one per robot, in instance order
};

/// Time step at which the path last arrives at `target` (0 if it starts there and never
/// leaves); -1 if the path does not end at `target`.
int pathCost(const Path& path, const GridPose& target);

struct PlanMetrics {
  long long soc = 0;
  int makespan = 0;
};

/// SOC and makespan; a path that does not end at its target makes both -1.
PlanMetrics planMetrics(const Plan& plan, const std::vector<GridPose>& targets);

/// State of a path at time t (the last state once the path has ended).
inline const GridPose& stateAt(const Path& path, int t) {
  return t < static_cast<int>(path.size()) ? path[t] : path.back();
}

}  // namespace fleet_planner
