#pragma once
/// Test-only reference for the optimality tests: an exhaustive, SOC-optimal joint-state search
/// for 2-3 robots on tiny maps. It is independent of every solver and of StateGraph: pose and
/// action legality come from FootprintCells + GridMap::blocked, robot-robot conflicts from
/// footprintsOverlap / sweepsOverlap (collision.h), i.e. the primitives the plan validator uses.
///
/// Dijkstra over (joint configuration, commit mask). In each time step, robots not in the mask
/// choose any legal action (wait, forward, rotate +-90; backward if the model allows it) and
/// robots in the mask wait. A joint step is allowed when no two robots' footprints overlap at
/// t + 1 (vertex conflict) and no two robots' swept cells overlap (transfer conflict). The step
/// costs the number of robots not in the mask before the step. After a step (and at t = 0) any
/// subset of the robots standing on their targets may join the mask; a robot in the mask stays
/// at its target forever. The goal is mask = all robots, so a robot's accumulated cost is the
/// time step it commits, and the optimum equals the minimum over plans of the sum of the time
/// steps at which each robot last arrives at its target (the SOC of plan.h).
#include "fleet_planner/model/action.h"
#include "fleet_planner/model/grid_map.h"
#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner::test {

/// Outcome of exhaustiveSearch().
struct ExhaustiveResult {
  long long soc = -1;             ///< optimal SOC; -1 if no plan exists or the budget ran out
  bool budget_exhausted = false;  ///< true when the search stopped at the state budget
  long long states = 0;           ///< joint states (configuration, mask) stored
  Plan plan;                      ///< an optimal plan in instance order when soc >= 0
};

/// The SOC-optimal plan of `instance` on `map` by exhaustive Dijkstra (see the file comment),
/// for at most 4 robots. Stops with budget_exhausted once more than `state_budget` joint states
/// are stored. An illegal start or target, or overlapping starts, give soc = -1 at once.
ExhaustiveResult exhaustiveSearch(const GridMap& map, const Instance& instance,
                                  long long state_budget = 2000000, const ActionModel& model = {});

/// exhaustiveSearch(map, instance, state_budget).soc: the optimal SOC, or -1 if no plan exists
/// within the state budget.
long long exhaustiveOptimalSoc(const GridMap& map, const Instance& instance,
                               long long state_budget = 2000000);

}  // namespace fleet_planner::test
