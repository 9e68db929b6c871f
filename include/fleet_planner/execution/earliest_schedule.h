#pragma once
/// A plan driven as early as its step dependencies allow: every robot starts each move as soon as
/// the dependencies release it and no robot is ever late (MAPF-POST's earliest schedule of the
/// temporal plan graph, with unit steps; Hönig et al., ICAPS 2016, see step_dependencies.h).
///
/// Each path keeps its sequence of poses; only its waits change. Move t of robot i starts at
///   S_i(t) = max(when i reached state t, max over its requirements (j, k) of S_j(k - 1) + 1),
/// computed in plan order (requirements point strictly backwards in plan time). By induction
/// S_i(t) <= t: no move is later than in the given plan, so no robot's cost and not the makespan
/// can grow. The result is collision-free for the reason any timing the dependencies release is
/// (step_dependencies.h): every pair of steps that share a cell keeps its order, one after the
/// other. One pass over the moves: the cost of building the dependencies dominates.
#include <optional>
#include <vector>

#include "fleet_planner/execution/plan_cells.h"
#include "fleet_planner/execution/step_dependencies.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

/// The retimed paths of `cells`' plan under `deps` (built from the same cells with from() == 0).
/// Nothing when a requirement names a state that its robot reaches by a wait, which a valid
/// plan's dependencies never do (step_dependencies.h).
std::optional<std::vector<Path>> earliestSchedule(const PlanCells& cells, const StepDependencies& deps);

/// Retimes `plan`, valid for `instance` under `model`, to its earliest schedule in place.
/// Returns the number of steps the robots' paths lost in all (trailing waits not counted).
long long retimeToEarliest(const Instance& instance, Plan& plan, const ActionModel& model);

}  // namespace fleet_planner
