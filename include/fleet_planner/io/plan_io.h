#pragma once
/// Reading and writing plans as YAML:
///
///     # fleet_planner plan: each path lists [x, y, heading] at time steps 0, 1, 2, ...
///     format: fleet_planner/plan/1
///     soc: 123
///     makespan: 40
///     robots:
///       - id: r1
///         cost: 12
///         path: [[10, 4, 0], [11, 4, 0], [11, 4, 2]]
///
/// `soc` and `makespan` are planMetrics() of the paths and `cost` is pathCost() of the robot's
/// path (-1 where a path does not end at its target). Robots are written in instance order;
/// after its last state a robot stays there. `format` and `robots` are required, the metrics
/// optional, and `backward_moves: true` (optional) says the plan was made with backward moves
/// allowed; other keys are errors.
#include <string>

#include "fleet_planner/model/instance.h"
#include "fleet_planner/model/plan.h"

namespace fleet_planner {

/// The plan as YAML (see above). Throws InvalidInput if the plan does not have one non-empty
/// path per robot of the instance. `backward_moves`: the plan was made with backward moves
/// allowed (written as `backward_moves: true`, so that `check` validates it in that model).
std::string planToYaml(const Instance& instance, const Plan& plan, bool backward_moves = false);

/// Writes planToYaml(instance, plan, backward_moves) to `path`. Throws InvalidInput naming the
/// path if it cannot be written.
void savePlan(const Instance& instance, const Plan& plan, const std::string& path, bool backward_moves = false);

/// Reads a plan for `instance`: paths are matched to robots by id and returned in instance
/// order. Positions are not checked against any map. Throws ParseError(path, line, reason) for
/// YAML errors, a missing or different `format`, unknown or repeated keys, an id that is not a
/// robot of the instance or appears twice, a robot of the instance without a path, an empty
/// path, a state that is not [x, y, heading] with integers and heading 0..3, and a `soc`,
/// `makespan` or `cost` that is present but differs from the one the paths give.
/// `backward_moves`, if given, is set to the file's optional `backward_moves` (false without it).
Plan loadPlan(const std::string& path, const Instance& instance, bool* backward_moves = nullptr);

}  // namespace fleet_planner
